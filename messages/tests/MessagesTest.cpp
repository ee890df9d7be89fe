// The message catalogue (messages/*.msg): its format, and every entry formats with the
// placeholders it declares (issue 15). tools/lint/messages.py checks that each call site passes
// exactly those placeholders.
#include "messages/Messages.hpp"

#include <gtest/gtest.h>

namespace stella::msg {
namespace {

// A value suited to a placeholder's format spec: a number for e/f/g/d..., text otherwise.
Arg sample(const std::string& name, const Entry& e) {
  std::string all = e.text;
  for (const std::string& a : e.advice) {
    all += a;
  }
  const auto at = all.find("{" + name + ":");
  if (at != std::string::npos) {
    const auto end = all.find('}', at);
    const char type = all[end - 1];
    if (std::string_view("eEfFgGaA%").find(type) != std::string_view::npos) {
      return Arg(name.c_str(), 1.25);
    }
    if (std::string_view("dxXbBoc").find(type) != std::string_view::npos) {
      return Arg(name.c_str(), 7);
    }
  }
  return Arg(name.c_str(), "x");
}

TEST(MessageCatalogue, EveryEntryFormatsWithItsPlaceholders) {
  ASSERT_GT(catalogue().size(), 0U);
  for (const Entry& e : catalogue()) {
    std::vector<std::string> names = placeholders(e.text);
    for (const std::string& a : e.advice) {
      for (std::string& n : placeholders(a)) {
        if (std::find(names.begin(), names.end(), n) == names.end()) {
          names.push_back(std::move(n));
        }
      }
    }
    std::vector<Arg> args;
    for (const std::string& n : names) {
      args.push_back(sample(n, e));
    }
    // An initializer_list cannot be built from a vector: pass 8 arguments, the unused ones
    // under a name no message has.
    const auto formatted = [&](auto&&... a) {
      if (e.kind == Kind::Note) {
        return text(e.key, {a...});
      }
      const Diagnostic d = make(e.key, {a...});
      EXPECT_EQ(d.id, e.id);
      EXPECT_EQ(d.notes.size(), e.advice.size()) << e.key;
      return d.message;
    };
    std::string out;
    ASSERT_LE(args.size(), 8U) << e.key << " has more than 8 placeholders: extend this test";
    const Arg none("unused_", "");
    auto arg = [&](std::size_t i) -> const Arg& { return i < args.size() ? args[i] : none; };
    EXPECT_NO_THROW(out = formatted(arg(0), arg(1), arg(2), arg(3), arg(4), arg(5), arg(6), arg(7))) << e.key;
    EXPECT_FALSE(out.empty()) << e.key;
  }
}

TEST(MessageCatalogue, ParsesKeysKindsTextsAndNotes) {
  const auto entries = parseMessageFile("demo", "# a comment\n"
                                                "[DEMO_1] fatal\n"
                                                "text: the mesh has no group '{group}'\n"
                                                "note: create it with DEFI_GROUP\n"
                                                "\n"
                                                "[DEMO_1.2] no-convergence\n"
                                                "text: {count:d} links at INST {time:.3e}\\nnext line\n");
  ASSERT_EQ(entries.size(), 2U);
  EXPECT_EQ(entries[0].id, "DEMO_1");
  EXPECT_EQ(entries[0].kind, Kind::Fatal);
  EXPECT_EQ(entries[0].advice, std::vector<std::string>{"create it with DEFI_GROUP"});
  EXPECT_EQ(entries[1].key, "DEMO_1.2");
  EXPECT_EQ(entries[1].id, "DEMO_1");
  EXPECT_EQ(entries[1].kind, Kind::NoConvergence);
  EXPECT_EQ(entries[1].text, "{count:d} links at INST {time:.3e}\nnext line");
  EXPECT_EQ(placeholders(entries[1].text), (std::vector<std::string>{"count", "time"}));
  EXPECT_EQ(placeholders("{{literal}} {a} {a:>4}"), std::vector<std::string>{"a"});
}

TEST(MessageCatalogue, RefusesMalformedFiles) {
  EXPECT_THROW(parseMessageFile("demo", "[DEMO_1] fatl\ntext: x\n"), InternalError);
  EXPECT_THROW(parseMessageFile("demo", "[DEMO_1] fatal\nnote: advice before the text\n"), InternalError);
  EXPECT_THROW(parseMessageFile("demo", "[DEMO_1] fatal\n"), InternalError);
}

TEST(MessageCatalogue, UnknownKeyIsAnInternalError) {
  EXPECT_THROW(make("NO_SUCH_MESSAGE_99"), InternalError);
}

} // namespace
} // namespace stella::msg

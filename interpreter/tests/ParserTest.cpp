// Parser: tree shapes and locations, error recovery (every error in one pass), nesting caps,
// and the pretty-printer round trip.
#include "interpreter/Parser.hpp"
#include "interpreter/Formatter.hpp"
#include "interpreter/Interpreter.hpp"

#include <gtest/gtest.h>

namespace stella {
namespace {

ParseResult parse(const std::string& text, bool comments = false) {
  return parseFile(SourceFile::fromText("p.comm", text), comments);
}

std::vector<std::string> errorIds(const ParseResult& r) {
  std::vector<std::string> ids;
  for (const auto& d : r.errors) {
    ids.push_back(d.id + "@" + std::to_string(d.location.line));
  }
  return ids;
}

TEST(Parser, CommandCallWithFactorKeywords) {
  ParseResult r = parse("MO = AFFE_MODELE(MAILLAGE=MAIL,\n                 AFFE=_F(TOUT='OUI'))\n");
  ASSERT_TRUE(r.errors.empty());
  ASSERT_EQ(r.module->body.size(), 1u);
  const Stmt& s = *r.module->body[0];
  EXPECT_EQ(s.kind, StmtKind::Assign);
  EXPECT_EQ(s.endLine, 2);
  const Expr& call = *s.exprs[1];
  ASSERT_EQ(call.kind, ExprKind::Call);
  ASSERT_EQ(call.items.size(), 3u);
  EXPECT_EQ(call.items[2]->kind, ExprKind::Keyword);
  EXPECT_EQ(call.items[2]->text, "AFFE");
  EXPECT_EQ(call.items[2]->pos.line, 2);
  EXPECT_EQ(call.items[2]->pos.column, 18);
}

TEST(Parser, PrecedenceAndAssociativity) {
  ParseResult r = parse("x = -2 ** 2 + 3 * 4 - 1\n");
  ASSERT_TRUE(r.errors.empty());
  EXPECT_EQ(formatExpression(*r.module->body[0]->exprs[1]), "-2**2 + 3 * 4 - 1");
  std::string tree = dumpExpr(*r.module->body[0]->exprs[1], false);
  // ((-(2**2)) + (3*4)) - 1
  EXPECT_EQ(tree.substr(0, tree.find('\n')), "Binary -");
}

TEST(Parser, EveryErrorIsReportedInOnePass) {
  ParseResult r =
      parse("a = (1 +\n)\nb = 2 3\nc = [1,\nd = 4\nif d > 3\n    d = 5\ne = f(A=1 B=2)\nok = 1\n");
  // `c = [1,` ends with a comma, so the lines after it are read inside the list until `e = f(...)`
  // at column 1 shows that the bracket never closes
  std::vector<std::string> expected = {"SYNTAX_1@2", "SYNTAX_1@3", "SYNTAX_8@4", "SYNTAX_1@5", "SYNTAX_1@8"};
  EXPECT_EQ(errorIds(r), expected);
  // the statements after the errors are still parsed
  EXPECT_EQ(r.module->body.back()->exprs[0]->text, "ok");
}

TEST(Parser, DeepNestingIsRefusedWithoutCrashing) {
  ParseResult r = parse("x = " + std::string(100000, '(') + "1" + std::string(100000, ')') + "\n");
  ASSERT_FALSE(r.errors.empty());
  EXPECT_EQ(r.errors[0].id, "SYNTAX_10");
  ParseResult chain = parse("x = 1" + [] {
    std::string s;
    for (int i = 0; i < 5000; ++i) {
      s += " + 1";
    }
    return s;
  }() + "\n");
  ASSERT_FALSE(chain.errors.empty());
  EXPECT_EQ(chain.errors[0].id, "SYNTAX_10");
  ParseResult unary = parse("x = " + std::string(50000, '-') + "1\n");
  ASSERT_FALSE(unary.errors.empty());
  std::string blocks;
  for (int i = 0; i < 300; ++i) {
    blocks += std::string(static_cast<std::size_t>(i), ' ') + "if x:\n";
  }
  blocks += std::string(300, ' ') + "pass\n";
  ParseResult deepBlocks = parse(blocks);
  ASSERT_FALSE(deepBlocks.errors.empty());
  EXPECT_EQ(deepBlocks.errors[0].id, "SYNTAX_10");
}

TEST(Parser, ModerateNestingIsAccepted) {
  ParseResult r = parse("x = " + std::string(150, '(') + "1" + std::string(150, ')') + "\n");
  EXPECT_TRUE(r.errors.empty());
}

TEST(Parser, FStringFieldsAreParsedWithTheirLocations) {
  ParseResult r = parse("s = f'a{x + 1:>4}b{y!r}'\n");
  ASSERT_TRUE(r.errors.empty());
  const Expr& f = *r.module->body[0]->exprs[1];
  ASSERT_EQ(f.kind, ExprKind::FString);
  ASSERT_EQ(f.items.size(), 4u);
  EXPECT_EQ(f.items[1]->kind, ExprKind::FormattedValue);
  EXPECT_EQ(f.items[1]->text, ">4");
  const Expr& x = *f.items[1]->items[0]->items[0];
  EXPECT_EQ(x.text, "x");
  EXPECT_EQ(x.pos.column, 9);
  EXPECT_EQ(f.items[3]->op, 'r');
}

TEST(Parser, ElifChainsAndElse) {
  ParseResult r = parse("if a:\n    x = 1\nelif b:\n    x = 2\nelse:\n    x = 3\n");
  ASSERT_TRUE(r.errors.empty());
  const Stmt& s = *r.module->body[0];
  ASSERT_EQ(s.orelse.size(), 1u);
  EXPECT_TRUE(s.orelse[0]->elif);
  EXPECT_EQ(s.orelse[0]->orelse.size(), 1u);
}

const char* roundTripSource = R"(# -*- coding: utf-8 -*-
from code_aster.Commands import *
import math as m

DEBUT()
# a comment before a command
MAIL = LIRE_MAILLAGE(UNITE=20, FORMAT='MED')  # trailing comment
RES = [None] * 2
for i, (a, b) in enumerate([(1, 2), (3, 4)]):
    if i == 0 and not a > b or b in (1, 2):
        RES[i] = STAT_NON_LINE(MODELE=MO, EXCIT=(_F(CHARGE=CH1), _F(CHARGE=CH2, FONC_MULT=RAMPE)), INCREMENT=_F(LIST_INST=L_INST, INST_FIN=1.0), NEWTON=_F(REAC_ITER=1, PREDICTION='ELASTIQUE'))
    elif i < 5:
        x = (-1) ** 2 - -2 ** 2 + 2 ** -1 + (a if b else -a) * 3 // 2 % 5
    else:
        pass
def f(a, b=1.5e-3, *args, **kw):
    global G
    return [v * 2 for v in args if v], {'k': a, **kw}, lambda q: q + b
s = f'x={x!r:>8} {{}} {"q"}' + 'it\'s' "\n" r'raw\n'
t = x[1:2], x[::-1], x[:, 1], x[1,]
while n < 10:
    n += 1
    if n: continue
    break
del x[0], y
assert n == 10, 'msg'
print(1 .real, 1.5.imag, 1e999, 3j, 0x10, 1_0, True, None, ..., ) if 0 else ()
FIN()
)";

TEST(Formatter, OutputReparsesToTheSameTree) {
  std::string source = std::string(roundTripSource);
  // `...` is not part of the language: drop it from the sample
  source.replace(source.find("..., "), 5, "");
  ParseResult first = parse(source, true);
  ASSERT_TRUE(first.errors.empty()) << formatDiagnostic(first.errors[0]);
  std::string printed = formatModule(*first.module, first.comments);
  ParseResult second = parse(printed);
  ASSERT_TRUE(second.errors.empty()) << formatDiagnostic(second.errors[0]) << printed;
  EXPECT_EQ(dumpModule(*first.module, false), dumpModule(*second.module, false)) << printed;
  EXPECT_NE(printed.find("# a comment before a command\nMAIL = "), std::string::npos) << printed;
  EXPECT_NE(printed.find("  # trailing comment"), std::string::npos);
  // the long call is broken one keyword per line, aligned after its '('
  EXPECT_NE(printed.find("RES[i] = STAT_NON_LINE(MODELE=MO,\n"), std::string::npos) << printed;
  EXPECT_EQ(formatModule(*second.module, {}), formatModule(*first.module, {}));
}

TEST(Formatter, FormatSourceThrowsOnSyntaxErrors) {
  auto file = SourceFile::fromText("bad.comm", "a = (\nb = 2 3\n");
  try {
    formatSource(file);
    FAIL() << "expected a UserError";
  } catch (const UserError& e) {
    EXPECT_GE(e.diagnostics().size(), 1u);
  }
}

TEST(DeveloperViews, TokensAndTree) {
  auto file = SourceFile::fromText("v.comm", "A = f(1)\n");
  std::string tokens = dumpTokens(file);
  EXPECT_NE(tokens.find("1:1 name A"), std::string::npos) << tokens;
  EXPECT_NE(tokens.find("1:6 '('"), std::string::npos) << tokens;
  std::string tree = dumpAst(file);
  EXPECT_NE(tree.find("Assign @1:1"), std::string::npos) << tree;
  EXPECT_NE(tree.find("Name f @1:5"), std::string::npos) << tree;
}

} // namespace
} // namespace stella

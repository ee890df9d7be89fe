// CompiledExpression: an expression text parsed once (FORMULE bodies, catalogue block
// conditions) and evaluated many times with names resolved through a lookup callback. Errors
// point inside the string, mapped onto the command file when the string literal is known.
#include "EmbeddedText.hpp"
#include "Evaluator.hpp"
#include "Interpreter.hpp"
#include "Parser.hpp"
#include "messages/Messages.hpp"

#include <algorithm>
#include <unordered_set>

namespace stella {

EmbeddedText::EmbeddedText(const std::string& text, const SourceLocation& origin)
    : file_(SourceFile::fromText("<expression>", text)), origin_(origin) {
  if (!origin.known()) {
    return;
  }
  // Find where the string's content starts in the file: skip a prefix and the opening quote(s),
  // and map only when the file holds the text verbatim there (no escapes).
  std::string_view line = origin.file->line(origin.line);
  auto col = static_cast<std::size_t>(origin.column - 1);
  if (col >= line.size()) {
    return;
  }
  std::size_t i = col;
  while (i < line.size() && line[i] != '\'' && line[i] != '"' && i < col + 2) {
    ++i;
  }
  if (i >= line.size() || (line[i] != '\'' && line[i] != '"')) {
    return;
  }
  std::size_t quote = (i + 2 < line.size() && line[i + 1] == line[i] && line[i + 2] == line[i]) ? 3 : 1;
  std::size_t content = i + quote;
  std::string_view firstLine = file_->line(1);
  if (line.substr(content, firstLine.size()) != firstLine) {
    return;
  }
  for (int l = 2; l <= file_->lineCount(); ++l) {
    if (origin.file->line(origin.line + l - 1).substr(0, file_->line(l).size()) != file_->line(l)) {
      return;
    }
  }
  mapped_ = true;
  firstColumn_ = static_cast<int>(content) + 1;
}

SourceLocation EmbeddedText::map(const SourceLocation& at) const {
  if (!mapped_ || at.file != file_) {
    return at;
  }
  SourceLocation out = origin_;
  out.line = origin_.line + at.line - 1;
  out.column = at.line == 1 ? firstColumn_ + at.column - 1 : at.column;
  out.length = at.length;
  return out;
}

std::vector<Diagnostic> EmbeddedText::map(std::vector<Diagnostic> ds) const {
  for (auto& d : ds) {
    d.location = map(d.location);
    if (!mapped_ && origin_.known() && d.location.file == file_) {
      d.withNote(msg::text("NOTE.n4", {{"origin", origin_.str()}}));
    }
  }
  return ds;
}

struct CompiledExpression::Impl {
  std::string text;
  EmbeddedText embedded;
  std::shared_ptr<Module> module;
  std::vector<std::string> freeNames;

  Impl(const std::string& t, const SourceLocation& origin) : text(t), embedded(t, origin) {}
};

CompiledExpression::CompiledExpression() = default;
CompiledExpression::~CompiledExpression() = default;
CompiledExpression::CompiledExpression(CompiledExpression&&) noexcept = default;
CompiledExpression& CompiledExpression::operator=(CompiledExpression&&) noexcept = default;

namespace {

void collectNames(const Expr& e, std::unordered_set<std::string>& bound, std::vector<std::string>& out) {
  if (e.kind == ExprKind::Name) {
    if (!bound.contains(e.text) && !mathNames().contains(e.text) && !builtinNames().contains(e.text) &&
        std::find(out.begin(), out.end(), e.text) == out.end()) {
      out.push_back(e.text);
    }
    return;
  }
  if (e.kind == ExprKind::ListComp) {
    for (std::size_t i = 1; i < e.items.size(); ++i) {
      std::vector<std::string> targets;
      std::unordered_set<std::string> none;
      collectNames(*e.items[i]->items[0], none, targets);
      bound.insert(targets.begin(), targets.end());
    }
  }
  if (e.kind == ExprKind::Lambda) {
    for (std::size_t i = 1; i < e.items.size(); ++i) {
      bound.insert(e.items[i]->text);
    }
    collectNames(*e.items[0], bound, out);
    return;
  }
  for (const auto& c : e.items) {
    if (c) {
      collectNames(*c, bound, out);
    }
  }
}

} // namespace

CompiledExpression CompiledExpression::compile(const std::string& text, const SourceLocation& origin) {
  CompiledExpression c;
  c.impl_ = std::make_unique<Impl>(text, origin);
  ParseResult parsed = parseExpressionFile(c.impl_->embedded.file());
  if (!parsed.errors.empty() || parsed.module->body.empty()) {
    if (parsed.errors.empty()) {
      parsed.errors.push_back(msg::make("SYNTAX_1", {}, {}));
    }
    throw UserError(c.impl_->embedded.map(std::move(parsed.errors)));
  }
  c.impl_->module = parsed.module;
  std::unordered_set<std::string> bound;
  collectNames(*parsed.module->body[0]->exprs[0], bound, c.impl_->freeNames);
  return c;
}

Value CompiledExpression::evaluate(const Lookup& lookup) const {
  Evaluator evaluator(nullptr, nullptr, EvaluatorOptions{});
  try {
    return evaluator.evalStandalone(impl_->module, *impl_->module->body[0]->exprs[0], &lookup);
  } catch (const UserError& e) {
    throw UserError(impl_->embedded.map(e.diagnostics()));
  }
}

std::vector<std::string> CompiledExpression::freeNames() const {
  return impl_->freeNames;
}

const std::string& CompiledExpression::text() const {
  return impl_->text;
}

} // namespace stella

// The evaluator's statements: blocks, assignments to names and indexed targets, augmented
// assignment, for/while loops with their caps, if, del, def and lambda.
#include "EvaluatorParts.hpp"
#include "Exceptions.hpp"

#include "Formatter.hpp"

namespace stella {

Evaluator::Flow Evaluator::execBlock(const std::vector<StmtPtr>& body) {
  for (const auto& s : body) {
    Flow flow = execStatement(*s);
    if (flow != Flow::Normal) {
      return flow;
    }
  }
  return Flow::Normal;
}

// An error raised without a location (e.g. LANG_DEPTH from printing or comparing a value nested
// too deeply) is placed at the statement being executed.
Evaluator::Flow Evaluator::execStatement(const Stmt& s) {
  try {
    return execStatementOfKind(s);
  } catch (const UserError& err) {
    if (err.first().location.known()) {
      throw;
    }
    std::vector<Diagnostic> ds = err.diagnostics();
    for (auto& d : ds) {
      if (!d.location.known()) {
        d.location = location(s.pos);
      }
    }
    rethrowWith(err, std::move(ds));
  }
}

Evaluator::Flow Evaluator::execStatementOfKind(const Stmt& s) {
  countStep(s.pos);
  switch (s.kind) {
  case StmtKind::Expr:
    eval(*s.exprs[0]);
    return Flow::Normal;
  case StmtKind::Assign:
    execAssign(s);
    return Flow::Normal;
  case StmtKind::AugAssign:
    execAugAssign(s);
    return Flow::Normal;
  case StmtKind::For:
    return execFor(s);
  case StmtKind::While:
    return execWhile(s);
  case StmtKind::If:
    if (eval(*s.exprs[0]).truthy()) {
      return execBlock(s.body);
    }
    return execBlock(s.orelse);
  case StmtKind::Pass:
    return Flow::Normal;
  case StmtKind::Break:
    return Flow::Break;
  case StmtKind::Continue:
    return Flow::Continue;
  case StmtKind::Del:
    execDel(s);
    return Flow::Normal;
  case StmtKind::Def:
    execDef(s);
    return Flow::Normal;
  case StmtKind::Return:
    returnValue_ = s.exprs.empty() ? Value() : eval(*s.exprs[0]);
    return Flow::Return;
  case StmtKind::Import:
    execImport(s);
    return Flow::Normal;
  case StmtKind::FromImport:
    execFromImport(s);
    return Flow::Normal;
  case StmtKind::Global:
    if (scope_ != nullptr) {
      for (const auto& n : s.imports) {
        scope_->globalNames.insert(n.name);
      }
    }
    return Flow::Normal;
  case StmtKind::Try:
    return execTry(s);
  case StmtKind::ExceptHandler: // run by execTry
    return Flow::Normal;
  case StmtKind::Raise:
    execRaise(s);
  case StmtKind::Assert:
    if (!eval(*s.exprs[0]).truthy()) {
      if (s.exprs.size() > 1) {
        raise(s.pos, "LANG_ASSERT.detail",
              {{"expression", formatExpression(*s.exprs[0])}, {"detail", eval(*s.exprs[1]).str()}});
      }
      raise(s.pos, "LANG_ASSERT", {{"expression", formatExpression(*s.exprs[0])}});
    }
    return Flow::Normal;
  }
  return Flow::Normal;
}

// The text of an assignment target passed to commands: `MAIL`, `RES[1]`.
std::string Evaluator::targetText(const Expr& target, Value* index) {
  if (target.kind == ExprKind::Name) {
    return target.text;
  }
  if (target.kind == ExprKind::Subscript && target.items[0]->kind == ExprKind::Name) {
    *index = eval(*target.items[1]);
    return target.items[0]->text + "[" + index->repr() + "]";
  }
  return {};
}

void Evaluator::execAssign(const Stmt& s) {
  const Expr& valueExpr = *s.exprs.back();
  Value value;
  if (valueExpr.kind == ExprKind::Call && s.exprs.size() == 2) {
    // `X = CMD(...)` or `RES[i] = CMD(...)`: the command is told its target
    const Expr& target = *s.exprs[0];
    Value index;
    std::string text = targetText(target, &index);
    value = evalCall(valueExpr, text);
    if (target.kind == ExprKind::Subscript && !text.empty()) {
      Value container = eval(*target.items[0]);
      noteMutated(container);
      try {
        setItem(container, index, value);
      } catch (const LangError& e) {
        raise(target.pos, e);
      }
      return;
    }
    assignTo(target, value);
    return;
  }
  value = eval(valueExpr);
  for (std::size_t i = 0; i + 1 < s.exprs.size(); ++i) {
    assignTo(*s.exprs[i], value);
  }
}

void Evaluator::bindName(const std::string& name, const Value& value) {
  if (scope_ != nullptr && !scope_->globalNames.contains(name)) {
    scope_->vars[name] = value;
  } else {
    globals_[name] = value;
  }
}

void Evaluator::assignTo(const Expr& target, const Value& value) {
  switch (target.kind) {
  case ExprKind::Name:
    bindName(target.text, value);
    return;
  case ExprKind::Subscript: {
    Value container = eval(*target.items[0]);
    Value index = eval(*target.items[1]);
    noteMutated(container);
    try {
      setItem(container, index, value);
    } catch (const LangError& e) {
      raise(target.pos, e);
    }
    return;
  }
  case ExprKind::Attribute:
    raise(target.pos, "LANG_TYPE.32", {{"text", target.text}});
  case ExprKind::Tuple:
  case ExprKind::List: {
    ValueList items;
    try {
      items = iterableItems(value, options_.limits);
    } catch (const LangError& e) {
      if (e.id == "LANG_BUDGET") {
        raise(target.pos, e);
      }
      raise(target.pos, "LANG_TYPE.33",
            {{"type_name", value.typeName()}, {"items_count", std::to_string(target.items.size())}});
    }
    if (items.size() != target.items.size()) {
      raise(target.pos, "LANG_VALUE.35",
            {{"items_count", std::to_string(items.size())},
             {"items_count_2", std::to_string(target.items.size())}});
    }
    for (std::size_t i = 0; i < items.size(); ++i) {
      assignTo(*target.items[i], items[i]);
    }
    return;
  }
  default:
    raise(target.pos, "LANG_TYPE.34", {});
  }
}

void Evaluator::execAugAssign(const Stmt& s) {
  const Expr& target = *s.exprs[0];
  auto op = static_cast<BinaryOp>(s.op);
  if (target.kind == ExprKind::Subscript) {
    Value container = eval(*target.items[0]);
    Value index = eval(*target.items[1]);
    noteMutated(container);
    try {
      Value current = getItem(container, index);
      Value rhs = eval(*s.exprs[1]);
      setItem(container, index, binaryOperation(op, current, rhs, options_.limits));
    } catch (const LangError& e) {
      raise(s.pos, e);
    }
    return;
  }
  Value current = eval(target);
  Value rhs = eval(*s.exprs[1]);
  if (op == BinaryOp::Add && current.isList()) { // `l += [...]` extends the list in place
    noteMutated(current);
    try {
      ValueList more = iterableItems(rhs, options_.limits);
      auto& items = current.asList()->items;
      if (static_cast<std::int64_t>(items.size() + more.size()) > options_.limits.maxSequenceLength) {
        langError("LANG_SIZE.6", {});
      }
      items.insert(items.end(), more.begin(), more.end());
    } catch (const LangError& e) {
      raise(s.pos, e);
    }
    return;
  }
  try {
    assignTo(target, binaryOperation(op, current, rhs, options_.limits));
  } catch (const LangError& e) {
    raise(s.pos, e);
  }
}

Evaluator::Flow Evaluator::execFor(const Stmt& s) {
  Value iterable = eval(*s.exprs[1]);
  const Expr& target = *s.exprs[0];
  Flow result = Flow::Normal;
  bool broke = false;
  LoopGuard running(loops_, &s, nullptr);
  auto body = [&](const Value& item) {
    running.turn();
    countStep(s.pos);
    assignTo(target, item);
    Flow flow = execBlock(s.body);
    if (flow == Flow::Break) {
      broke = true;
      return false;
    }
    if (flow == Flow::Return) {
      result = Flow::Return;
      return false;
    }
    return true;
  };
  try {
    forEachItem(iterable, body);
  } catch (const LangError& e) {
    raise(s.exprs[1]->pos, e);
  }
  if (result == Flow::Normal && !broke) {
    return execBlock(s.orelse);
  }
  return result;
}

Evaluator::Flow Evaluator::execWhile(const Stmt& s) {
  long iterations = 0;
  LoopGuard running(loops_, &s, nullptr);
  while (eval(*s.exprs[0]).truthy()) {
    running.turn();
    if (++iterations > options_.whileIterationCap) {
      raise(s.pos, "LANG_WHILE",
            {{"while_iteration_cap", std::to_string(options_.whileIterationCap)},
             {"format_expression", formatExpression(*s.exprs[0])}});
    }
    countStep(s.pos);
    Flow flow = execBlock(s.body);
    if (flow == Flow::Break) {
      return Flow::Normal;
    }
    if (flow == Flow::Return) {
      return flow;
    }
  }
  return execBlock(s.orelse);
}

void Evaluator::execDel(const Stmt& s) {
  for (const auto& t : s.exprs) {
    if (t->kind == ExprKind::Name) {
      bool removed = false;
      if (scope_ != nullptr && !scope_->globalNames.contains(t->text)) {
        removed = scope_->vars.erase(t->text) > 0;
      }
      if (!removed && globals_.erase(t->text) == 0) {
        unknownName(*t);
      }
    } else if (t->kind == ExprKind::Subscript) {
      Value container = eval(*t->items[0]);
      Value index = eval(*t->items[1]);
      try {
        deleteItem(container, index);
      } catch (const LangError& e) {
        raise(t->pos, e);
      }
    } else if (t->kind == ExprKind::Tuple || t->kind == ExprKind::List) {
      for (const auto& item : t->items) {
        if (item->kind != ExprKind::Name) {
          raise(item->pos, "LANG_TYPE.35", {});
        }
        if (globals_.erase(item->text) == 0 && (scope_ == nullptr || scope_->vars.erase(item->text) == 0)) {
          unknownName(*item);
        }
      }
    } else {
      raise(t->pos, "LANG_TYPE.36", {});
    }
  }
}

void Evaluator::execDef(const Stmt& s) {
  ValueList defaults;
  std::vector<bool> has;
  for (const auto& p : s.params) {
    has.push_back(p.defaultValue != nullptr);
    defaults.push_back(p.defaultValue ? eval(*p.defaultValue) : Value());
  }
  auto fn = std::make_shared<UserFunction>(module_, &s, nullptr, std::move(defaults));
  fn->hasDefault = std::move(has);
  bindName(s.name, Value(std::shared_ptr<Callable>(fn)));
}

Value Evaluator::evalLambda(const Expr& e) {
  auto fn = std::make_shared<UserFunction>(module_, nullptr, &e, ValueList{});
  return Value(std::shared_ptr<Callable>(fn));
}

} // namespace stella

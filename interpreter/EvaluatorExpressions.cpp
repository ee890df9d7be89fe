// The evaluator's expressions: literals, names (with suggestions for unknown ones), operators,
// comparisons, displays, comprehensions, f-strings and attributes.
#include "EvaluatorParts.hpp"

#include "Suggest.hpp"
#include "messages/Messages.hpp"

namespace stella {

using evaluation::DepthGuard;

Value Evaluator::eval(const Expr& e) {
  switch (e.kind) {
  case ExprKind::Name:
    return evalName(e);
  case ExprKind::Int:
    return Value(e.intValue);
  case ExprKind::Real:
    return Value(e.realValue);
  case ExprKind::Imaginary:
    return Value(std::complex<double>(0.0, e.realValue));
  case ExprKind::String:
    return Value(e.text);
  case ExprKind::None:
    return Value();
  case ExprKind::True:
    return Value(true);
  case ExprKind::False:
    return Value(false);
  default:
    break;
  }
  countStep(e.pos);
  DepthGuard guard(evalDepth_, options_.maxEvalDepth, *this, e.pos);
  switch (e.kind) {
  case ExprKind::FString:
    return evalFString(e);
  case ExprKind::Tuple:
  case ExprKind::List: {
    ValueList items;
    items.reserve(e.items.size());
    for (const auto& item : e.items) {
      items.push_back(eval(*item));
    }
    return e.kind == ExprKind::Tuple ? Value::tuple(std::move(items)) : Value::list(std::move(items));
  }
  case ExprKind::Dict:
    return evalDict(e);
  case ExprKind::ListComp:
    return evalListComp(e);
  case ExprKind::Unary: {
    Value v = eval(*e.items[0]);
    try {
      return unaryOperation(static_cast<UnaryOp>(e.op), v);
    } catch (const LangError& err) {
      raise(e.pos, err);
    }
  }
  case ExprKind::Binary: {
    Value a = eval(*e.items[0]);
    Value b = eval(*e.items[1]);
    try {
      return binaryOperation(static_cast<BinaryOp>(e.op), a, b, options_.limits);
    } catch (const LangError& err) {
      raise(e.pos, err);
    }
  }
  case ExprKind::Compare:
    return evalCompare(e);
  case ExprKind::And: {
    Value v;
    for (const auto& item : e.items) {
      v = eval(*item);
      if (!v.truthy()) {
        return v;
      }
    }
    return v;
  }
  case ExprKind::Or: {
    Value v;
    for (const auto& item : e.items) {
      v = eval(*item);
      if (v.truthy()) {
        return v;
      }
    }
    return v;
  }
  case ExprKind::Not:
    return Value(!eval(*e.items[0]).truthy());
  case ExprKind::Conditional:
    return eval(*e.items[1]).truthy() ? eval(*e.items[0]) : eval(*e.items[2]);
  case ExprKind::Call:
    return evalCall(e);
  case ExprKind::Attribute:
    return evalAttribute(e);
  case ExprKind::Subscript: {
    Value container = eval(*e.items[0]);
    Value index = eval(*e.items[1]);
    try {
      return getItem(container, index);
    } catch (const LangError& err) {
      raise(e.pos, err);
    }
  }
  case ExprKind::Slice:
    return makeSlice(e.items[0] ? eval(*e.items[0]) : Value(), e.items[1] ? eval(*e.items[1]) : Value(),
                     e.items[2] ? eval(*e.items[2]) : Value());
  case ExprKind::Lambda:
    return evalLambda(e);
  default:
    raise(e.pos, "LANG_TYPE.31", {});
  }
}

Value Evaluator::evalName(const Expr& e) {
  const Value* found = nullptr;
  for (Scope* s = scope_; s != nullptr && found == nullptr; s = s->parent) {
    if (s->globalNames.contains(e.text)) {
      break;
    }
    auto it = s->vars.find(e.text);
    if (it != s->vars.end()) {
      found = &it->second;
    }
  }
  if (found == nullptr && lookup_ != nullptr) {
    std::optional<Value> v = (*lookup_)(e.text);
    if (v) {
      return *v;
    }
    auto m = mathNames().find(e.text);
    if (m != mathNames().end()) {
      return m->second;
    }
  }
  if (found == nullptr) {
    auto it = globals_.find(e.text);
    if (it != globals_.end()) {
      found = &it->second;
    }
  }
  if (found == nullptr) {
    auto it = builtinNames().find(e.text);
    if (it == builtinNames().end()) {
      unknownName(e);
    }
    return it->second;
  }
  if (found->isConcept() && found->asConcept()->destroyed) {
    raise(e.pos, "LANG_DESTROYED.2", {{"text", e.text}});
  }
  return *found;
}

std::vector<std::string> Evaluator::visibleNames() const {
  std::vector<std::string> names;
  for (Scope* s = scope_; s != nullptr; s = s->parent) {
    for (const auto& [name, value] : s->vars) {
      names.push_back(name);
    }
  }
  for (const auto& [name, value] : globals_) {
    names.push_back(name);
  }
  for (const auto& [name, value] : builtinNames()) {
    names.push_back(name);
  }
  if (lookup_ != nullptr) {
    for (const auto& [name, value] : mathNames()) {
      names.push_back(name);
    }
  }
  return names;
}

void Evaluator::unknownName(const Expr& e) const {
  std::string note = suggestionNote(e.text, visibleNames());
  if (note.empty() && mathNames().contains(e.text) && lookup_ == nullptr) {
    note = msg::text("LANG_NAME.n_math", {{"name", e.text}});
  }
  raise(e.pos, "LANG_NAME", {{"text", e.text}}, note);
}

Value Evaluator::evalCompare(const Expr& e) {
  Value left = eval(*e.items[0]);
  for (std::size_t i = 0; i < e.compareCount(); ++i) {
    Value right = eval(*e.items[i + 1]);
    bool ok = false;
    try {
      ok = compareOperation(e.compareOp(i), left, right);
    } catch (const LangError& err) {
      raise(e.items[i + 1]->pos.line == e.pos.line ? e.pos : e.items[i + 1]->pos, err);
    }
    if (!ok) {
      return Value(false);
    }
    left = std::move(right);
  }
  return Value(true);
}

Value Evaluator::evalDict(const Expr& e) {
  auto dict = std::make_shared<DictObject>();
  for (std::size_t i = 0; i + 1 < e.items.size(); i += 2) {
    try {
      if (e.items[i]) {
        Value key = eval(*e.items[i]);
        dictSet(*dict, key, eval(*e.items[i + 1]));
      } else {
        Value other = eval(*e.items[i + 1]);
        if (!other.isDict()) {
          langError("LANG_TYPE.9", {{"type_name", other.typeName()}});
        }
        for (const auto& [k, v] : other.asDict()->items) {
          dictSet(*dict, k, v);
        }
      }
    } catch (const LangError& err) {
      raise(e.items[i] ? e.items[i]->pos : e.items[i + 1]->pos, err);
    }
  }
  return Value(dict);
}

Value Evaluator::evalListComp(const Expr& e) {
  Scope local;
  local.parent = scope_;
  Scope* saved = scope_;
  scope_ = &local;
  ValueList out;
  // Runs the clauses from `clause` on, appending the element when all have matched.
  std::function<void(std::size_t)> run = [&](std::size_t clause) {
    if (clause >= e.items.size()) {
      if (static_cast<std::int64_t>(out.size()) >= options_.limits.maxSequenceLength) {
        raise(e.pos, "LANG_SIZE.6", {});
      }
      out.push_back(eval(*e.items[0]));
      if (out.size() == out.capacity()) {
        meter_.allocation(static_cast<std::int64_t>(out.capacity() * sizeof(Value)));
      }
      return;
    }
    const Expr& c = *e.items[clause];
    Value iterable = eval(*c.items[1]);
    LoopGuard running(loops_, nullptr, &c);
    try {
      forEachItem(iterable, [&](const Value& item) {
        running.turn();
        countStep(c.pos);
        assignTo(*c.items[0], item);
        for (std::size_t k = 2; k < c.items.size(); ++k) {
          if (!eval(*c.items[k]).truthy()) {
            return true;
          }
        }
        run(clause + 1);
        return true;
      });
    } catch (const LangError& err) {
      raise(c.items[1]->pos, err);
    }
  };
  try {
    run(1);
  } catch (...) {
    scope_ = saved;
    throw;
  }
  scope_ = saved;
  return Value::list(std::move(out));
}

Value Evaluator::evalFString(const Expr& e) {
  std::string out;
  for (const auto& part : e.items) {
    if (part->kind == ExprKind::String) {
      out += part->text;
      continue;
    }
    Value v = eval(*part->items[0]);
    try {
      if (part->op == 'r' || part->op == 'a') {
        v = Value(v.repr());
      } else if (part->op == 's') {
        v = Value(v.str());
      }
      out += formatWithSpec(v, part->text);
    } catch (const LangError& err) {
      raise(part->pos, err);
    }
    if (static_cast<std::int64_t>(out.size()) > options_.limits.maxStringLength) {
      raise(e.pos, "LANG_SIZE.4", {});
    }
  }
  return Value(std::move(out));
}

Value Evaluator::evalAttribute(const Expr& e) {
  Value object = eval(*e.items[0]);
  return attributeOf(object, e.text, e.pos);
}

Value Evaluator::attributeOf(const Value& object, const std::string& name, const Pos& at) {
  if (object.isConcept()) {
    if (object.asConcept()->destroyed) {
      raise(at, "LANG_DESTROYED.3", {{"name", object.asConcept()->name}});
    }
    if (handler_ == nullptr) {
      raise(at, "LANG_ATTR.2", {});
    }
    return handler_->conceptAttribute(object.asConcept(), name, location(at));
  }
  if (object.isNative()) {
    std::shared_ptr<const Value> v;
    try {
      v = object.asNative()->attribute(name);
    } catch (const LangError& e) {
      raise(at, e);
    }
    if (v) {
      return *v;
    }
  }
  if (object.kind() == Value::Kind::Complex && (name == "real" || name == "imag")) {
    return Value(name == "real" ? object.asComplex().real() : object.asComplex().imag());
  }
  if (hasMethod(object, name)) {
    Value self = object;
    std::string method = name;
    Evaluator* ev = this;
    Pos pos = at;
    return makeNativeFunction(name, [ev, self, method, pos](const CallArguments& args) -> Value {
      return *callMethod(*ev, self, method, args, pos);
    });
  }
  raise(at, "LANG_ATTR.3", {{"type_name", object.typeName()}, {"name", name}});
}

} // namespace stella

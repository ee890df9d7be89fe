// The evaluator: statements and expressions of a parsed command file, with Python's semantics.
// Command calls go to the CommandHandler with their assignment target; user errors are thrown
// as UserError located at the node being evaluated.
#include "Evaluator.hpp"

#include "Formatter.hpp"
#include "Suggest.hpp"

#include <algorithm>

namespace stella {

// A function defined with `def` (or `lambda`) in a command file.
class UserFunction : public Callable {
public:
  UserFunction(std::shared_ptr<const Module> definedIn, const Stmt* definition, const Expr* lambdaExpr,
               ValueList defaultValues)
      : module(std::move(definedIn)), def(definition), lambda(lambdaExpr),
        defaults(std::move(defaultValues)) {}
  std::string name() const override { return def != nullptr ? def->name : "<lambda>"; }
  std::shared_ptr<const Module> module;
  const Stmt* def;
  const Expr* lambda;
  ValueList defaults; // one per parameter; None where there is no default (see hasDefault)
  std::vector<bool> hasDefault;
};

namespace {

// A command bound by defineCommand: calling it goes to the CommandHandler.
class CommandCallable : public Callable {
public:
  explicit CommandCallable(std::string name) : name_(std::move(name)) {}
  std::string name() const override { return name_; }
  bool isCommand() const override { return true; }

private:
  std::string name_;
};

// A module made by `import math` (or the code_aster namespace): attributes are its names.
class ModuleObject : public NativeObject {
public:
  ModuleObject(std::string name, const std::unordered_map<std::string, Value>* names)
      : name_(std::move(name)), names_(names) {}
  std::string typeName() const override { return "module " + name_; }
  std::shared_ptr<const Value> attribute(const std::string& name) const override {
    auto it = names_->find(name);
    if (it == names_->end()) {
      return nullptr;
    }
    return std::make_shared<const Value>(it->second);
  }

private:
  std::string name_;
  const std::unordered_map<std::string, Value>* names_;
};

bool isCodeAsterModule(const std::string& module) {
  return module == "code_aster" || module.rfind("code_aster.", 0) == 0 || module == "__future__" ||
         module == "Accas" || module == "Cata" || module.rfind("Cata.", 0) == 0;
}

// RAII depth counter: refuses evaluations nested deeper than the stack can hold.
class DepthGuard {
public:
  DepthGuard(int& depth, int max, const Evaluator& ev, const Pos& pos) : depth_(depth) {
    if (++depth_ > max) {
      --depth_;
      ev.raise(pos, "LANG_DEPTH",
               "evaluation nested too deeply (more than " + std::to_string(max) + " levels)",
               "is a function calling itself without end?");
    }
  }
  ~DepthGuard() { --depth_; }
  DepthGuard(const DepthGuard&) = delete;
  DepthGuard& operator=(const DepthGuard&) = delete;

private:
  int& depth_;
};

} // namespace

Evaluator::Evaluator(CommandHandler* handler, DiagnosticSink* sink, EvaluatorOptions options)
    : handler_(handler), sink_(sink), options_(options) {}

void Evaluator::noteMutated(const Value& container) {
  const void* id = container.isList()
                       ? static_cast<const void*>(container.asList().get())
                       : (container.isDict() ? static_cast<const void*>(container.asDict().get()) : nullptr);
  if (id == nullptr || id == lastMutated_) {
    return;
  }
  lastMutated_ = id;
  if (container.isList()) {
    mutatedLists_.emplace(id, container.asList());
  } else {
    mutatedDicts_.emplace(id, container.asDict());
  }
}

namespace {

// One depth-first search over the containers reachable from the mutated lists and dicts; an edge
// back to a container still on the search stack closes a cycle, which is broken by emptying a
// list or dict of that cycle. Linear in the size of the reachable graph.
class CycleBreaker {
public:
  void visit(const Value& v, int depth) {
    const void* id = idOf(v);
    if (id == nullptr || depth > 5000) {
      return;
    }
    auto [it, inserted] = state_.emplace(id, OnStack);
    if (!inserted) {
      if (it->second == OnStack) {
        markCycleTo(id);
      }
      return;
    }
    stack_.push_back(v);
    if (v.isSequence()) {
      for (const Value& item : v.items()) {
        visit(item, depth + 1);
      }
    } else if (v.isDict()) {
      for (const auto& kv : v.asDict()->items) {
        visit(kv.first, depth + 1);
        visit(kv.second, depth + 1);
      }
    } else {
      for (const auto& kw : v.asFactor()->keywords) {
        visit(*kw.value, depth + 1);
      }
    }
    stack_.pop_back();
    it = state_.find(id);
    it->second = Done;
  }

  void breakCycles() {
    for (Value& v : toEmpty_) {
      if (v.isList()) {
        ValueList items;
        items.swap(v.asList()->items);
      } else {
        std::vector<std::pair<Value, Value>> items;
        items.swap(v.asDict()->items);
      }
    }
    toEmpty_.clear();
  }

private:
  enum State { OnStack, Done };

  static const void* idOf(const Value& v) {
    if (v.isList()) {
      return v.asList().get();
    }
    if (v.isDict()) {
      return v.asDict().get();
    }
    if (v.isTuple()) {
      return &v.items();
    }
    if (v.isFactor()) {
      return v.asFactor().get();
    }
    return nullptr;
  }

  // The cycle is the stack from `target` to the top: empty its last list or dict.
  void markCycleTo(const void* target) {
    for (auto it = stack_.rbegin(); it != stack_.rend(); ++it) {
      if (it->isList() || it->isDict()) {
        toEmpty_.push_back(*it);
        return;
      }
      if (idOf(*it) == target) {
        return;
      }
    }
  }

  std::unordered_map<const void*, State> state_;
  std::vector<Value> stack_;
  std::vector<Value> toEmpty_;
};

} // namespace

Evaluator::~Evaluator() {
  globals_.clear();
  CycleBreaker breaker;
  for (const auto& [id, weak] : mutatedLists_) {
    if (auto list = weak.lock()) {
      breaker.visit(Value(list), 0);
    }
  }
  for (const auto& [id, weak] : mutatedDicts_) {
    if (auto dict = weak.lock()) {
      breaker.visit(Value(dict), 0);
    }
  }
  breaker.breakCycles();
}

void Evaluator::raise(const Pos& pos, const std::string& id, const std::string& message,
                      const std::string& note) const {
  Diagnostic d = Diagnostic::fatal(id, message, location(pos));
  if (!note.empty()) {
    d.withNote(note);
  }
  throw UserError(std::move(d));
}

void Evaluator::countStep(const Pos& pos) {
  if (options_.stepBudget > 0 && ++steps_ > options_.stepBudget) {
    raise(pos, "LANG_LIMIT",
          "the run exceeded its budget of " + std::to_string(options_.stepBudget) + " steps");
  }
}

void Evaluator::defineCommand(const std::string& name) {
  globals_[name] = Value(std::shared_ptr<Callable>(std::make_shared<CommandCallable>(name)));
}

void Evaluator::execModule(const std::shared_ptr<const Module>& module, std::size_t firstStatement) {
  auto savedModule = module_;
  auto savedFile = file_;
  module_ = module;
  file_ = module->file;
  for (std::size_t i = firstStatement; i < module->body.size(); ++i) {
    execStatement(*module->body[i]);
  }
  module_ = savedModule;
  file_ = savedFile;
}

Value Evaluator::evalStandalone(const std::shared_ptr<const Module>& module, const Expr& expr,
                                const std::function<std::optional<Value>(const std::string&)>* lookup) {
  module_ = module;
  file_ = module->file;
  lookup_ = lookup;
  return eval(expr);
}

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
    throw UserError(std::move(ds));
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
  case StmtKind::Assert:
    if (!eval(*s.exprs[0]).truthy()) {
      std::string message = "assertion failed: " + formatExpression(*s.exprs[0]);
      if (s.exprs.size() > 1) {
        message += " (" + eval(*s.exprs[1]).str() + ")";
      }
      raise(s.pos, "LANG_ASSERT", message);
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
    raise(target.pos, "LANG_TYPE", "cannot set the attribute '" + target.text + "'",
          "attributes of concepts and objects are read-only in command files");
  case ExprKind::Tuple:
  case ExprKind::List: {
    ValueList items;
    try {
      items = iterableItems(value, options_.limits);
    } catch (const LangError& e) {
      raise(target.pos, "LANG_TYPE",
            "cannot unpack a '" + value.typeName() + "' into " + std::to_string(target.items.size()) +
                " names");
    }
    if (items.size() != target.items.size()) {
      raise(target.pos, "LANG_VALUE",
            "cannot unpack " + std::to_string(items.size()) + " values into " +
                std::to_string(target.items.size()) + " names",
            "the number of names on the left of '=' must match the number of values");
    }
    for (std::size_t i = 0; i < items.size(); ++i) {
      assignTo(*target.items[i], items[i]);
    }
    return;
  }
  default:
    raise(target.pos, "LANG_TYPE", "cannot assign to this expression");
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
        langError("LANG_SIZE", "list too long");
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
  auto body = [&](const Value& item) {
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
  while (eval(*s.exprs[0]).truthy()) {
    if (++iterations > options_.whileIterationCap) {
      raise(s.pos, "LANG_WHILE",
            "while loop stopped after " + std::to_string(options_.whileIterationCap) +
                " iterations: its condition '" + formatExpression(*s.exprs[0]) + "' was still true",
            "check that the loop changes what its condition tests");
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
          raise(item->pos, "LANG_TYPE", "del of this expression is not supported");
        }
        if (globals_.erase(item->text) == 0 && (scope_ == nullptr || scope_->vars.erase(item->text) == 0)) {
          unknownName(*item);
        }
      }
    } else {
      raise(t->pos, "LANG_TYPE", "cannot delete this expression");
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

void Evaluator::execImport(const Stmt& s) {
  for (const auto& in : s.imports) {
    std::string bound = in.alias.empty() ? in.name.substr(0, in.name.find('.')) : in.alias;
    if (in.name == "math") {
      bindName(bound,
               Value(std::shared_ptr<NativeObject>(std::make_shared<ModuleObject>("math", &mathNames()))));
    } else if (isCodeAsterModule(in.name)) {
      bindName(bound,
               Value(std::shared_ptr<NativeObject>(std::make_shared<ModuleObject>(in.name, &globals_))));
    } else {
      raise(in.pos, "LANG_IMPORT", "import of module '" + in.name + "' is refused",
            "command files are a sandbox: they may import only the code_aster command namespace and 'math'");
    }
  }
}

void Evaluator::execFromImport(const Stmt& s) {
  const Pos& modulePos = s.imports[0].pos;
  if (isCodeAsterModule(s.name)) {
    for (std::size_t i = 1; i < s.imports.size(); ++i) {
      const auto& in = s.imports[i];
      if (in.name == "CA" || in.name == "Commands") {
        bindName(in.alias.empty() ? in.name : in.alias,
                 Value(std::shared_ptr<NativeObject>(std::make_shared<ModuleObject>(in.name, &globals_))));
      }
      // command names are already global: `from code_aster.Commands import *` is a no-op
    }
    return;
  }
  if (s.name != "math") {
    raise(modulePos, "LANG_IMPORT", "import from module '" + s.name + "' is refused",
          "command files are a sandbox: they may import only the code_aster command namespace and 'math'");
  }
  const auto& names = mathNames();
  for (std::size_t i = 1; i < s.imports.size(); ++i) {
    const auto& in = s.imports[i];
    if (in.name == "*") {
      for (const auto& [name, value] : names) {
        bindName(name, value);
      }
      continue;
    }
    auto it = names.find(in.name);
    if (it == names.end()) {
      std::vector<std::string> candidates;
      for (const auto& [name, value] : names) {
        candidates.push_back(name);
      }
      raise(in.pos, "LANG_IMPORT", "module 'math' has no name '" + in.name + "'",
            suggestionNote(in.name, candidates));
    }
    bindName(in.alias.empty() ? in.name : in.alias, it->second);
  }
}

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
    raise(e.pos, "LANG_TYPE", "this expression cannot be evaluated here");
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
    raise(e.pos, "LANG_DESTROYED", "concept '" + e.text + "' was destroyed (by DETRUIRE) and cannot be used",
          "assign it again with a command before using it");
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
    note = "'" + e.text + "' is in the math module: add 'from math import " + e.text + "' (or 'import math')";
  }
  raise(e.pos, "LANG_NAME", "name '" + e.text + "' is not defined", note);
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
          langError("LANG_TYPE", "'**' in a dict needs a dict, not '" + other.typeName() + "'");
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
        raise(e.pos, "LANG_SIZE", "list too long");
      }
      out.push_back(eval(*e.items[0]));
      return;
    }
    const Expr& c = *e.items[clause];
    Value iterable = eval(*c.items[1]);
    try {
      forEachItem(iterable, [&](const Value& item) {
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
      raise(e.pos, "LANG_SIZE", "string too long");
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
      raise(at, "LANG_DESTROYED", "concept '" + object.asConcept()->name + "' was destroyed (by DETRUIRE)");
    }
    if (handler_ == nullptr) {
      raise(at, "LANG_ATTR", "concept attributes are not available here");
    }
    return handler_->conceptAttribute(object.asConcept(), name, location(at));
  }
  if (object.isNative()) {
    std::shared_ptr<const Value> v = object.asNative()->attribute(name);
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
  raise(at, "LANG_ATTR", "'" + object.typeName() + "' object has no attribute '" + name + "'");
}

void Evaluator::collectArguments(const Expr& call, std::size_t first, CallArguments& args) {
  for (std::size_t i = first; i < call.items.size(); ++i) {
    const Expr& a = *call.items[i];
    switch (a.kind) {
    case ExprKind::Keyword: {
      const Expr& valueExpr = *a.items[0];
      args.keywords.push_back(KeywordArgument{
          a.text, std::make_shared<const Value>(eval(valueExpr)),
          location(Pos{a.pos.line, a.pos.column, static_cast<int>(a.text.size())}), location(valueExpr.pos)});
      break;
    }
    case ExprKind::Star: {
      Value v = eval(*a.items[0]);
      try {
        for (Value& item : iterableItems(v, options_.limits)) {
          args.positional.push_back(std::move(item));
          args.positionalLocations.push_back(location(a.pos));
        }
      } catch (const LangError& err) {
        raise(a.pos, err);
      }
      break;
    }
    case ExprKind::DoubleStar: {
      Value v = eval(*a.items[0]);
      if (!v.isDict()) {
        raise(a.pos, "LANG_TYPE", "'**' needs a dict, not '" + v.typeName() + "'");
      }
      for (const auto& [key, value] : v.asDict()->items) {
        if (!key.isString()) {
          raise(a.pos, "LANG_TYPE", "keywords given with '**' must be strings, not '" + key.typeName() + "'");
        }
        if (args.find(key.asString()) != nullptr) {
          raise(a.pos, "LANG_ARGS", "keyword argument '" + key.asString() + "' given twice");
        }
        args.keywords.push_back(KeywordArgument{key.asString(), std::make_shared<const Value>(value),
                                                location(a.pos), location(a.pos)});
      }
      break;
    }
    default:
      args.positional.push_back(eval(a));
      args.positionalLocations.push_back(location(a.pos));
    }
  }
}

Value Evaluator::evalCall(const Expr& e, const std::string& target) {
  const Expr& calleeExpr = *e.items[0];
  // `obj.method(...)` on strings, lists and dicts: call the method directly
  if (calleeExpr.kind == ExprKind::Attribute) {
    Value object = eval(*calleeExpr.items[0]);
    if ((object.isString() || object.isSequence() || object.isDict()) && hasMethod(object, calleeExpr.text)) {
      return evalMethodCall(e, object);
    }
    Value callee = attributeOf(object, calleeExpr.text, calleeExpr.pos);
    CallArguments args;
    args.callLocation = location(calleeExpr.pos);
    collectArguments(e, 1, args);
    return call(callee, args, calleeExpr.pos, target);
  }
  Value callee = eval(calleeExpr);
  CallArguments args;
  args.callLocation = location(calleeExpr.pos);
  collectArguments(e, 1, args);
  return call(callee, args, calleeExpr.pos, target);
}

Value Evaluator::evalMethodCall(const Expr& e, const Value& object) {
  const Expr& calleeExpr = *e.items[0];
  CallArguments args;
  args.callLocation = location(calleeExpr.pos);
  collectArguments(e, 1, args);
  return *callMethod(*this, object, calleeExpr.text, args, calleeExpr.pos);
}

Value Evaluator::call(const Value& callee, const CallArguments& args, const Pos& at,
                      const std::string& target) {
  DepthGuard guard(evalDepth_, options_.maxEvalDepth, *this, at);
  if (callee.isCallable()) {
    const Callable& c = *callee.asCallable();
    if (c.isCommand()) {
      return callCommand(c.name(), args, at, target);
    }
    if (const auto* b = dynamic_cast<const Builtin*>(&c)) {
      return callBuiltin(*this, *b, args, at);
    }
    if (const auto* u = dynamic_cast<const UserFunction*>(&c)) {
      return callUser(*u, args, at);
    }
    if (const auto* n = dynamic_cast<const NativeCallable*>(&c)) {
      return callNative(*n, args, at);
    }
  }
  if (callee.isConcept() && handler_ != nullptr) {
    Value fn = attributeOf(callee, "__call__", at);
    if (fn.isCallable()) {
      return call(fn, args, at);
    }
  }
  raise(at, "LANG_CALL", "'" + callee.typeName() + "' object is not callable",
        callee.isConcept() ? "concept '" + callee.asConcept()->name + "' is not a function" : "");
}

void Evaluator::checkNotDestroyed(const Value& v, const Pos& at, int depth) const {
  if (depth > 20) {
    return;
  }
  if (v.isConcept() && v.asConcept()->destroyed) {
    raise(at, "LANG_DESTROYED",
          "concept '" + v.asConcept()->name + "' was destroyed (by DETRUIRE) and cannot be used");
  }
  if (v.isSequence()) {
    for (const Value& item : v.items()) {
      checkNotDestroyed(item, at, depth + 1);
    }
  } else if (v.isFactor()) {
    for (const auto& kw : v.asFactor()->keywords) {
      checkNotDestroyed(*kw.value, at, depth + 1);
    }
  }
}

Value Evaluator::callCommand(const std::string& name, const CallArguments& args, const Pos& at,
                             const std::string& target) {
  if (handler_ == nullptr) {
    raise(at, "LANG_CALL", "command " + name + " cannot be called here");
  }
  for (std::size_t i = 0; i < args.positional.size(); ++i) {
    checkNotDestroyed(args.positional[i], at);
  }
  for (const auto& kw : args.keywords) {
    if (kw.name == "reuse") {
      continue;
    }
    try {
      checkNotDestroyed(*kw.value, at);
    } catch (UserError&) {
      Diagnostic d = Diagnostic::fatal("LANG_DESTROYED",
                                       "keyword " + kw.name + " of " + name +
                                           " refers to a concept destroyed by DETRUIRE",
                                       kw.valueLocation);
      throw UserError(std::move(d));
    }
  }
  Value result = handler_->callCommand(name, args, target);
  if (handler_->finished()) {
    throw FinishSignal{};
  }
  return result;
}

Value Evaluator::callNative(const NativeCallable& fn, const CallArguments& args, const Pos& at) {
  try {
    return fn.function()(args);
  } catch (const UserError& err) {
    std::vector<Diagnostic> ds = err.diagnostics();
    bool changed = false;
    for (auto& d : ds) {
      if (!d.location.known()) {
        d.location = location(at);
        changed = true;
      } else if (d.location.file != file_ || d.location.line != at.line) {
        d.withNote("while evaluating the call of " + fn.name() + " at " + location(at).str());
        changed = true;
      }
    }
    if (!changed) {
      throw;
    }
    throw UserError(std::move(ds));
  } catch (const LangError& err) {
    raise(at, err);
  }
}

Value Evaluator::callUser(const UserFunction& fn, const CallArguments& args, const Pos& at) {
  if (callDepth_ >= options_.maxCallDepth) {
    raise(at, "LANG_DEPTH",
          "too many nested function calls (more than " + std::to_string(options_.maxCallDepth) + ")",
          "is a function calling itself without end?");
  }
  Scope local;
  local.function = true;
  std::string name = fn.name();
  if (fn.lambda != nullptr) {
    std::size_t n = fn.lambda->items.size() - 1;
    if (args.positional.size() != n || !args.keywords.empty()) {
      raise(at, "LANG_ARGS",
            "lambda takes " + std::to_string(n) + " positional arguments but " +
                std::to_string(args.positional.size()) + " were given");
    }
    for (std::size_t i = 0; i < n; ++i) {
      local.vars[fn.lambda->items[i + 1]->text] = args.positional[i];
    }
  } else {
    const auto& params = fn.def->params;
    std::vector<bool> bound(params.size(), false);
    std::size_t regular = 0;
    int starIndex = -1;
    int starStarIndex = -1;
    for (std::size_t i = 0; i < params.size(); ++i) {
      if (params[i].star == 1) {
        starIndex = static_cast<int>(i);
      } else if (params[i].star == 2) {
        starStarIndex = static_cast<int>(i);
      } else if (starIndex < 0) {
        ++regular;
      }
    }
    ValueList extra;
    for (std::size_t i = 0; i < args.positional.size(); ++i) {
      if (i < regular) {
        local.vars[params[i].name] = args.positional[i];
        bound[i] = true;
      } else if (starIndex >= 0) {
        extra.push_back(args.positional[i]);
      } else {
        raise(at, "LANG_ARGS",
              name + "() takes " + std::to_string(regular) + " positional arguments but " +
                  std::to_string(args.positional.size()) + " were given");
      }
    }
    if (starIndex >= 0) {
      local.vars[params[static_cast<std::size_t>(starIndex)].name] = Value::tuple(std::move(extra));
      bound[static_cast<std::size_t>(starIndex)] = true;
    }
    auto kwargs = std::make_shared<DictObject>();
    for (const auto& kw : args.keywords) {
      auto it = std::find_if(params.begin(), params.end(),
                             [&](const Param& p) { return p.name == kw.name && p.star == 0; });
      if (it == params.end()) {
        if (starStarIndex >= 0) {
          kwargs->items.emplace_back(Value(kw.name), *kw.value);
          continue;
        }
        std::vector<std::string> names;
        for (const auto& p : params) {
          names.push_back(p.name);
        }
        Diagnostic d =
            Diagnostic::fatal("LANG_ARGS", name + "() got an unexpected keyword argument '" + kw.name + "'",
                              kw.location.known() ? kw.location : location(at));
        std::string note = suggestionNote(kw.name, names);
        if (!note.empty()) {
          d.withNote(note);
        }
        throw UserError(std::move(d));
      }
      auto index = static_cast<std::size_t>(it - params.begin());
      if (bound[index]) {
        raise(at, "LANG_ARGS", name + "() got multiple values for argument '" + kw.name + "'");
      }
      local.vars[kw.name] = *kw.value;
      bound[index] = true;
    }
    if (starStarIndex >= 0) {
      local.vars[params[static_cast<std::size_t>(starStarIndex)].name] = Value(kwargs);
      bound[static_cast<std::size_t>(starStarIndex)] = true;
    }
    for (std::size_t i = 0; i < params.size(); ++i) {
      if (!bound[i]) {
        if (!fn.hasDefault[i]) {
          raise(at, "LANG_ARGS", name + "() missing required argument '" + params[i].name + "'");
        }
        local.vars[params[i].name] = fn.defaults[i];
      }
    }
  }
  Scope* savedScope = scope_;
  auto savedModule = module_;
  auto savedFile = file_;
  scope_ = &local;
  module_ = fn.module;
  file_ = fn.module->file;
  ++callDepth_;
  auto restore = [&] {
    --callDepth_;
    scope_ = savedScope;
    module_ = savedModule;
    file_ = savedFile;
  };
  Value result;
  try {
    if (fn.lambda != nullptr) {
      result = eval(*fn.lambda->items[0]);
    } else {
      Flow flow = execBlock(fn.def->body);
      if (flow == Flow::Return) {
        result = std::move(returnValue_);
        returnValue_ = Value();
      }
    }
  } catch (...) {
    restore();
    throw;
  }
  restore();
  return result;
}

} // namespace stella

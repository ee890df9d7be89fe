// Freeing the lists and dicts that contain themselves (reference cycles) when the evaluator is
// destroyed: the containers changed in place are recorded, then searched for cycles.
#include "EvaluatorParts.hpp"

#include <unordered_map>

namespace stella {

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

} // namespace stella

// Access to containers with Python's rules: range objects, iteration, indices and slices
// (getItem, setItem, deleteItem) and dictionary keys.
#include "Runtime.hpp"
#include "SequenceObject.hpp"

#include <algorithm>
#include <limits>

namespace stella {

namespace {

bool isIntLike(const Value& v) {
  return v.isInt() || v.isBool();
}

} // namespace

std::int64_t RangeObject::size() const {
  // in unsigned arithmetic: stop - start may not fit in 64 signed bits
  std::uint64_t n = 0;
  if (step > 0 && stop > start) {
    n = (static_cast<std::uint64_t>(stop) - static_cast<std::uint64_t>(start) - 1) /
            static_cast<std::uint64_t>(step) +
        1;
  } else if (step < 0 && start > stop) {
    n = (static_cast<std::uint64_t>(start) - static_cast<std::uint64_t>(stop) - 1) /
            (static_cast<std::uint64_t>(-(step + 1)) + 1) +
        1;
  }
  return n > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())
             ? std::numeric_limits<std::int64_t>::max()
             : static_cast<std::int64_t>(n);
}

const RangeObject* asRange(const Value& v) {
  return v.isNative() ? dynamic_cast<const RangeObject*>(v.asNative().get()) : nullptr;
}

ValueList iterableItems(const Value& v, const RuntimeLimits& limits) {
  if (v.isSequence()) {
    chargeBulk(static_cast<std::int64_t>(v.items().size()), sizeof(Value));
    return v.items();
  }
  if (const RangeObject* r = asRange(v)) {
    if (r->size() > limits.maxSequenceLength) {
      langError("LANG_SIZE", {{"max_sequence_length", std::to_string(limits.maxSequenceLength)}});
    }
  }
  ValueList out;
  forEachItem(v, [&](const Value& item) {
    out.push_back(item);
    if (out.size() == out.capacity()) {
      chargeAllocation(static_cast<std::int64_t>(out.capacity() * sizeof(Value)));
    }
    return true;
  });
  return out;
}

std::size_t normalizeIndex(std::int64_t index, std::size_t size, const char* what) {
  auto n = static_cast<std::int64_t>(size);
  std::int64_t i = index < 0 ? index + n : index;
  if (i < 0 || i >= n) {
    langError(size == 0 ? "LANG_INDEX.empty" : "LANG_INDEX.range",
              {{"what", what}, {"index", index}, {"size", size}, {"last", n - 1}, {"n", n}});
  }
  return static_cast<std::size_t>(i);
}

std::int64_t toIndex(const Value& v, const char* what) {
  if (!isIntLike(v)) {
    langError("LANG_TYPE.2", {{"what", std::string(what)}, {"type_name", v.typeName()}});
  }
  return v.asInt();
}

namespace {

// Python's slice.indices(): clamps bounds for a sequence of `size`.
struct SliceBounds {
  std::int64_t start, stop, step;
};

SliceBounds sliceBounds(const Value& slice, std::size_t size) {
  const ValueList& parts = slice.items(); // (lower, upper, step) as a tuple tagged by the evaluator
  auto n = static_cast<std::int64_t>(size);
  std::int64_t step = parts[2].isNone() ? 1 : toIndex(parts[2], "slice step");
  if (step == 0) {
    langError("LANG_VALUE", {});
  }
  auto clamp = [&](const Value& v, std::int64_t dflt) {
    if (v.isNone()) {
      return dflt;
    }
    std::int64_t i = toIndex(v, "slice index");
    if (i < 0) {
      i += n;
      if (i < 0) {
        i = step < 0 ? -1 : 0;
      }
    } else if (i >= n) {
      i = step < 0 ? n - 1 : n;
    }
    return i;
  };
  std::int64_t start = clamp(parts[0], step < 0 ? n - 1 : 0);
  std::int64_t stop = clamp(parts[1], step < 0 ? -1 : n);
  return {start, stop, step};
}

} // namespace

// A slice value is a Native SliceObject made by the evaluator.
class SliceObject : public NativeObject {
public:
  explicit SliceObject(Value bounds) : parts(std::move(bounds)) {}
  std::string typeName() const override { return "slice"; }
  Value parts;
};

Value makeSlice(Value lower, Value upper, Value step) {
  return Value(std::shared_ptr<NativeObject>(
      std::make_shared<SliceObject>(Value::tuple({std::move(lower), std::move(upper), std::move(step)}))));
}

namespace {
const SliceObject* asSlice(const Value& v) {
  return v.isNative() ? dynamic_cast<const SliceObject*>(v.asNative().get()) : nullptr;
}

template <class Seq, class Get> Seq sliceOf(std::size_t size, const SliceObject& slice, Get get) {
  SliceBounds b = sliceBounds(slice.parts, size);
  Seq out;
  if (b.step > 0) {
    for (std::int64_t i = b.start; i < b.stop; i += b.step) {
      get(out, static_cast<std::size_t>(i));
    }
  } else {
    for (std::int64_t i = b.start; i > b.stop; i += b.step) {
      get(out, static_cast<std::size_t>(i));
    }
  }
  return out;
}
} // namespace

Value getItem(const Value& container, const Value& index) {
  if (const SliceObject* slice = asSlice(index)) {
    if (container.isString()) {
      const std::string& s = container.asString();
      return Value(
          sliceOf<std::string>(s.size(), *slice, [&](std::string& out, std::size_t i) { out += s[i]; }));
    }
    if (container.isSequence()) {
      const ValueList& items = container.items();
      ValueList out = sliceOf<ValueList>(items.size(), *slice,
                                         [&](ValueList& o, std::size_t i) { o.push_back(items[i]); });
      return container.isTuple() ? Value::tuple(std::move(out)) : Value::list(std::move(out));
    }
    langError("LANG_TYPE.3", {{"type_name", container.typeName()}});
  }
  if (container.isSequence()) {
    const ValueList& items = container.items();
    return items[normalizeIndex(toIndex(index, "list index"), items.size(), container.typeName().c_str())];
  }
  if (container.isString()) {
    const std::string& s = container.asString();
    return Value(std::string(1, s[normalizeIndex(toIndex(index, "string index"), s.size(), "string")]));
  }
  if (container.isDict()) {
    checkHashable(index);
    const Value* v = dictFind(*container.asDict(), index);
    if (v == nullptr) {
      langError("LANG_KEY", {{"repr", index.repr()}});
    }
    return *v;
  }
  if (const RangeObject* r = asRange(container)) {
    return Value(r->at(static_cast<std::int64_t>(
        normalizeIndex(toIndex(index, "range index"), static_cast<std::size_t>(r->size()), "range"))));
  }
  if (const auto* seq =
          container.isNative() ? dynamic_cast<const SequenceObject*>(container.asNative().get()) : nullptr) {
    const std::string what = container.typeName();
    return seq->item(static_cast<std::int64_t>(
        normalizeIndex(toIndex(index, "index"), static_cast<std::size_t>(seq->length()), what.c_str())));
  }
  langError(container.isConcept() ? "LANG_TYPE.concept_subscript" : "LANG_TYPE.subscript",
            {{"type", container.typeName()}});
}

void setItem(const Value& container, const Value& index, const Value& value) {
  if (container.isList()) {
    if (asSlice(index) != nullptr) {
      langError("LANG_TYPE.4", {});
    }
    auto& items = container.asList()->items;
    items[normalizeIndex(toIndex(index, "list index"), items.size(), "list")] = value;
    return;
  }
  if (container.isDict()) {
    dictSet(*container.asDict(), index, value);
    return;
  }
  langError(container.isTuple() ? "LANG_TYPE.tuple_assignment" : "LANG_TYPE.assignment",
            {{"type", container.typeName()}});
}

void deleteItem(const Value& container, const Value& index) {
  if (container.isList()) {
    auto& items = container.asList()->items;
    items.erase(items.begin() + static_cast<std::ptrdiff_t>(
                                    normalizeIndex(toIndex(index, "list index"), items.size(), "list")));
    return;
  }
  if (container.isDict()) {
    auto& items = container.asDict()->items;
    for (auto it = items.begin(); it != items.end(); ++it) {
      if (it->first.equals(index)) {
        items.erase(it);
        return;
      }
    }
    langError("LANG_KEY", {{"repr", index.repr()}});
  }
  langError("LANG_TYPE.5", {{"type_name", container.typeName()}});
}

void checkHashable(const Value& key) {
  if (key.isList() || key.isDict()) {
    langError("LANG_TYPE.6", {{"type_name", key.typeName()}});
  }
}

const Value* dictFind(const DictObject& dict, const Value& key) {
  for (const auto& [k, v] : dict.items) {
    if (k.equals(key)) {
      return &v;
    }
  }
  return nullptr;
}

void dictSet(DictObject& dict, const Value& key, const Value& value) {
  checkHashable(key);
  for (auto& [k, v] : dict.items) {
    if (k.equals(key)) {
      v = value;
      return;
    }
  }
  dict.items.emplace_back(key, value);
}

} // namespace stella

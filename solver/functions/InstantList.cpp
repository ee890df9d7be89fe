#include "InstantList.hpp"

namespace stella {

FailurePolicy InstantList::onError() const {
  for (const auto& f : failures) {
    if (f.event == FailurePolicy::Event::Error) {
      return f;
    }
  }
  return FailurePolicy{};
}

} // namespace stella

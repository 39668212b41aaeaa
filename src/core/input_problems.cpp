#include "core/input_problems.hpp"

namespace drawbend {

void InputProblems::throw_if_any() const {
  if (messages_.empty()) return;
  if (messages_.size() == 1) throw InputError(messages_.front());
  std::string all = std::to_string(messages_.size()) + " problems in " + file_ + ":";
  for (const auto& m : messages_) all += "\n  " + m;
  throw InputError(all);
}

}  // namespace drawbend

#pragma once
// Collects every problem found in one input file, so that a user fixes them
// all in one go instead of one per run.  Each message already names
// file:line: key: what was expected, what was found; throw_if_any() throws one
// InputError holding all of them (one per line).
#include <string>
#include <vector>

#include "core/csv.hpp"

namespace drawbend {

class InputProblems {
 public:
  explicit InputProblems(std::string file) : file_(std::move(file)) {}

  void add(std::string message) { messages_.push_back(std::move(message)); }
  bool empty() const { return messages_.empty(); }
  std::size_t size() const { return messages_.size(); }
  const std::vector<std::string>& messages() const { return messages_; }

  /// Run `fn`; an InputError or std::invalid_argument it throws becomes one
  /// problem (an invalid_argument gets the file name in front).  Returns
  /// whether fn completed.
  template <class F>
  bool attempt(F&& fn) {
    try {
      fn();
      return true;
    } catch (const InputError& e) {
      add(e.what());
    } catch (const std::invalid_argument& e) {
      add(file_ + ": " + e.what());
    }
    return false;
  }

  /// Throw one InputError with every message (nothing if there is none).
  void throw_if_any() const;

 private:
  std::string file_;
  std::vector<std::string> messages_;
};

}  // namespace drawbend

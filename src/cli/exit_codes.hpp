#pragma once
// The `drawbend` commands' error handling: one message on standard error and
// the exit code (2 input error, 3 numerical fault or other failure).
#include <iostream>
#include <stdexcept>

#include "core/csv.hpp"
#include "fe/guards.hpp"

namespace drawbend::cli {

template <class F>
int with_exit_codes(F&& f) {
  try {
    return f();
  } catch (const InputError& e) {
    std::cerr << "input error: " << e.what() << "\n";
    return 2;
  } catch (const std::invalid_argument& e) {
    std::cerr << "input error: " << e.what() << "\n";
    return 2;
  } catch (const fe::NumericalFault& e) {
    std::cerr << "\nnumerical fault: " << e.what() << "\n";
    return 3;
  } catch (const std::exception& e) {
    std::cerr << "\nerror: " << e.what() << "\n";
    return 3;
  }
}

}  // namespace drawbend::cli

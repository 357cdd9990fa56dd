// The one place where exceptions become messages and exit statuses for every isosid program:
// 0 success, 1 failure during the computation, 2 bad input (one line naming file, field, problem).
#pragma once
#include "isosid/format/error.hpp"

#include <exception>
#include <iostream>
#include <new>

namespace isosid::common {

constexpr int kExitBadInput = 2;
constexpr int kExitFailure = 1;

template <class Body>
int run_guarded(const char* program, Body&& body) {
  try {
    return body();
  } catch (const format::InputError& e) {
    std::cerr << program << ": error: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const format::ComputationError& e) {
    std::cerr << program << ": failed: " << e.what() << "\n";
    return kExitFailure;
  } catch (const std::bad_alloc&) {
    std::cerr << program << ": failed: out of memory\n";
    return kExitFailure;
  } catch (const std::exception& e) {
    std::cerr << program << ": failed: " << e.what() << "\n";
    return kExitFailure;
  }
}

}  // namespace isosid::common

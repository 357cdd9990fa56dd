// Test support: what a program leaves on stderr when it refuses its input (exit 2) or a
// computation fails (exit 1): one line (docs/diagnostics.md).
#pragma once
#include "support/run_program.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <concepts>
#include <string>

namespace isosid::test {

/// Checks that `r` exited with `status` and printed one line that `message` matches.
template <class Matcher>
  requires std::derived_from<Matcher, Catch::Matchers::Impl::MatcherUntypedBase>
void check_one_line_exit(const ProgramResult& r, int status, const Matcher& message) {
  INFO(r.err);
  CHECK(r.exit_status == status);
  CHECK_THAT(r.err, message);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
}

/// Checks that `r` exited with `status` and printed one line that contains `expected`.
inline void check_one_line_exit(const ProgramResult& r, int status, const std::string& expected) {
  check_one_line_exit(r, status, Catch::Matchers::Contains(expected));
}

}  // namespace isosid::test

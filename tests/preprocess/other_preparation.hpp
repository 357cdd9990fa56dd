// Another preparation on the machine, for the tests of the memory ledger: a forked child that
// records a reservation in a ledger folder and then runs on.
#pragma once
#include "reduce/memory_ledger.hpp"

#include <catch2/catch.hpp>
#include <sys/types.h>
#include <unistd.h>

#include <string>

namespace isosid::test {

/// Forks a child whose current stage will take `bytes` more (recorded in `folder`), and returns
/// its pid once it is recorded. The child then ends after `seconds`, or runs until killed (0).
/// It ends as a killed preparation would, without removing its file; the caller reaps it.
inline pid_t fork_other_preparation(const std::string& folder, double bytes, unsigned seconds) {
  int ready[2];
  REQUIRE(::pipe(ready) == 0);
  const pid_t child = ::fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    prep::MemoryLedger other(folder);
    const char byte = other.request(bytes, 10 * bytes) == prep::Admission::Start ? 1 : 0;
    (void)!::write(ready[1], &byte, 1);
    if (seconds > 0)
      ::sleep(seconds);
    else
      ::pause();
    ::_exit(0);
  }
  char byte = 0;
  REQUIRE(::read(ready[0], &byte, 1) == 1);
  REQUIRE(byte == 1);
  ::close(ready[0]);
  ::close(ready[1]);
  return child;
}

}  // namespace isosid::test

// Another preparation on the machine, for the tests of the memory ledger: a forked child that
// records a reservation in a ledger folder and then runs on.
#pragma once
#include "reduce/memory_ledger.hpp"

#include <catch2/catch.hpp>
#include <csignal>
#include <sys/prctl.h>
#include <sys/types.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace isosid::test {

enum class OtherEnds {
  WhenKilled,         ///< runs until the test kills it
  WhenAnotherWaits,   ///< ends once another process's entry says it waits (at most after 120 s)
};

/// Forks a child whose current stage will take `bytes` more (recorded in `folder`), and returns
/// its pid once it is recorded. It ends as a killed preparation would, without removing its
/// file, and with the test process at the latest; the caller reaps it.
inline pid_t fork_other_preparation(const std::string& folder, double bytes, OtherEnds ends) {
  int ready[2];
  REQUIRE(::pipe(ready) == 0);
  const pid_t child = ::fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    prep::MemoryLedger other(folder);
    const char byte = other.request(bytes, 10 * bytes) == prep::Admission::Start ? 1 : 0;
    (void)!::write(ready[1], &byte, 1);
    if (ends == OtherEnds::WhenKilled) ::pause();
    const std::string self = "pid-" + std::to_string(::getpid());
    for (int i = 0; i < 6000; ++i) {  // 20 ms apart
      std::error_code ec;
      for (const auto& file : std::filesystem::directory_iterator(folder, ec)) {
        const std::string name = file.path().filename().string();
        unsigned long long start = 0;
        long long reserved = 0;
        int waiting = 0;
        if (name.rfind("pid-", 0) == 0 && name != self && std::ifstream(file.path()) >> start >> reserved >> waiting && waiting == 1) ::_exit(0);
      }
      ::usleep(20000);
    }
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

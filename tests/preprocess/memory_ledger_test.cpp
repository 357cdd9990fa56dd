// The ledger of the preparations sharing one machine's memory (preprocess/reduce/memory_ledger):
// its decision, its files between processes, preparations on threads of one process, and a
// preparation's entry while it runs.
#include "isosid/common/progress_line.hpp"
#include "model/model_file.hpp"
#include "pipeline/prepare.hpp"
#include "reduce/memory_budget.hpp"
#include "preprocess/other_preparation.hpp"
#include "reduce/memory_ledger.hpp"
#include "support/run_program.hpp"

#include <atomic>
#include <catch2/catch.hpp>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <thread>
#include <sys/wait.h>
#include <unistd.h>

using namespace isosid;
using prep::Admission;

TEST_CASE("a stage starts beside the other preparations' coming growth, waits where it fits once they end, else is refused", "[memory]") {
  // no others: the memory available decides alone
  CHECK(prep::admission(4, 10, {}) == Admission::Start);
  CHECK(prep::admission(11, 10, {}) == Admission::Refuse);
  // one other holds 4 and will reach 10 (6 to come): 4 of the 10 available are left now, 14 once it ends
  const std::vector<prep::LedgerEntry> growing{{10, 4, false}};
  CHECK(prep::admission(4, 10, growing) == Admission::Start);
  CHECK(prep::admission(5, 10, growing) == Admission::Wait);
  CHECK(prep::admission(14, 10, growing) == Admission::Wait);
  CHECK(prep::admission(15, 10, growing) == Admission::Refuse);
  // one that waits itself is not waited for (two preparations never wait for each other), but
  // what it was promised before it waited counts against a start
  const std::vector<prep::LedgerEntry> waiting{{4, 4, true}};
  CHECK(prep::admission(10, 10, waiting) == Admission::Start);
  CHECK(prep::admission(11, 10, waiting) == Admission::Refuse);
  const std::vector<prep::LedgerEntry> promised{{10, 4, true}};
  CHECK(prep::admission(4, 10, promised) == Admission::Start);
  CHECK(prep::admission(5, 10, promised) == Admission::Refuse);
  CHECK(prep::growers(promised).promised == 6);
  // growth is what is still to come: one past its reservation adds none, yet ending returns its memory
  const std::vector<prep::LedgerEntry> past{{3, 5, false}};
  CHECK(prep::admission(10, 10, past) == Admission::Start);
  CHECK(prep::admission(15, 10, past) == Admission::Wait);
}

namespace {

/// Waits until /proc shows `pid` in a state whose letter is among `states` (at most 2 s).
void await_state(pid_t pid, const std::string& states) {
  for (int i = 0; i < 200; ++i) {
    std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
    std::string line;
    std::getline(stat, line);
    const auto end = line.rfind(')');
    if (end != std::string::npos && end + 2 < line.size() && states.find(line[end + 2]) != std::string::npos) return;
    ::usleep(10000);
  }
}

/// ISOSID_MEMORY_LEDGER set for a scope.
struct LedgerFolder {
  explicit LedgerFolder(const std::string& folder) { ::setenv("ISOSID_MEMORY_LEDGER", folder.c_str(), 1); }
  ~LedgerFolder() { ::unsetenv("ISOSID_MEMORY_LEDGER"); }
};

}  // namespace

TEST_CASE("the ledger counts a live preparation's reservation and drops an ended one's or a reused pid's", "[memory]") {
  const test::ScratchDir dir("memory-ledger");
  const std::string folder = dir.path("ledger");
  const pid_t child = test::fork_other_preparation(folder, 1e12, test::OtherEnds::WhenKilled);  // 1 TB to come
  const std::string child_file = folder + "/pid-" + std::to_string(child), own_file = folder + "/pid-" + std::to_string(::getpid());
  // a file named by a live pid (1) that records another start time: a pid since reused; and a
  // file of another name, which the ledger never touches
  std::ofstream(folder + "/pid-1") << "12345 1000000000000 0\n";
  std::ofstream(folder + "/notes") << "not the ledger's\n";
  {
    prep::MemoryLedger mine(folder);
    prep::Growers others;
    CHECK(mine.request(1e9, 1e10, &others) == Admission::Wait);
    CHECK(others.count == 1);
    CHECK(others.growth == Approx(1e12).margin(1e8));  // reserved 1 TB beyond what it held, as it still holds
    CHECK(others.resident > 0);                        // the child's pages, read from /proc
    CHECK_FALSE(std::filesystem::exists(folder + "/pid-1"));
    CHECK(std::filesystem::exists(folder + "/notes"));
    CHECK(std::filesystem::exists(child_file));
    // stopped (a signal, a debugger), it is not waited for (refused, not waiting without end),
    // though what it was promised still counts; going on, it is waited for again
    ::kill(child, SIGSTOP);
    await_state(child, "Tt");
    CHECK(mine.request(1e9, 1e10, &others) == Admission::Refuse);
    CHECK(others.count == 0);
    CHECK(others.promised == Approx(1e12).margin(1e8));
    ::kill(child, SIGCONT);
    await_state(child, "SR");
    CHECK(mine.request(1e9, 1e10) == Admission::Wait);
    // the other ends without removing its file (killed; a zombie until reaped counts as ended)
    ::kill(child, SIGKILL);
    await_state(child, "Z");
    CHECK(mine.request(1e9, 1e10, &others) == Admission::Start);
    CHECK(others.count == 0);
    CHECK_FALSE(std::filesystem::exists(child_file));
    CHECK(std::filesystem::exists(own_file));
    mine.withdraw();
    CHECK_FALSE(std::filesystem::exists(own_file));
    CHECK(mine.request(1e9, 1e10) == Admission::Start);
  }
  // a preparation that ends removes its own file
  CHECK_FALSE(std::filesystem::exists(own_file));
  ::waitpid(child, nullptr, 0);
}

TEST_CASE("preparations on two threads of one process count each other: the second waits for the first's stage", "[memory]") {
  const test::ScratchDir dir("memory-ledger-threads");
  const LedgerFolder ledger(dir.path("ledger"));
  // each stage needs 60 % of what is available (what check_memory compares with): one fits, two do not
  const double available = prep::memory_limit();
  REQUIRE(available > 0);
  const double stage = 0.6 * available;
  std::atomic<int> first{0};  // 1: its stage started (or refused: -1); 2: told to end
  std::atomic<bool> second_started{false}, refused{false};
  std::thread one([&] {
    const prep::PreparationMemory span;
    try {
      prep::check_memory("test", "the first stage", stage);
    } catch (const prep::MemoryRefusal&) {  // the machine's memory fell meanwhile: failed below
      refused = true;
    }
    first = 1;
    while (first != 2) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  });
  while (first != 1) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  std::thread two([&] {
    const prep::PreparationMemory span;
    try {
      prep::check_memory("test", "the second stage", stage);
      second_started = true;
    } catch (const prep::MemoryRefusal&) {
      refused = true;
    }
  });
  for (int i = 0; i < 400 && common::work_step().rfind("waiting for memory: the second stage", 0) != 0; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  CHECK_THAT(common::work_step(), Catch::Matchers::StartsWith("waiting for memory: the second stage needs about"));
  CHECK_FALSE(second_started);
  first = 2;  // the first preparation ends: the second goes on
  one.join();
  two.join();
  CHECK(second_started);
  CHECK_FALSE(refused);
}

TEST_CASE("a preparation in process holds its entry in the ledger while it runs and withdraws it at its end", "[memory]") {
  const test::ScratchDir dir("memory-ledger-prepare");
  const std::string folder = dir.path("ledger");
  const LedgerFolder ledger(folder);
  const std::string entry = folder + "/pid-" + std::to_string(::getpid());
  struct Watch : prep::StageObserver {
    std::string entry;
    bool held_in_reduction = false;
    void finished(const std::string& stage, double) override {
      if (stage == "reduction") held_in_reduction = std::filesystem::exists(entry);
    }
  } watch;
  watch.entry = entry;
  // a check outside any preparation (a library call on its own) reserves nothing after it
  prep::check_memory("test", "a stage outside any preparation", 1);
  CHECK_FALSE(std::filesystem::exists(entry));
  (void)prep::prepare(prep::read_model_file(std::string(ISOSID_GOLDEN_DIR) + "/sphere_small.model.toml"), {.build_sid = true, .output = ""}, watch);
  CHECK(watch.held_in_reduction);
  CHECK_FALSE(std::filesystem::exists(entry));  // a process that lives on (Python's) reserves nothing after it
}

// The ledger of the preparations sharing one machine's memory (preprocess/reduce/memory_ledger):
// its decision, its files between processes, and a preparation's entry while it runs.
#include "model/model_file.hpp"
#include "pipeline/prepare.hpp"
#include "preprocess/other_preparation.hpp"
#include "reduce/memory_ledger.hpp"
#include "support/run_program.hpp"

#include <catch2/catch.hpp>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
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
  // one that waits itself neither grows nor is waited for: two preparations never wait for each other
  const std::vector<prep::LedgerEntry> waiting{{4, 4, true}};
  CHECK(prep::admission(10, 10, waiting) == Admission::Start);
  CHECK(prep::admission(11, 10, waiting) == Admission::Refuse);
  // growth is what is still to come: one past its reservation adds none, yet ending returns its memory
  const std::vector<prep::LedgerEntry> past{{3, 5, false}};
  CHECK(prep::admission(10, 10, past) == Admission::Start);
  CHECK(prep::admission(15, 10, past) == Admission::Wait);
}

TEST_CASE("the ledger counts a live preparation's reservation and drops an ended one's or a reused pid's", "[memory]") {
  const test::ScratchDir dir("memory-ledger");
  const std::string folder = dir.path("ledger");
  const pid_t child = test::fork_other_preparation(folder, 1e12, 0);  // 1 TB to come, running until killed
  // a file named by a live pid (1) that records another start time: a pid since reused
  std::ofstream(folder + "/1") << "12345 1000000000000 0\n";
  {
    prep::MemoryLedger mine(folder);
    CHECK(mine.request(1e9, 1e10) == Admission::Wait);
    CHECK(mine.others_growing() == 1);
    CHECK(mine.others_growth() == Approx(1e12).margin(1e8));  // reserved 1 TB beyond what it held, as it still holds
    CHECK(mine.others_resident() > 0);  // the child's pages, read from /proc
    CHECK_FALSE(std::filesystem::exists(folder + "/1"));
    CHECK(std::filesystem::exists(folder + "/" + std::to_string(child)));
    // the other ends without removing its file (killed; a zombie until reaped counts as ended)
    ::kill(child, SIGKILL);
    for (int i = 0; i < 200 && std::filesystem::exists("/proc/" + std::to_string(child) + "/stat"); ++i) {
      std::ifstream stat("/proc/" + std::to_string(child) + "/stat");
      std::string line;
      std::getline(stat, line);
      if (line.find(") Z") != std::string::npos) break;
      ::usleep(10000);
    }
    CHECK(mine.request(1e9, 1e10) == Admission::Start);
    CHECK(mine.others_growing() == 0);
    CHECK_FALSE(std::filesystem::exists(folder + "/" + std::to_string(child)));
    CHECK(std::filesystem::exists(folder + "/" + std::to_string(::getpid())));
    mine.withdraw();
    CHECK_FALSE(std::filesystem::exists(folder + "/" + std::to_string(::getpid())));
    CHECK(mine.request(1e9, 1e10) == Admission::Start);
  }
  // a preparation that ends removes its own file
  CHECK_FALSE(std::filesystem::exists(folder + "/" + std::to_string(::getpid())));
  ::waitpid(child, nullptr, 0);
}

TEST_CASE("a preparation in process holds its entry in the ledger while it runs and withdraws it at its end", "[memory]") {
  const test::ScratchDir dir("memory-ledger-prepare");
  const std::string folder = dir.path("ledger");
  ::setenv("ISOSID_MEMORY_LEDGER", folder.c_str(), 1);
  const std::string entry = folder + "/" + std::to_string(::getpid());
  struct Watch : prep::StageObserver {
    std::string entry;
    bool held_in_reduction = false;
    void finished(const std::string& stage, double) override {
      if (stage == "reduction") held_in_reduction = std::filesystem::exists(entry);
    }
  } watch;
  watch.entry = entry;
  (void)prep::prepare(prep::read_model_file(std::string(ISOSID_GOLDEN_DIR) + "/sphere_small.model.toml"), {.build_sid = true, .output = ""}, watch);
  ::unsetenv("ISOSID_MEMORY_LEDGER");
  CHECK(watch.held_in_reduction);
  CHECK_FALSE(std::filesystem::exists(entry));  // a process that lives on (Python's) reserves nothing after it
}

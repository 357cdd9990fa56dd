// Memory limit of a preparation; see memory_budget.hpp.
#include "reduce/memory_budget.hpp"

#include "isosid/common/heap_reuse.hpp"
#include "isosid/common/progress_line.hpp"
#include "reduce/memory_ledger.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <mutex>
#include <optional>
#include <sys/resource.h>
#include <thread>

namespace isosid::prep {
namespace {

std::atomic<double> g_limit{0};

double available_bytes() {
  double bytes = 0;
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  double kib = 0;
  std::string unit;
  while (meminfo >> key >> kib >> unit)
    if (key == "MemAvailable:") bytes = kib * 1024.0;
  // what this process has freed stays in its heap for reuse (common/heap_reuse), uncounted there
  if (bytes > 0) bytes += common::freed_bytes_held();
  for (int resource : {RLIMIT_AS, RLIMIT_DATA}) {
    rlimit r{};
    if (::getrlimit(resource, &r) == 0 && r.rlim_cur != RLIM_INFINITY)
      bytes = bytes > 0 ? std::min(bytes, double(r.rlim_cur)) : double(r.rlim_cur);
  }
  return bytes;
}

/// The process's place in the machine's memory ledger, and the lock of its checks (a
/// process's preparations may run on threads of their own).
struct ProcessLedger {
  std::mutex mutex;
  std::optional<MemoryLedger> ledger;  ///< in ledger_folder() as it was at the last check
  int preparations = 0;                ///< PreparationMemory scopes open

  MemoryLedger& current() {
    const std::string folder = ledger_folder();
    if (!ledger || ledger->folder() != folder) ledger.emplace(folder);  // the old one's file withdrawn
    return *ledger;
  }
};

ProcessLedger& process_ledger() {
  static ProcessLedger the;
  return the;
}

std::string gib(double bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g GiB", bytes / (1024.0 * 1024.0 * 1024.0));
  return text;
}

}  // namespace

void set_memory_limit(double bytes) { g_limit.store(std::max(0.0, bytes)); }

double memory_limit() {
  const double set = g_limit.load();
  return set > 0 ? set : available_bytes();
}

void check_memory(const std::string& field, const std::string& what, double bytes) {
  const double set = g_limit.load();
  if (set > 0) {  // the user's limit for this process alone
    if (bytes > set) throw MemoryRefusal(field, what + " needs about " + gib(bytes) + ", more than the " + gib(set) + " of --memory-limit");
    return;
  }
  // the machine's memory, shared with the other preparations running on it (memory_ledger)
  ProcessLedger& process = process_ledger();
  const std::lock_guard<std::mutex> one_check(process.mutex);
  MemoryLedger& ledger = process.current();
  const std::string step = common::work_step();
  bool waited = false;
  for (;;) {
    const double available = available_bytes();
    if (available <= 0) return;  // not known here: nothing to check against
    switch (ledger.request(bytes, available)) {
      case Admission::Start:
        if (waited) common::set_work_step(step);
        return;
      case Admission::Refuse:
        throw MemoryRefusal(field, what + " needs about " + gib(bytes) + ", more than the " +
                                       (ledger.others_growing() > 0 ? gib(available + ledger.others_resident()) + " this machine would have available once the " +
                                                                          std::to_string(ledger.others_growing()) + " other preparation(s) running on it end"
                                                                    : gib(available) + " this machine has available"));
      case Admission::Wait:
        if (!waited)
          common::set_work_step("waiting for memory: " + what + " needs about " + gib(bytes) + ", and " + std::to_string(ledger.others_growing()) +
                                " other preparation(s) running on this machine will take " + gib(ledger.others_growth()) + " more of the " + gib(available) + " available");
        waited = true;
        std::this_thread::sleep_for(std::chrono::milliseconds(500));
    }
  }
}

PreparationMemory::PreparationMemory() {
  ProcessLedger& process = process_ledger();
  const std::lock_guard<std::mutex> lock(process.mutex);
  ++process.preparations;
}

PreparationMemory::~PreparationMemory() {
  ProcessLedger& process = process_ledger();
  const std::lock_guard<std::mutex> lock(process.mutex);
  if (--process.preparations == 0 && process.ledger) process.ledger->withdraw();
}

}  // namespace isosid::prep

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
#include <map>
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

/// The process's place in the machine's memory ledger, and its preparations: one per thread
/// that runs one (Python's isosid.prepare may run several at once), each with its stage's
/// estimate, so that the process's record covers them all and each check counts the others.
struct ProcessLedger {
  struct Preparation {
    double stage_bytes = 0;  ///< the estimate of its stage under way (0: none checked yet)
    bool waiting = false;
  };
  std::mutex mutex;
  std::optional<MemoryLedger> ledger;  ///< in ledger_folder() as it was at the last check
  std::map<long, Preparation> preparations;  ///< by PreparationMemory's number; 0: a check outside any
  long next_number = 1;
  double reserved = 0;  ///< the process's record: the most any of its checks since its preparations began reserved

  MemoryLedger& current() {
    const std::string folder = ledger_folder();
    if (!ledger || ledger->folder() != folder) {
      ledger.emplace(folder);  // the old one's file withdrawn
      if (!ledger->usable())
        std::fprintf(stderr, "isosid-prep: the memory ledger %s cannot be used (%s): preparations running at once on this machine do not see each other's memory\n",
                     folder.c_str(), ledger->problem().c_str());
    }
    return *ledger;
  }
  /// The estimates of this process's other preparations that go on (not waiting).
  double siblings_bytes(long self) const {
    double bytes = 0;
    for (const auto& [number, p] : preparations)
      if (number != self && !p.waiting) bytes += p.stage_bytes;
    return bytes;
  }
  bool all_waiting() const {
    return std::all_of(preparations.begin(), preparations.end(), [](const auto& p) { return p.second.waiting; });
  }
};

/// Never destroyed: a thread may still be in a check when the process exits (a stale file is
/// removed by the next reader).
ProcessLedger& process_ledger() {
  static ProcessLedger* const the = new ProcessLedger;
  return *the;
}

/// The PreparationMemory this thread is in (0: none), and how deeply.
thread_local long t_preparation = 0;
thread_local int t_depth = 0;

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
  const std::string step = common::work_step();
  bool waited = false;
  for (;;) {
    const double available = available_bytes();
    if (available <= 0) return;  // not known here: nothing to check against
    Admission decision = Admission::Start;
    Growers others;
    {
      const std::lock_guard<std::mutex> one_check(process.mutex);
      ProcessLedger::Preparation& me = process.preparations[t_preparation];
      process.current().update([&](const std::vector<LedgerEntry>& entries, double resident) {
        // this process's other preparations count as one more process that holds none of theirs yet
        const double siblings = process.siblings_bytes(t_preparation);
        std::vector<LedgerEntry> all = entries;
        if (siblings > 0) all.push_back({siblings, 0, false});
        decision = admission(bytes, available, all);
        others = growers(all);
        me.waiting = decision != Admission::Start;
        if (decision == Admission::Start) {
          me.stage_bytes = bytes;
          // never less than before within the preparations: an outer stage's estimate (a MacNeal
          // basis allocated after the factorization checked within it) stays reserved
          process.reserved = std::max(process.reserved, resident + siblings + bytes);
        }
        return process.all_waiting() ? LedgerRecord{resident, true} : LedgerRecord{process.reserved, false};
      });
    }
    switch (decision) {
      case Admission::Start:
        if (waited) common::set_work_step(step);
        return;
      case Admission::Refuse:
        throw MemoryRefusal(field, what + " needs about " + gib(bytes) + ", more than the " +
                                       (others.count > 0 ? gib(available + others.resident) + " this machine would have available once the " +
                                                              std::to_string(others.count) + " other preparation(s) running on it end"
                                                        : gib(available) + " this machine has available"));
      case Admission::Wait:
        if (!waited)
          common::set_work_step("waiting for memory: " + what + " needs about " + gib(bytes) + ", and " + std::to_string(others.count) +
                                " other preparation(s) running on this machine will take " + gib(others.growth) + " more of the " + gib(available) + " available");
        waited = true;
        std::this_thread::sleep_for(std::chrono::milliseconds(500));  // the lock released: the others go on
    }
  }
}

PreparationMemory::PreparationMemory() {
  if (t_depth++ > 0) return;  // nested: the outer one's
  ProcessLedger& process = process_ledger();
  const std::lock_guard<std::mutex> lock(process.mutex);
  t_preparation = process.next_number++;
  process.preparations[t_preparation] = {};
}

PreparationMemory::~PreparationMemory() {
  if (--t_depth > 0) return;
  ProcessLedger& process = process_ledger();
  const std::lock_guard<std::mutex> lock(process.mutex);
  process.preparations.erase(t_preparation);
  t_preparation = 0;
  const bool others = std::any_of(process.preparations.begin(), process.preparations.end(), [](const auto& p) { return p.first != 0; });
  if (!others) {  // the last (with the checks made outside any)
    process.preparations.clear();
    process.reserved = 0;
    if (process.ledger) process.ledger->withdraw();
  }
}

}  // namespace isosid::prep

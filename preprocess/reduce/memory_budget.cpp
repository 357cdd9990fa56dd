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
/// that runs one (Python's isosid.prepare may run several at once), each with what it will
/// hold at most, so that the process's record covers them all and each check counts the others.
struct ProcessLedger {
  struct Preparation {
    /// the process's memory this preparation will reach at most: the largest of its checks'
    /// resident memory plus their estimates (an outer stage's stays while one within it runs)
    double reserved = 0;
    bool waiting = false;
  };
  std::mutex mutex;
  std::optional<MemoryLedger> ledger;        ///< in ledger_folder() as it was at the last check
  std::map<long, Preparation> preparations;  ///< by PreparationMemory's number; 0: a check outside any, dropped after it
  long next_number = 1;
  double base = 0;  ///< the process's resident memory when the first of its open preparations began

  MemoryLedger& current() {
    const std::string folder = ledger_folder();
    if (!ledger || ledger->folder() != folder) {
      ledger.emplace(folder);  // the old one's file withdrawn
      if (!ledger->usable())
        std::fprintf(stderr, "isosid-prep: the memory ledger %s cannot be used (%s): this process's preparations do not see other processes' memory\n",
                     folder.c_str(), ledger->problem().c_str());
    }
    return *ledger;
  }
  /// What the preparations but `except` will still take above the memory held now, whether
  /// there are any, and whether every one of them waits.
  struct Coming {
    double bytes = 0;
    bool any = false, all_waiting = true;
  };
  Coming coming(double resident, long except) const {
    Coming c;
    for (const auto& [number, p] : preparations) {
      if (number == except) continue;
      c.any = true;
      c.bytes += std::max(0.0, p.reserved - resident);
      c.all_waiting = c.all_waiting && p.waiting;
    }
    return c;
  }
  /// The process's other preparations as one more entry: what they will still take and what
  /// they hold (the memory above the base).
  std::optional<LedgerEntry> siblings(long self, double resident) const {
    const Coming c = coming(resident, self);
    const double held = std::max(0.0, resident - base);
    return c.any ? std::optional<LedgerEntry>(LedgerEntry{held + c.bytes, held, c.all_waiting}) : std::nullopt;
  }
  /// The process's record: the memory held now plus what each preparation will still take;
  /// waiting when every one waits.
  LedgerRecord record(double resident) const {
    const Coming c = coming(resident, -1);  // numbers are never negative: every preparation
    return {resident + c.bytes, c.any && c.all_waiting};
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
      MemoryLedger& ledger = process.current();
      ledger.update([&](const std::vector<LedgerEntry>& entries, double resident) {
        std::vector<LedgerEntry> all = entries;
        if (const auto siblings = process.siblings(t_preparation, resident)) all.push_back(*siblings);
        decision = admission(bytes, available, all);
        others = growers(all);
        me.waiting = decision != Admission::Start;
        if (decision == Admission::Start) me.reserved = std::max(me.reserved, resident + bytes);
        return process.record(resident);
      });
      if (t_preparation == 0 && decision != Admission::Wait) {  // a check outside any preparation reserves nothing after it
        process.preparations.erase(0);
        if (process.preparations.empty()) ledger.withdraw();
      }
    }
    switch (decision) {
      case Admission::Start:
        if (waited) common::set_work_step(step);
        return;
      case Admission::Refuse:
        throw MemoryRefusal(field, what + " needs about " + gib(bytes) + ", more than the " +
                                       (others.count > 0 ? gib(available + others.resident) + " this machine would have available once the " +
                                                              std::to_string(others.count) + " other preparation(s) running on it end"
                                                        : gib(available) + " this machine has available") +
                                       (others.promised > 0 ? " (" + gib(others.promised) + " more of it promised to preparations that wait or are stopped)" : ""));
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
  if (std::none_of(process.preparations.begin(), process.preparations.end(), [](const auto& p) { return p.first != 0; }))
    process.base = own_resident_bytes();
  t_preparation = process.next_number++;
  process.preparations[t_preparation] = {};
}

PreparationMemory::~PreparationMemory() {
  if (--t_depth > 0) return;
  ProcessLedger& process = process_ledger();
  const std::lock_guard<std::mutex> lock(process.mutex);
  process.preparations.erase(t_preparation);
  t_preparation = 0;
  if (!process.ledger) return;
  if (process.preparations.empty())
    process.ledger->withdraw();
  else  // the others' record, without this one's reservation
    process.ledger->update([&](const std::vector<LedgerEntry>&, double resident) { return process.record(resident); });
}

}  // namespace isosid::prep

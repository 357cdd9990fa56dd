// Memory limit of a preparation; see memory_budget.hpp.
#include "reduce/memory_budget.hpp"

#include "isosid/common/heap_reuse.hpp"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <fstream>
#include <sys/resource.h>

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
  const double limit = memory_limit();
  if (limit > 0 && bytes > limit)
    throw MemoryRefusal(field, what + " needs about " + gib(bytes) + ", more than the " + gib(limit) +
                        (g_limit.load() > 0 ? " of --memory-limit" : " this machine has available"));
}

}  // namespace isosid::prep

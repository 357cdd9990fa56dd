// What a preparation may hold in memory at once. The large stages (a sparse factorization, a
// reduction's dense blocks) estimate their peak before they start and are refused above the
// limit, with the estimate, instead of being killed by the kernel part way.
#pragma once
#include <stdexcept>
#include <string>
#include <utility>

namespace isosid::prep {

/// A stage's estimate exceeds the memory limit; the message names the stage, its estimate and
/// the limit, `field` the model file's part that sets the size (the pipeline turns it into an
/// input error naming the model file).
class MemoryRefusal : public std::runtime_error {
public:
  MemoryRefusal(std::string field, const std::string& message) : std::runtime_error(message), field_(std::move(field)) {}
  const std::string& field() const { return field_; }

private:
  std::string field_;
};

/// Sets the limit in bytes for this process; 0: the machine's (the default).
void set_memory_limit(double bytes);
/// The limit in bytes: set_memory_limit's, else the memory available now (MemAvailable of
/// /proc/meminfo, or a lower RLIMIT_AS or RLIMIT_DATA).
double memory_limit();
/// Throws MemoryRefusal if `bytes`, the estimated peak of `what`, exceed the limit; `field`:
/// the model file's part that sets its size. Against the machine's memory (no limit set), the
/// other preparations running on the machine count with what they are about to take: a stage
/// that fits once they end waits for them (the step says so), one that does not is refused.
void check_memory(const std::string& field, const std::string& what, double bytes);

/// One preparation's span in this process: when the outermost ends, what its stages reserved
/// in the machine's memory ledger is withdrawn, so that the other preparations stop counting
/// it while the process lives on (Python's isosid.prepare).
class PreparationMemory {
public:
  PreparationMemory();
  ~PreparationMemory();
  PreparationMemory(const PreparationMemory&) = delete;
  PreparationMemory& operator=(const PreparationMemory&) = delete;
};

}  // namespace isosid::prep

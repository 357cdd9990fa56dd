// The memory of one machine shared by the preparations running on it at once: a study's ranks,
// the adaptive loop's builds side by side. Each preparation checks a large stage's estimate
// against the memory available (memory_budget), which shows what the others hold but not what
// they are about to take: two stages that each fit alone could start together, and the kernel
// would kill one part way. The ledger, a folder with one file per preparation that says how
// much it will hold at its current stage's peak, lets a check count the others' coming growth,
// and wait for them where its stage fits once they end.
#pragma once
#include <string>
#include <vector>

namespace isosid::prep {

/// Another preparation, as the ledger and /proc show it.
struct LedgerEntry {
  double reserved = 0;   ///< bytes it will hold at its stage's peak (its resident memory at its check plus the stage's estimate)
  double resident = 0;   ///< bytes it holds now
  bool waiting = false;  ///< waiting for memory itself: it will not grow until it starts
};

enum class Admission {
  Start,   ///< the stage fits beside the others' coming growth
  Wait,    ///< it fits once the growing ones end and return what they hold
  Refuse,  ///< it does not fit even then
};

/// Whether a stage needing `bytes` more may start with `available` bytes free on the machine
/// beside `others`. Preparations that wait neither grow nor end soon, so they are neither
/// counted nor waited for: two preparations never wait for each other.
Admission admission(double bytes, double available, const std::vector<LedgerEntry>& others);

/// The ledger's folder: $ISOSID_MEMORY_LEDGER, else /dev/shm/isosid-memory-<uid> (memory of
/// this machine: each node of a cluster has its own).
std::string ledger_folder();

/// This process's place in a ledger. Its file is named by the pid and records the process's
/// start time, so that a file left by a process that ended (also by a crash or a kill) or of a
/// pid since reused is recognised as stale and removed.
class MemoryLedger {
public:
  explicit MemoryLedger(std::string folder);
  ~MemoryLedger() { withdraw(); }
  MemoryLedger(const MemoryLedger&) = delete;
  MemoryLedger& operator=(const MemoryLedger&) = delete;

  /// Under the ledger's lock: reads the other live preparations, decides by admission(), and
  /// records this one's file (Start: its resident memory plus `bytes`; Wait or Refuse: its
  /// resident memory, waiting). Without a usable folder there are no others.
  Admission request(double bytes, double available);
  const std::string& folder() const { return folder_; }
  /// Removes this process's file: it reserves nothing until its next request.
  void withdraw();
  /// The others growing (not waiting) at the last request, their coming growth and what they
  /// hold, in bytes.
  int others_growing() const { return others_growing_; }
  double others_growth() const { return others_growth_; }
  double others_resident() const { return others_resident_; }

private:
  std::string folder_;
  bool usable_ = false;
  int others_growing_ = 0;
  double others_growth_ = 0;
  double others_resident_ = 0;
};

}  // namespace isosid::prep

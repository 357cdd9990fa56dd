// The memory of one machine shared by the preparations running on it at once: a study's ranks,
// the adaptive loop's builds side by side. Each preparation checks a large stage's estimate
// against the memory available (memory_budget), which shows what the others hold but not what
// they are about to take: two stages that each fit alone could start together, and the kernel
// would kill one part way. The ledger, a folder with one file per process that says how much
// it will hold at most in its current stages, lets a check count the others' coming growth,
// and wait for them where its stage fits once they end. (The preparations one process runs
// on threads of its own are counted together by memory_budget.)
#pragma once
#include <functional>
#include <string>
#include <vector>

namespace isosid::prep {

/// Another process's entry, as the ledger and /proc show it.
struct LedgerEntry {
  double reserved = 0;   ///< bytes it will hold at most in its current stages (its resident memory at a check plus the estimates)
  double resident = 0;   ///< bytes it holds now
  bool waiting = false;  ///< waiting for memory itself, or stopped (a signal, a debugger): it will not grow until it goes on
};

/// What a process records of itself.
struct LedgerRecord {
  double reserved = 0;
  bool waiting = false;
};

/// The entries that grow (not waiting): how many, their coming growth (reserved less resident)
/// and what they hold, in bytes; and the coming growth of those that wait or are stopped, which
/// they will take when they go on.
struct Growers {
  int count = 0;
  double growth = 0, resident = 0;
  double promised = 0;
};
Growers growers(const std::vector<LedgerEntry>& others);

enum class Admission {
  Start,   ///< the stage fits beside the others' coming growth
  Wait,    ///< it fits once the growing ones end and return what they hold
  Refuse,  ///< it does not fit even then
};

/// Whether a stage needing `bytes` more may start with `available` bytes free on the machine
/// beside `others`: beside everyone's coming growth. Preparations that wait (or are stopped)
/// do not end soon, so they are not waited for: two preparations never wait for each other.
Admission admission(double bytes, double available, const std::vector<LedgerEntry>& others);

/// The ledger's folder: $ISOSID_MEMORY_LEDGER (made absolute), else
/// /dev/shm/isosid-memory-<uid> (memory of this machine: each node of a cluster has its own),
/// or the temporary folder where there is no /dev/shm.
std::string ledger_folder();

/// This process's resident memory in bytes (/proc/self/statm), 0 if it cannot be read.
double own_resident_bytes();

/// This process's place in a ledger: a file `pid-<pid>` that records the process's start time,
/// so that a file left by a process that ended (also by a crash or a kill) or of a pid since
/// reused is recognised as stale and removed, and its record. The folder must be this user's
/// own, not a link, and is kept to mode 0700; files of other names are never touched.
class MemoryLedger {
public:
  explicit MemoryLedger(std::string folder);
  ~MemoryLedger() { withdraw(); }
  MemoryLedger(const MemoryLedger&) = delete;
  MemoryLedger& operator=(const MemoryLedger&) = delete;

  /// Under the ledger's lock: reads the other live processes' entries, lets `decide` choose
  /// this process's record from them and its own resident memory, and writes it (atomically:
  /// a reader never sees it half written). Without a usable folder or its lock, `decide` sees
  /// no others and nothing is written.
  using Decide = std::function<LedgerRecord(const std::vector<LedgerEntry>& others, double resident)>;
  void update(const Decide& decide);
  /// One preparation in this process: decides by admission() and records its resident memory
  /// plus `bytes` on Start, else its resident memory, waiting. `others` receives the growers.
  Admission request(double bytes, double available, Growers* others = nullptr);
  /// Removes this process's file: it reserves nothing until its next update.
  void withdraw();

  const std::string& folder() const { return folder_; }
  bool usable() const { return problem_.empty(); }
  /// Why the folder cannot be used (empty: it can).
  const std::string& problem() const { return problem_; }

private:
  std::string folder_, problem_;
};

}  // namespace isosid::prep

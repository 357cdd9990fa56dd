// isosid-prep run as a subprocess: the runtime links no preprocessing code, but builds SIDs
// on demand (stale SIDs of a scene, the contact-sized rebuild, refined models at an impact).
#pragma once
#include <string>
#include <sys/types.h>
#include <vector>

namespace isosid::run {

/// isosid-prep: $ISOSID_PREP, else beside this program (install) or in the build tree, else PATH.
std::string find_prep();

/// A started isosid-prep: its process and the pipe that carries its output. Dropped before
/// finish_prep (an exception on the way), it stops the process and waits for it.
struct PrepProcess {
  pid_t pid = -1;
  int output = -1;
  std::string model;
  std::string sid;  ///< the file it writes
  bool quiet = true;
  std::string pending;  ///< its output read, not yet passed on (read ahead while another build was waited for)

  PrepProcess(pid_t pid, int output, std::string model, std::string sid, bool quiet);
  PrepProcess(PrepProcess&& other) noexcept;
  PrepProcess& operator=(PrepProcess&&) = delete;
  PrepProcess(const PrepProcess&) = delete;
  ~PrepProcess();
};

/// The cores this process may run on (its CPU affinity), at least 1.
int usable_cores();

/// Starts isosid-prep on `model`, writing `sid` (none: empty), with further options `extra` (e.g. --coarse);
/// `threads` > 0 limits its OpenMP assembly and its BLAS to that many threads (for builds side
/// by side), unless the user set OMP_NUM_THREADS or OPENBLAS_NUM_THREADS.
PrepProcess start_prep(const std::string& model, const std::string& sid, const std::vector<std::string>& extra, bool quiet,
                       const std::string& what, int threads = 0);

/// Waits for a started isosid-prep. Its progress lines pass through to stderr; its one-line
/// error is held back and becomes this program's: InputError for a refused model (its exit 2),
/// ComputationError for any other failure. A SID it built gets its digest recorded (sid_digest).
/// The builds `beside` it have their output read meanwhile and kept (PrepProcess::pending): one
/// blocked on a full pipe could hold memory this build waits for (preprocess's memory ledger).
void finish_prep(PrepProcess& process, const std::vector<PrepProcess*>& beside = {});

/// start_prep, then finish_prep (`what` says why it runs, in the progress line).
void run_prep(const std::string& model, const std::string& sid, const std::vector<std::string>& extra, bool quiet,
              const std::string& what);

/// isosid-prep --check on `model`: returns if it reads as a valid model, else throws its
/// InputError (or a ComputationError when isosid-prep cannot run).
void check_model(const std::string& model);

}  // namespace isosid::run

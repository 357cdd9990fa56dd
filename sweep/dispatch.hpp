// Running a study's cases on the ranks of an MPI job (mpirun -np N isosid-sweep ...), or in one
// process without mpirun. Rank 0 hands the cases out one at a time as ranks ask for work
// (dynamic balancing: cases differ in cost) from a thread of its own, and runs cases itself;
// each rank writes its cases' results and rows (a shared file system), rank 0 the table.
#pragma once
#include "study_file.hpp"

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace isosid::sweep {

/// This process's place in the job. MPI is started only under a launcher (mpirun sets
/// OMPI_COMM_WORLD_SIZE, Slurm's srun PMI_SIZE): a plain start is rank 0 of 1.
class Ranks {
public:
  Ranks(int& argc, char**& argv);
  ~Ranks();
  Ranks(const Ranks&) = delete;
  Ranks& operator=(const Ranks&) = delete;
  int rank() const { return rank_; }
  int size() const { return size_; }
  /// Ends the whole job (every rank) with `status` after a failure on one rank.
  [[noreturn]] void abort(int status) const;

private:
  int rank_ = 0, size_ = 1;
  bool mpi_ = false;
};

/// The threads each rank's isosid-prep may use for its assembly and BLAS when the ranks on
/// one node build SIDs side by side: the node's cores shared among its ranks, at most the
/// cores a rank may run on (its binding), at least one.
int prep_threads_per_rank(int usable_cores, int node_cores, int ranks_on_node);

struct CaseWork {
  const Study& study;
  const std::vector<Case>& cases;
  std::string dir;                       ///< the study's results folder
  std::vector<std::string> collect;
  std::function<bool()> stop_requested;  ///< a signal: the running cases stop, no new case starts
};

/// What handing out the cases cost rank 0 (counted on rank 0 under mpirun): the dispatcher
/// thread's CPU time per request (receiving a report, parsing its row, answering), against
/// which the cases' own time sets how many ranks one dispatcher serves; its wall time per
/// request (more where the thread waits for a core); and the time a rank waited for the answer
/// after each case, as the ranks measured it (it includes the thread's polling; the answer to a
/// rank's first request waits for rank 0's check of every case and is not counted).
struct DispatchCost {
  long requests = 0;   ///< reports answered
  double cpu_s = 0;    ///< the thread's CPU time from a report's arrival to its answer, summed
  double busy_s = 0;   ///< the same in wall time
  double busiest_s = 0;  ///< the longest of those
  long waits = 0;      ///< answers whose wait a rank reported
  double waited_s = 0;  ///< the ranks' time from sending a report to its answer, summed
  double longest_wait_s = 0;
};

/// Runs the cases numbered in `todo` (rank 0's list; the other ranks' is ignored) over all
/// ranks. On rank 0, `on_row` receives every case's row: its own as each ends, the other ranks'
/// (sent with their next request) between its cases and after its last; it returns once every
/// rank has stopped. A rank a signal reached stops taking cases, and a case it interrupted goes
/// back to the queue. Returns, on rank 0, what the dispatching cost (no requests in one
/// process); the other ranks count nothing and return zeros.
DispatchCost run_cases(const Ranks& ranks, const CaseWork& work, const std::vector<int>& todo, const std::function<void(const nlohmann::json&)>& on_row);

}  // namespace isosid::sweep

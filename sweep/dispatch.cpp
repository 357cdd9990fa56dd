// The cases over the ranks; see dispatch.hpp.
#include "dispatch.hpp"

#include "case_run.hpp"
#include "study_table.hpp"

#include <mpi.h>

#include <chrono>
#include <cstdlib>
#include <deque>
#include <thread>

namespace isosid::sweep {
namespace {

constexpr int kRequest = 1;  ///< rank -> 0: the case it finished (or -1), asking for the next
constexpr int kAssign = 2;   ///< 0 -> rank: the next case, or -1: stop

/// Rank 0's side: the queue of cases and the requests of the other ranks.
class Dispatcher {
public:
  Dispatcher(const Ranks& ranks, const CaseWork& work, const std::vector<int>& todo, const std::function<void(const nlohmann::json&)>& on_row)
      : work_(work), queue_(todo.begin(), todo.end()), on_row_(on_row), running_(ranks.size() - 1) {}

  /// The next case for rank 0 itself, or -1.
  int next() {
    if (work_.stop_requested() || queue_.empty()) return -1;
    const int c = queue_.front();
    queue_.pop_front();
    return c;
  }

  /// Answers the requests that have arrived (at most every millisecond, from the steps of rank
  /// 0's own runs: a probe costs microseconds, a step of a small run about as much).
  void serve() {
    const auto now = std::chrono::steady_clock::now();
    if (now - last_serve_ < std::chrono::milliseconds(1)) return;
    last_serve_ = now;
    for (;;) {
      int waiting = 0;
      MPI_Status status;
      MPI_Iprobe(MPI_ANY_SOURCE, kRequest, MPI_COMM_WORLD, &waiting, &status);
      if (!waiting) return;
      int finished = -1;
      MPI_Recv(&finished, 1, MPI_INT, status.MPI_SOURCE, kRequest, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      if (finished >= 0)
        if (const auto row = read_row(work_.dir, finished)) on_row_(*row);
      int assigned = next();
      if (assigned < 0) --running_;
      MPI_Send(&assigned, 1, MPI_INT, status.MPI_SOURCE, kAssign, MPI_COMM_WORLD);
    }
  }

  /// After rank 0's last case: answers until every other rank has been told to stop (without
  /// spinning a core: the others are computing).
  void drain() {
    while (running_ > 0) {
      last_serve_ = {};
      serve();
      if (running_ > 0) std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
  }

private:
  const CaseWork& work_;
  std::deque<int> queue_;
  const std::function<void(const nlohmann::json&)>& on_row_;
  int running_;  ///< other ranks not yet told to stop
  std::chrono::steady_clock::time_point last_serve_{};
};

/// Runs case `index` on this rank; its row is written unless a signal interrupted it.
bool run_one(const CaseWork& work, int index, const std::function<bool()>& at_step) {
  const Case& c = work.cases[std::size_t(index)];
  const nlohmann::json row = run_case(work.study, c, case_folder(work.dir, index), work.collect, at_step);
  if (row["status"] == "interrupted") return false;
  write_row(work.dir, row);
  return true;
}

}  // namespace

Ranks::Ranks(int& argc, char**& argv) {
  if (!std::getenv("OMPI_COMM_WORLD_SIZE") && !std::getenv("PMI_SIZE")) return;
  MPI_Init(&argc, &argv);
  mpi_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

Ranks::~Ranks() {
  if (mpi_) MPI_Finalize();
}

void Ranks::abort(int status) const {
  if (mpi_) MPI_Abort(MPI_COMM_WORLD, status);
  std::exit(status);
}

void run_cases(const Ranks& ranks, const CaseWork& work, const std::vector<int>& todo, const std::function<void(const nlohmann::json&)>& on_row) {
  if (ranks.rank() == 0) {
    Dispatcher dispatcher(ranks, work, todo, on_row);
    const bool others = ranks.size() > 1;
    const std::function<bool()> at_step = [&] {
      if (others) dispatcher.serve();
      return work.stop_requested();
    };
    for (int c = dispatcher.next(); c >= 0; c = dispatcher.next())
      if (run_one(work, c, at_step)) on_row(*read_row(work.dir, c));
    if (others) dispatcher.drain();
    return;
  }
  int finished = -1;
  for (;;) {
    MPI_Send(&finished, 1, MPI_INT, 0, kRequest, MPI_COMM_WORLD);
    int assigned = -1;
    MPI_Recv(&assigned, 1, MPI_INT, 0, kAssign, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (assigned < 0) return;
    finished = run_one(work, assigned, work.stop_requested) ? assigned : -1;
  }
}

}  // namespace isosid::sweep

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

constexpr int kReport = 1;  ///< rank -> 0: a JSON report (below), asking for the next case
constexpr int kAssign = 2;  ///< 0 -> rank: the next case, or -1: stop

/// What a rank reports with each request: "case" it ran (-1: none yet), "outcome" ("row": its
/// row follows under "row"; "interrupted": hand it out again), and "stopping" (a signal reached
/// this rank: send it no more cases).
nlohmann::json report(int index, const nlohmann::json& row, bool stopping) {
  if (index < 0) return {{"case", -1}, {"outcome", "none"}, {"stopping", stopping}};
  if (row["status"] == "interrupted") return {{"case", index}, {"outcome", "interrupted"}, {"stopping", stopping}};
  return {{"case", index}, {"outcome", "row"}, {"row", row}, {"stopping", stopping}};
}

/// Rank 0's side: the queue of cases, the other ranks' reports, and their rows, handed to the
/// caller between rank 0's own cases (never from inside a step, where an error would leave a
/// rank waiting for its answer).
class Dispatcher {
public:
  Dispatcher(const Ranks& ranks, const CaseWork& work, const std::vector<int>& todo)
      : work_(work), queue_(todo.begin(), todo.end()), running_(ranks.size() - 1) {}

  /// The next case for rank 0 itself, or -1.
  int next() {
    if (work_.stop_requested() || queue_.empty()) return -1;
    const int c = queue_.front();
    queue_.pop_front();
    return c;
  }
  void put_back(int index) { queue_.push_front(index); }

  /// Answers the reports that have arrived, at most every millisecond (called at rank 0's
  /// steps: a probe costs microseconds, a step of a small run about as much).
  void serve() {
    const auto now = std::chrono::steady_clock::now();
    if (now - last_serve_ < std::chrono::milliseconds(1)) return;
    last_serve_ = now;
    for (;;) {
      int waiting = 0;
      MPI_Status status;
      MPI_Iprobe(MPI_ANY_SOURCE, kReport, MPI_COMM_WORLD, &waiting, &status);
      if (!waiting) return;
      int size = 0;
      MPI_Get_count(&status, MPI_CHAR, &size);
      std::string text(std::size_t(size), '\0');
      MPI_Recv(text.data(), size, MPI_CHAR, status.MPI_SOURCE, kReport, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      const nlohmann::json r = nlohmann::json::parse(text);
      if (r["outcome"] == "row") rows_.push_back(r["row"]);
      if (r["outcome"] == "interrupted") put_back(r["case"].get<int>());
      const int assigned = r["stopping"].get<bool>() ? -1 : next();
      if (assigned < 0) --running_;
      MPI_Send(&assigned, 1, MPI_INT, status.MPI_SOURCE, kAssign, MPI_COMM_WORLD);
    }
  }

  /// The rows the other ranks reported since the last call.
  std::vector<nlohmann::json> take_rows() { return std::exchange(rows_, {}); }

  /// After rank 0's last case: answers until every other rank has been told to stop (without
  /// spinning a core: the others are computing), handing their rows on as they come.
  void drain(const std::function<void(const nlohmann::json&)>& on_row) {
    while (running_ > 0) {
      last_serve_ = {};
      serve();
      for (const nlohmann::json& row : take_rows()) on_row(row);
      if (running_ > 0) std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
  }

private:
  const CaseWork& work_;
  std::deque<int> queue_;
  std::vector<nlohmann::json> rows_;
  int running_;  ///< other ranks not yet told to stop
  std::chrono::steady_clock::time_point last_serve_{};
};

/// Runs case `index` on this rank and writes its row, unless a signal interrupted it.
nlohmann::json run_one(const CaseWork& work, int index, const std::function<bool()>& at_step) {
  const Case& c = work.cases[std::size_t(index)];
  nlohmann::json row = run_case(work.study, c, case_folder(work.dir, index), work.collect, at_step);
  if (row["status"] != "interrupted") write_row(work.dir, row);
  return row;
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
    Dispatcher dispatcher(ranks, work, todo);
    const bool others = ranks.size() > 1;
    const std::function<bool()> at_step = [&] {
      if (others) dispatcher.serve();
      return work.stop_requested();
    };
    for (int c = dispatcher.next(); c >= 0; c = dispatcher.next()) {
      const nlohmann::json row = run_one(work, c, at_step);
      if (row["status"] != "interrupted") on_row(row);
      for (const nlohmann::json& r : dispatcher.take_rows()) on_row(r);
    }
    if (others) dispatcher.drain(on_row);
    return;
  }
  int ran = -1;
  nlohmann::json row;
  for (;;) {
    const std::string text = report(ran, row, work.stop_requested()).dump();
    MPI_Send(text.data(), int(text.size()), MPI_CHAR, 0, kReport, MPI_COMM_WORLD);
    int assigned = -1;
    MPI_Recv(&assigned, 1, MPI_INT, 0, kAssign, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (assigned < 0) return;
    row = run_one(work, assigned, work.stop_requested);
    ran = assigned;
  }
}

}  // namespace isosid::sweep

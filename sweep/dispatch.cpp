// The cases over the ranks; see dispatch.hpp.
#include "dispatch.hpp"

#include "case_run.hpp"
#include "study_table.hpp"
#include "scene/prep_process.hpp"

#include <mpi.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <mutex>
#include <thread>
#include <time.h>
#include <unistd.h>

namespace isosid::sweep {
namespace {

constexpr int kReport = 1;  ///< rank -> 0: a JSON report (below), asking for the next case
constexpr int kAssign = 2;  ///< 0 -> rank: the next case, or -1: stop

/// What a rank reports with each request: "case" it ran (-1: none yet), "outcome" ("row": its
/// row follows under "row"; "interrupted": hand it out again), "stopping" (a signal reached
/// this rank: send it no more cases), and "waited_s", how long it waited for the answer to its
/// previous report of a case (-1: none yet).
nlohmann::json report(int index, const nlohmann::json& row, bool stopping, double waited_s) {
  nlohmann::json r = {{"case", index}, {"outcome", "none"}, {"stopping", stopping}, {"waited_s", waited_s}};
  if (index < 0) return r;
  r["outcome"] = row["status"] == "interrupted" ? "interrupted" : "row";
  if (r["outcome"] == "row") r["row"] = row;
  return r;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// The calling thread's CPU time [s].
double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

/// Rank 0's side: the queue of cases and the other ranks' reports, answered by a thread of
/// its own (every millisecond, sleeping between), so that a rank never waits while rank 0 reads
/// a SID or writes results; their rows go to rank 0's main thread between its own cases.
class Dispatcher {
public:
  Dispatcher(const Ranks& ranks, const CaseWork& work, const std::vector<int>& todo)
      : work_(work), queue_(todo.begin(), todo.end()), running_(ranks.size() - 1) {
    if (running_ > 0) thread_ = std::thread([this] { answer(); });
  }
  ~Dispatcher() {  // after drain(), or on an error of rank 0 (the job is then aborted)
    quit_ = true;
    if (thread_.joinable()) thread_.join();
  }
  Dispatcher(const Dispatcher&) = delete;
  Dispatcher& operator=(const Dispatcher&) = delete;

  /// The next case for rank 0 itself, or -1.
  int next() {
    const std::lock_guard<std::mutex> lock(mutex_);
    return next_locked();
  }

  /// The rows the other ranks reported since the last call.
  std::vector<nlohmann::json> take_rows() {
    const std::lock_guard<std::mutex> lock(mutex_);
    return std::exchange(rows_, {});
  }

  /// After rank 0's last case: waits for the other ranks, handing their rows on as they come.
  void drain(const std::function<void(const nlohmann::json&)>& on_row) {
    for (;;) {
      for (const nlohmann::json& row : take_rows()) on_row(row);
      {
        const std::lock_guard<std::mutex> lock(mutex_);
        if (running_ == 0) break;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    if (thread_.joinable()) thread_.join();
    for (const nlohmann::json& row : take_rows()) on_row(row);
  }

  /// What answering cost so far (final after drain()).
  DispatchCost cost() {
    const std::lock_guard<std::mutex> lock(mutex_);
    return cost_;
  }

private:
  int next_locked() {
    if (work_.stop_requested() || queue_.empty()) return -1;
    const int c = queue_.front();
    queue_.pop_front();
    return c;
  }

  /// The thread: answers each report with the next case (or -1: stop) until every other rank
  /// has been told to stop. The only caller of MPI while it runs (MPI_THREAD_SERIALIZED).
  void answer() {
    while (!quit_) {
      int waiting = 0;
      MPI_Status status;
      MPI_Iprobe(MPI_ANY_SOURCE, kReport, MPI_COMM_WORLD, &waiting, &status);
      if (!waiting) {
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
        continue;
      }
      const auto arrived = std::chrono::steady_clock::now();
      const double cpu_at_arrival = thread_cpu_seconds();
      int size = 0;
      MPI_Get_count(&status, MPI_CHAR, &size);
      std::string text(std::size_t(size), '\0');
      MPI_Recv(text.data(), size, MPI_CHAR, status.MPI_SOURCE, kReport, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      const nlohmann::json r = nlohmann::json::parse(text);
      int assigned = -1;
      bool done = false;
      {
        const std::lock_guard<std::mutex> lock(mutex_);
        if (r["outcome"] == "row") rows_.push_back(r["row"]);
        if (r["outcome"] == "interrupted") queue_.push_front(r["case"].get<int>());
        assigned = r["stopping"].get<bool>() ? -1 : next_locked();
        if (assigned < 0) --running_;
        done = running_ == 0;
      }
      MPI_Send(&assigned, 1, MPI_INT, status.MPI_SOURCE, kAssign, MPI_COMM_WORLD);
      const double busy = seconds_since(arrived), cpu = thread_cpu_seconds() - cpu_at_arrival;
      {
        const std::lock_guard<std::mutex> lock(mutex_);
        ++cost_.requests;
        cost_.cpu_s += cpu;
        cost_.busy_s += busy;
        cost_.busiest_s = std::max(cost_.busiest_s, busy);
        if (const double waited = r["waited_s"].get<double>(); waited >= 0) {
          ++cost_.waits;
          cost_.waited_s += waited;
          cost_.longest_wait_s = std::max(cost_.longest_wait_s, waited);
        }
      }
      if (done) return;
    }
  }

  const CaseWork& work_;
  std::mutex mutex_;  ///< guards the queue, the rows, the count and the cost
  std::deque<int> queue_;
  std::vector<nlohmann::json> rows_;
  int running_;  ///< other ranks not yet told to stop
  DispatchCost cost_;
  std::atomic<bool> quit_{false};
  std::thread thread_;
};

/// Runs case `index` on this rank and writes its row, unless a signal interrupted it.
nlohmann::json run_one(const CaseWork& work, int index, const std::function<bool()>& at_step) {
  const Case& c = work.cases[std::size_t(index)];
  nlohmann::json row = run_case(work.study, c, work.dir, work.collect, at_step);
  if (row["status"] != "interrupted") write_row(work.dir, row);
  return row;
}

}  // namespace

Ranks::Ranks(int& argc, char**& argv) {
  if (!std::getenv("OMPI_COMM_WORLD_SIZE") && !std::getenv("PMI_SIZE")) return;
  int provided = 0;  // rank 0's dispatcher thread calls MPI while its main thread runs cases
  MPI_Init_thread(&argc, &argv, MPI_THREAD_SERIALIZED, &provided);
  mpi_ = true;
  if (provided < MPI_THREAD_SERIALIZED) {
    std::fprintf(stderr, "isosid-sweep: this MPI library cannot be called from a second thread (MPI_THREAD_SERIALIZED)\n");
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  // Ranks that build SIDs at once would each start isosid-prep's OpenMP assembly and BLAS on
  // every core they may use (mpirun binds two ranks to a core each, more to a socket each, or
  // none): the builds get the node's share, as the adaptive loop's side-by-side builds do,
  // through the environment the builds inherit, unless the user set it
  MPI_Comm node;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank_, MPI_INFO_NULL, &node);
  int on_node = 1;
  MPI_Comm_size(node, &on_node);
  MPI_Comm_free(&node);
  const std::string threads = std::to_string(prep_threads_per_rank(run::usable_cores(), int(sysconf(_SC_NPROCESSORS_ONLN)), on_node));
  setenv("OPENBLAS_NUM_THREADS", threads.c_str(), 0);
  setenv("OMP_NUM_THREADS", threads.c_str(), 0);
}

int prep_threads_per_rank(int usable_cores, int node_cores, int ranks_on_node) {
  return std::max(1, std::min(usable_cores, node_cores / std::max(1, ranks_on_node)));
}

Ranks::~Ranks() {
  if (mpi_) MPI_Finalize();
}

void Ranks::abort(int status) const {
  if (mpi_) MPI_Abort(MPI_COMM_WORLD, status);
  std::exit(status);
}

DispatchCost run_cases(const Ranks& ranks, const CaseWork& work, const std::vector<int>& todo, const std::function<void(const nlohmann::json&)>& on_row) {
  if (ranks.rank() == 0) {
    Dispatcher dispatcher(ranks, work, todo);
    const bool others = ranks.size() > 1;
    for (int c = dispatcher.next(); c >= 0; c = dispatcher.next()) {
      const nlohmann::json row = run_one(work, c, work.stop_requested);
      if (row["status"] != "interrupted") on_row(row);
      for (const nlohmann::json& r : dispatcher.take_rows()) on_row(r);
    }
    if (others) dispatcher.drain(on_row);
    return dispatcher.cost();
  }
  int ran = -1;
  nlohmann::json row;
  double waited = -1;
  for (;;) {
    const std::string text = report(ran, row, work.stop_requested(), waited).dump();
    const auto sent = std::chrono::steady_clock::now();
    MPI_Send(text.data(), int(text.size()), MPI_CHAR, 0, kReport, MPI_COMM_WORLD);
    int assigned = -1;
    MPI_Recv(&assigned, 1, MPI_INT, 0, kAssign, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    waited = ran >= 0 ? seconds_since(sent) : -1;  // the first answer waits for rank 0's check of every case: not dispatch
    if (assigned < 0) return {};
    row = run_one(work, assigned, work.stop_requested);
    ran = assigned;
  }
}

}  // namespace isosid::sweep

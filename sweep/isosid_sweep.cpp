// isosid-sweep: a study of many impacts, one base scene run for every case of its parameters,
// in-process through the library's pipeline, on the ranks of an MPI job or in one process,
// into one table (study.csv, study.h5). A stopped study resumes where it stopped.
#include "case_run.hpp"
#include "dispatch.hpp"
#include "isosid/common/cli_guard.hpp"
#include "isosid/common/cli_parse.hpp"
#include "isosid/common/file_lock.hpp"
#include "isosid/common/heap_reuse.hpp"
#include "isosid/common/progress_line.hpp"
#include "isosid/common/toml_override.hpp"
#include "isosid/format/error.hpp"
#include "study_table.hpp"

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>

namespace {
using namespace isosid;
namespace fs = std::filesystem;

volatile std::sig_atomic_t g_stop_signal = 0;
void request_stop(int signal) { g_stop_signal = signal; }

/// Set once every rank has read the study: a failure after it may leave other ranks waiting
/// for this one, so it ends the whole job.
bool g_study_read = false;

/// out/<study name> for study files named <name>.study.toml.
std::string default_output(const std::string& study_file) {
  const std::string name = fs::path(study_file).filename().string();
  return (fs::path("out") / name.substr(0, name.find('.'))).string();
}

/// Rank 0's record of the study: every case's row, the table rewritten as rows arrive (and at
/// the end), and the progress line. A rewrite is linear in the rows (about 3 s at 1e5), so it
/// waits at least 2 s and ten times the last one's time: rewriting takes at most a tenth of
/// rank 0's time at any study size. The record times itself, since with many ranks rank 0's
/// share of each case bounds how many ranks it can serve.
class StudyRecord {
public:
  StudyRecord(const sweep::Study& study, const std::vector<sweep::Case>& cases, std::string dir, std::vector<std::string> collect, bool quiet)
      : study_(study), total_(cases.size()), dir_(std::move(dir)), collect_(std::move(collect)), quiet_(quiet) {}
  void add(const nlohmann::json& row, bool run_now) {
    const auto start = std::chrono::steady_clock::now();
    const int index = row["case"].get<int>();
    if (const auto old = rows_.find(index); old != rows_.end()) --statuses_[old->second["status"].get<std::string>()];
    ++statuses_[row["status"].get<std::string>()];
    rows_[index] = row;
    dirty_ = true;
    if (run_now) {
      show_progress();
      ++rows_added_;
      adding_s_ += seconds_since(start);
      if (seconds_between(written_, start) > std::max(2.0, 10 * last_write_s_)) write();
    }
  }
  /// Writes the table if rows arrived since it was last written, and ends the progress line.
  void finish() {
    if (dirty_) write();
    line_.finish();
  }
  std::size_t rows() const { return rows_.size(); }
  std::size_t total() const { return total_; }
  int count(const std::string& status) const {
    const auto n = statuses_.find(status);
    return n == statuses_.end() ? 0 : n->second;
  }
  /// The first few cases without a row, as "3, 17, 20 ...".
  std::string missing() const {
    std::string out;
    int shown = 0;
    for (std::size_t i = 0; i < total_ && shown < 5; ++i)
      if (!rows_.count(int(i))) out += (shown++ ? ", " : "") + std::to_string(i);
    return out + (total_ - rows_.size() > 5 ? " ..." : "");
  }
  /// What recording the rows run now cost rank 0, as "0.05 ms per row, the table rewritten
  /// 3 times in 9.3 ms (the last: 40 rows in 4.1 ms)".
  std::string cost() const {
    char text[200];
    std::snprintf(text, sizeof text, "%.3g ms per row, the table rewritten %d time%s in %.3g ms (the last: %zu rows in %.3g ms)",
                  rows_added_ ? 1e3 * adding_s_ / double(rows_added_) : 0.0, writes_, writes_ == 1 ? "" : "s", 1e3 * writing_s_,
                  written_rows_, 1e3 * last_write_s_);
    return text;
  }

private:
  static double seconds_between(std::chrono::steady_clock::time_point from, std::chrono::steady_clock::time_point to) {
    return std::chrono::duration<double>(to - from).count();
  }
  static double seconds_since(std::chrono::steady_clock::time_point start) { return seconds_between(start, std::chrono::steady_clock::now()); }
  /// The progress after a row: on a terminal at most every 0.2 s, in a log every 10 s (as
  /// the other programs' steps), and the last row's always.
  void show_progress() {
    if (quiet_) return;
    const auto now = std::chrono::steady_clock::now();
    if (rows_.size() < total_ && now - shown_ < (line_.terminal() ? std::chrono::milliseconds(200) : std::chrono::milliseconds(10'000))) return;
    shown_ = now;
    const double elapsed = seconds_between(start_, now);
    const double fraction = double(rows_.size()) / double(total_);
    char text[160];
    std::snprintf(text, sizeof text, "%zu/%zu cases (%d failed, %d bad input)", rows_.size(), total_, count("failed"), count("bad input"));
    const std::string left = common::ProgressLine::time_left(fraction, elapsed);
    line_.show(left.empty() ? text : std::string(text) + ", " + left);
  }
  void write() {
    const auto start = std::chrono::steady_clock::now();
    std::vector<nlohmann::json> rows;
    for (const auto& [index, row] : rows_) rows.push_back(row);
    if (!rows.empty()) sweep::write_table(dir_, study_, collect_, rows);
    dirty_ = false;
    written_ = std::chrono::steady_clock::now();
    ++writes_;
    written_rows_ = rows.size();
    last_write_s_ = seconds_since(start);
    writing_s_ += last_write_s_;
  }
  const sweep::Study& study_;
  std::size_t total_;
  std::string dir_;
  std::vector<std::string> collect_;
  bool quiet_;
  std::map<int, nlohmann::json> rows_;
  std::map<std::string, int> statuses_;  ///< rows per status
  bool dirty_ = false;
  long rows_added_ = 0;  ///< rows of cases run now
  double adding_s_ = 0;  ///< their recording and progress, without the table's rewrites
  int writes_ = 0;       ///< the table's rewrites
  double writing_s_ = 0, last_write_s_ = 0;
  std::size_t written_rows_ = 0;  ///< the last rewrite's rows
  common::ProgressLine line_{"isosid-sweep"};
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now(), written_{}, shown_{};
};

/// A row found in the study folder, checked against the case the study file plans now: a
/// folder holds one study, and a row made with other values must not pass for this one's.
void check_row_matches(const nlohmann::json& row, const sweep::Case& c, const std::string& dir) {
  for (const common::TomlOverride& s : c.settings)
    if (row["settings"].value(s.key, std::string()) != s.value)
      throw format::InputError(dir, "cases", "case " + std::to_string(c.index) + " there was run with " + s.key + " = " +
                                                 row["settings"].value(s.key, std::string("(unset)")) + ", the study file now says " + s.value +
                                                 ": a study folder holds one study (give another -o)");
}

int run_study(const sweep::Ranks& ranks, const std::string& study_file, std::string out_dir, int only_case, bool quiet) {
  const sweep::Study study = sweep::read_study_file(study_file);
  const std::vector<sweep::Case> cases = sweep::plan_cases(study);
  const std::vector<std::string> collect = study.collect.empty() ? sweep::default_collect(study) : study.collect;
  if (out_dir.empty()) out_dir = default_output(study_file);
  if (only_case >= int(cases.size()))
    throw format::InputError("--case", "", std::to_string(only_case) + " is beyond the study's " + std::to_string(cases.size()) + " cases (from 0)");
  if (only_case >= 0 && ranks.size() > 1) throw format::InputError("--case", "", "runs one case in one process: not under mpirun");
  g_study_read = true;
  const sweep::CaseWork work{study, cases, out_dir, collect, [] { return g_stop_signal != 0; }};

  if (only_case >= 0) {  // one case of a job array: its folder and row, no table
    fs::create_directories(out_dir);
    const sweep::Case& c = cases[std::size_t(only_case)];
    if (const auto done = sweep::read_row(out_dir, only_case)) {
      check_row_matches(*done, c, out_dir);
      if (!quiet) std::fprintf(stderr, "isosid-sweep: case %d is done (its row.json); nothing to run\n", only_case);
      return 0;
    }
    const std::string problem = sweep::case_input_problem(study, c, out_dir);
    const nlohmann::json row = problem.empty() ? sweep::run_case(study, c, out_dir, collect, work.stop_requested)
                                               : sweep::refused_case(c, problem);
    if (row["status"] == "interrupted") return 128 + int(g_stop_signal);
    sweep::write_row(out_dir, row);
    if (!quiet) std::fprintf(stderr, "isosid-sweep: case %d %s%s\n", only_case, row["status"].get<std::string>().c_str(),
                             row["message"].get<std::string>().empty() ? "" : (": " + row["message"].get<std::string>()).c_str());
    return row["exit_class"].get<int>();
  }

  std::optional<common::FileLock> lock;  // the study folder's, against a second study into it (not this job's ranks)
  std::optional<StudyRecord> record;
  std::vector<int> todo;
  if (ranks.rank() == 0) {
    fs::create_directories(out_dir);
    lock.emplace((fs::path(out_dir) / ".isosid-sweep.lock").string(), common::FileLock::Mode::ExclusiveOrNone);
    if (!lock->held()) throw format::InputError(out_dir, "", "another isosid-sweep is running into this folder");
    record.emplace(study, cases, out_dir, collect, quiet);
    // every case checked before any runs: one refused is recorded as bad input, the rest go on
    for (const sweep::Case& c : cases) {
      if (const auto row = sweep::read_row(out_dir, c.index)) {
        check_row_matches(*row, c, out_dir);
        record->add(*row, false);  // done by an earlier start of the study: never run twice
        continue;
      }
      if (const std::string problem = sweep::case_input_problem(study, c, out_dir); !problem.empty()) {
        const nlohmann::json row = sweep::refused_case(c, problem);
        sweep::write_row(out_dir, row);
        record->add(row, false);
        continue;
      }
      todo.push_back(c.index);
    }
    if (!quiet)
      std::fprintf(stderr, "isosid-sweep: %zu cases, %zu to run on %d rank%s (%zu done before, %d refused)\n", cases.size(), todo.size(),
                   ranks.size(), ranks.size() > 1 ? "s" : "", record->rows() - std::size_t(record->count("bad input")), record->count("bad input"));
  }
  const sweep::DispatchCost dispatch = sweep::run_cases(ranks, work, todo, [&](const nlohmann::json& row) { record->add(row, true); });
  if (ranks.rank() != 0) return 0;
  record->finish();
  const std::string table = (fs::path(out_dir) / "study.csv").string();
  if (!quiet) {
    std::fprintf(stderr, "isosid-sweep: %zu of %zu cases recorded (%d completed, %d failed, %d bad input) -> %s\n", record->rows(), record->total(),
                 record->count("completed"), record->count("failed"), record->count("bad input"), table.c_str());
    std::fprintf(stderr, "isosid-sweep: rank 0's own cost: %s\n", record->cost().c_str());
    if (dispatch.requests > 0)
      std::fprintf(stderr,
                   "isosid-sweep: dispatch: %ld requests answered with %.3g ms CPU each, in %.3g ms (the longest %.3g ms); "
                   "a rank waited %.3g ms per answer (the longest %.3g ms)\n",
                   dispatch.requests, 1e3 * dispatch.cpu_s / double(dispatch.requests), 1e3 * dispatch.busy_s / double(dispatch.requests),
                   1e3 * dispatch.busiest_s, dispatch.waits ? 1e3 * dispatch.waited_s / double(dispatch.waits) : 0.0,
                   1e3 * dispatch.longest_wait_s);
  }
  if (g_stop_signal) {
    std::fprintf(stderr, "isosid-sweep: interrupted by %s; the same command resumes the study\n", strsignal(g_stop_signal));
    return 128 + int(g_stop_signal);
  }
  if (record->rows() < record->total())  // a rank stopped early (a signal of its own): never a silent gap
    throw format::ComputationError(std::to_string(record->total() - record->rows()) + " cases have no row (" + record->missing() +
                                   "): a rank stopped before running them; the same command runs them");
  return 0;
}

/// The command line: every rank parses it and reads the same study file.
int run_command(const sweep::Ranks& ranks, int argc, char** argv) {
  CLI::App app{"Runs a study: one scene for every case of its parameters, into one table (study.csv, study.h5).", "isosid-sweep"};
  std::string study_file, out_dir;
  int only_case = -1;
  bool quiet = false;
  app.add_option("study", study_file, "study file (*.study.toml)")->required();
  app.add_option("-o,--output", out_dir, "study folder (default: out/<study name>)");
  app.add_option("--case", only_case, "run only case I (from 0), e.g. one task of a Slurm job array; no table")->check(CLI::NonNegativeNumber);
  app.add_flag("-q,--quiet", quiet, "no progress on stderr");
  if (auto status = common::parse_command_line(app, argc, argv)) return *status;
  for (int signal : {SIGINT, SIGTERM, SIGHUP}) std::signal(signal, request_stop);  // the running cases stop at a step
  return run_study(ranks, study_file, out_dir, only_case, quiet);
}

}  // namespace

int main(int argc, char** argv) {
  // reading SIDs and the solvers' blocks reuse pages instead of faulting anew (a run's memory is small)
  const isosid::common::HeapReuse heap_reuse;
  sweep::Ranks ranks(argc, argv);
  const int status = common::run_guarded("isosid-sweep", [&]() -> int {
    try {
      return run_command(ranks, argc, argv);
    } catch (const format::InputError&) {
      if (ranks.rank() != 0 && !g_study_read) return common::kExitBadInput;  // one line, from rank 0, for a bad study file
      throw;
    }
  });
  if (status != 0 && status < 128 && ranks.size() > 1 && g_study_read) ranks.abort(status);  // others may wait for this rank
  return status;
}

// The preprocessing pipeline's named stages: an observer told when each starts and ends
// (progress), and the clock that runs them and keeps their times (SID provenance, reports).
#pragma once
#include "isosid/common/progress_line.hpp"

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

namespace isosid::prep {

using StageTimings = std::vector<std::pair<std::string, double>>;  ///< stage name, seconds

/// Told about every stage; the default does nothing (no progress).
class StageObserver {
public:
  virtual ~StageObserver() = default;
  virtual void started(const std::string& /*stage*/, const std::string& /*what*/) {}
  virtual void finished(const std::string& /*stage*/, double /*seconds*/) {}
};

/// An observer that says nothing.
StageObserver& no_progress();

/// Progress on stderr: "PROGRAM: what ..." and "PROGRAM: stage done in 1.234 s". On a
/// terminal the first is one line updated a few times a second with the step within the stage
/// (common::work_step), its elapsed time, and its percentage and time left where the stage
/// reports them (common::work_fraction); elsewhere each new step is a line of its own, and a
/// stage that reports its share gets a line with it whenever `log_interval` passed without one.
class StderrProgress : public StageObserver {
public:
  explicit StderrProgress(std::string program, std::chrono::duration<double> log_interval = std::chrono::seconds(10));
  ~StderrProgress() override;
  void started(const std::string& stage, const std::string& what) override;
  void finished(const std::string& stage, double seconds) override;

private:
  void stop_ticker();

  common::ProgressLine line_;
  std::chrono::duration<double> log_interval_;
  std::mutex line_mutex_;  ///< a log's lines come from the step listener and the ticker
  std::chrono::steady_clock::time_point last_line_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool running_ = false;
  std::thread ticker_;
};

/// Runs stages, tells the observer and records their times in order.
class StageClock {
public:
  explicit StageClock(StageObserver& observer) : observer_(observer) {}

  template <class F>
  auto run(const std::string& stage, const std::string& what, F&& f) {
    common::set_work_fraction(-1);  // unknown until the stage reports it
    common::set_work_step("");
    observer_.started(stage, what);
    const auto t0 = std::chrono::steady_clock::now();
    auto finish = [&] {
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      timings_.emplace_back(stage, s);
      observer_.finished(stage, s);
    };
    if constexpr (std::is_void_v<std::invoke_result_t<F>>) {
      f();
      finish();
    } else {
      auto result = f();
      finish();
      return result;
    }
  }
  const StageTimings& timings() const { return timings_; }

private:
  StageObserver& observer_;
  StageTimings timings_;
};

}  // namespace isosid::prep

// Progress observers of the pipeline's stages; see stages.hpp.
#include "pipeline/stages.hpp"

#include <cstdio>

namespace isosid::prep {

namespace {

/// "what ... step, 40 %, 12.0 s" (with ", 18 s left" where `time_left`); without the step where
/// there is none, and without the share where it is unknown (negative).
std::string stage_line(const std::string& what, const std::string& step, double fraction, double elapsed, bool time_left) {
  char text[96];
  if (fraction >= 0) {
    const std::string left = time_left ? common::ProgressLine::time_left(fraction, elapsed) : "";
    std::snprintf(text, sizeof text, " %.0f %%, %.1f s%s%s", 100 * fraction, elapsed, left.empty() ? "" : ", ", left.c_str());
  } else {
    std::snprintf(text, sizeof text, " %.1f s", elapsed);
  }
  return what + " ..." + (step.empty() ? "" : " " + step + ",") + text;
}

}  // namespace

StageObserver& no_progress() {
  static StageObserver silent;
  return silent;
}

StderrProgress::StderrProgress(std::string program, std::chrono::duration<double> log_interval)
    : line_(std::move(program)), log_interval_(log_interval) {}

StderrProgress::~StderrProgress() { stop_ticker(); }

void StderrProgress::started(const std::string& /*stage*/, const std::string& what) {
  stop_ticker();
  if (!line_.terminal()) {
    // a log: a line for each new kind of step (its text up to a comma) as it is set, and for
    // a step whose count moves on at most every interval, so that it stays readable through a
    // long eigen solve; and, when an interval passed with no line, the stage's step, share
    // (where it reports one) and elapsed time
    const auto t0 = std::chrono::steady_clock::now();
    {
      const std::lock_guard<std::mutex> lock(line_mutex_);
      line_.show(what + " ...");
      last_line_ = t0;
    }
    common::set_work_step_listener([this, what, kind = std::string(), shown_at = std::chrono::steady_clock::time_point()](
                                       const std::string& step) mutable {
      const auto now = std::chrono::steady_clock::now();
      const std::string step_kind = step.substr(0, step.find(','));
      if (step.empty() || (step_kind == kind && now - shown_at < log_interval_)) return;
      const std::lock_guard<std::mutex> lock(line_mutex_);
      line_.show(what + " ... " + step);
      kind = step_kind;
      shown_at = last_line_ = now;
    });
    running_ = true;
    ticker_ = std::thread([this, what, t0] {
      std::unique_lock<std::mutex> lock(mutex_);
      while (!wake_.wait_for(lock, log_interval_, [this] { return !running_; })) {
        const double fraction = common::work_fraction();
        // the step before the line's lock: the step listener holds the step's lock and takes the line's
        const std::string step = common::work_step();
        const auto now = std::chrono::steady_clock::now();
        const std::lock_guard<std::mutex> line_lock(line_mutex_);
        if (now - last_line_ < log_interval_) continue;
        line_.show(stage_line(what, step, fraction, std::chrono::duration<double>(now - t0).count(), false));
        last_line_ = now;
      }
    });
    return;
  }
  // a terminal: one line, rewritten four times a second with the step, the elapsed time and
  // (where the stage reports them) its fraction and the time left
  running_ = true;
  ticker_ = std::thread([this, what] {
    const auto t0 = std::chrono::steady_clock::now();
    std::unique_lock<std::mutex> lock(mutex_);
    do {
      const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      line_.show(stage_line(what, common::work_step(), common::work_fraction(), elapsed, true));
    } while (!wake_.wait_for(lock, std::chrono::milliseconds(250), [this] { return !running_; }));
  });
}

void StderrProgress::finished(const std::string& stage, double seconds) {
  stop_ticker();
  char text[64];
  std::snprintf(text, sizeof text, " done in %.3f s", seconds);
  line_.show(stage + text);
  line_.finish();
}

void StderrProgress::stop_ticker() {
  common::set_work_step_listener(nullptr);
  if (!ticker_.joinable()) return;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    running_ = false;
  }
  wake_.notify_all();
  ticker_.join();
}

}  // namespace isosid::prep

// Progress on stderr; see progress_line.hpp.
#include "isosid/common/progress_line.hpp"

#include <atomic>
#include <cstdio>
#include <mutex>
#include <unistd.h>

namespace isosid::common {

ProgressLine::ProgressLine(std::string program) : ProgressLine(std::move(program), isatty(STDERR_FILENO) == 1) {}

ProgressLine::ProgressLine(std::string program, bool terminal) : program_(std::move(program)), terminal_(terminal) {}

ProgressLine::~ProgressLine() { finish(); }

void ProgressLine::show(const std::string& text) {
  if (terminal_) {
    std::fprintf(stderr, "\r%s: %s\033[K", program_.c_str(), text.c_str());
    std::fflush(stderr);
    open_ = true;
  } else {
    std::fprintf(stderr, "%s: %s\n", program_.c_str(), text.c_str());
  }
}

void ProgressLine::finish() {
  if (!open_) return;
  std::fputc('\n', stderr);
  open_ = false;
}

std::string ProgressLine::time_left(double fraction, double elapsed_s) {
  if (!(fraction >= 0.01) || fraction >= 1) return "";
  const double left = elapsed_s * (1 - fraction) / fraction;
  char text[48];
  if (left < 99.5)
    std::snprintf(text, sizeof text, "%.0f s left", left);
  else if (left < 5970)
    std::snprintf(text, sizeof text, "%.0f min left", left / 60);
  else
    std::snprintf(text, sizeof text, "%.1f h left", left / 3600);
  return text;
}

namespace {
std::atomic<double> g_work_fraction{-1.0};
std::mutex g_work_step_mutex;
std::string g_work_step;
std::function<void(const std::string&)> g_work_step_listener;
}  // namespace

void set_work_fraction(double fraction) { g_work_fraction.store(fraction, std::memory_order_relaxed); }

double work_fraction() { return g_work_fraction.load(std::memory_order_relaxed); }

void set_work_step(std::string step) {
  const std::lock_guard<std::mutex> lock(g_work_step_mutex);
  g_work_step = std::move(step);
  if (g_work_step_listener) g_work_step_listener(g_work_step);
}

void set_work_step_listener(std::function<void(const std::string&)> listener) {
  const std::lock_guard<std::mutex> lock(g_work_step_mutex);
  g_work_step_listener = std::move(listener);
}

std::string work_step() {
  const std::lock_guard<std::mutex> lock(g_work_step_mutex);
  return g_work_step;
}

}  // namespace isosid::common

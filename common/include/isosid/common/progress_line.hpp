// Progress of long work on stderr. On a terminal: one line rewritten in place (carriage
// return, clear to the end), kept when the work ends. Elsewhere (a log, a pipe, CI): plain
// lines, so that logs stay readable.
#pragma once
#include <chrono>
#include <functional>
#include <string>

namespace isosid::common {

class ProgressLine {
public:
  /// `program` prefixes every line; `terminal` defaults to whether stderr is one.
  explicit ProgressLine(std::string program);
  ProgressLine(std::string program, bool terminal);
  ~ProgressLine();
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  /// Shows "<program>: <text>": replaces the current line on a terminal, else prints a line.
  void show(const std::string& text);
  /// Ends the current line on a terminal (the next output starts on a fresh line).
  void finish();
  bool terminal() const { return terminal_; }

  /// "12 s left" (or minutes, hours) for work `fraction` done after `elapsed_s`; empty below 1 %.
  static std::string time_left(double fraction, double elapsed_s);

private:
  std::string program_;
  bool terminal_;
  bool open_ = false;  ///< a terminal line is shown and not yet ended
};

/// How far the long loop under way is, 0..1 (negative: unknown): set by the loop (e.g. the
/// element loop of assembly, from any thread), read by whoever shows progress. One value for
/// the process: the programs run one long loop at a time.
void set_work_fraction(double fraction);
double work_fraction();

/// What the long work under way is doing now, within its stage (e.g. "Lanczos, 57 solves"),
/// shown after the stage's own text; empty: nothing more to say. Set from any thread, like
/// the fraction.
void set_work_step(std::string step);
std::string work_step();
/// Called with every new step as it is set (in the setting thread, one call at a time): for
/// progress in a log, which prints steps as they come rather than sampling them (it must not
/// set a step itself). Empty: none.
void set_work_step_listener(std::function<void(const std::string&)> listener);

}  // namespace isosid::common

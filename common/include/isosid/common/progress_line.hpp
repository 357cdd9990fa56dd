// Progress of long work on stderr. On a terminal: one line rewritten in place (carriage
// return, clear to the end), kept when the work ends. Elsewhere (a log, a pipe, CI): plain
// lines, so that logs stay readable.
#pragma once
#include <chrono>
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

}  // namespace isosid::common

// The preparation's progress in a log (stderr not a terminal): a stage's steps as lines, and
// its share whenever an interval passed with no line, so that a long stage that reports a share
// and no steps (an assembly) is not silent.
#include "isosid/common/progress_line.hpp"
#include "pipeline/stages.hpp"

#include <catch2/catch.hpp>
#include <chrono>
#include <cstdio>
#include <sstream>
#include <thread>
#include <unistd.h>

using namespace isosid;
using Catch::Matchers::Contains;

namespace {

/// stderr written into a file while alive; `text()` reads what was written.
class CapturedStderr {
public:
  CapturedStderr() : file_(std::tmpfile()), saved_(dup(STDERR_FILENO)) {
    std::fflush(stderr);
    dup2(fileno(file_), STDERR_FILENO);
  }
  ~CapturedStderr() {
    restore();
    std::fclose(file_);
  }
  /// What was written so far (stderr is unbuffered: every line is in the file once shown).
  std::string text() const {
    std::string out;
    char buffer[4096];
    for (off_t at = 0;;) {
      const ssize_t n = pread(fileno(file_), buffer, sizeof buffer, at);
      if (n <= 0) return out;
      out.append(buffer, std::size_t(n));
      at += n;
    }
  }
  /// Waits up to `limit` for `part` to be written; true when it was.
  bool wait_for(const std::string& part, std::chrono::seconds limit = std::chrono::seconds(20)) const {
    const auto until = std::chrono::steady_clock::now() + limit;
    while (text().find(part) == std::string::npos) {
      if (std::chrono::steady_clock::now() > until) return false;
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return true;
  }

private:
  void restore() {
    if (saved_ < 0) return;
    std::fflush(stderr);
    dup2(saved_, STDERR_FILENO);
    close(saved_);
    saved_ = -1;
  }
  std::FILE* file_;
  int saved_;
};

}  // namespace

TEST_CASE("StderrProgress: in a log, a stage's share or its elapsed time gets a line whenever an interval passed without one", "[pipeline]") {
  CapturedStderr captured;  // a file, never a terminal: the log's form
  common::set_work_fraction(-1);
  common::set_work_step("");
  {
    prep::StderrProgress progress("test", std::chrono::milliseconds(100));
    progress.started("assembly", "assembling 8 elements");
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    // no share reported: the elapsed time, so that a long stage is never silent
    CHECK_THAT(captured.text(), Catch::Matchers::StartsWith("test: assembling 8 elements ...\ntest: assembling 8 elements ... 0."));
    common::set_work_fraction(0.25);
    REQUIRE(captured.wait_for("test: assembling 8 elements ... 25 %, "));
    common::set_work_fraction(0.75);
    common::set_work_step("a step");  // a line of its own, at once
    REQUIRE(captured.wait_for("test: assembling 8 elements ... a step, 75 %, "));  // the share with the step
    progress.finished("assembly", 0.75);
  }
  common::set_work_fraction(-1);
  common::set_work_step("");
  const std::string log = captured.text();
  CHECK(log.find("... a step\n") < log.find("... a step, 75 %"));
  CHECK_THAT(log, Contains("test: assembly done in 0.750 s\n"));
  // every line whole: the two threads' lines do not interleave
  std::istringstream lines(log);
  for (std::string line; std::getline(lines, line);) CHECK_THAT(line, Catch::Matchers::StartsWith("test: "));
}

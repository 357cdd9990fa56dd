// The time-left estimate of progress lines: linear extrapolation of the elapsed time, in the
// unit a reader takes in at a glance, and nothing while too little is done to tell.
#include "isosid/common/progress_line.hpp"

#include <catch2/catch.hpp>

using isosid::common::ProgressLine;

TEST_CASE("time left: extrapolated from the fraction done, in seconds, minutes or hours", "[common][progress]") {
  CHECK(ProgressLine::time_left(0.5, 10.0) == "10 s left");
  CHECK(ProgressLine::time_left(0.25, 60.0) == "3 min left");
  CHECK(ProgressLine::time_left(0.1, 3600.0) == "9.0 h left");
  CHECK(ProgressLine::time_left(0.001, 10.0).empty());  // below 1 %: no estimate
  CHECK(ProgressLine::time_left(1.0, 10.0).empty());    // done
  CHECK(ProgressLine::time_left(-1.0, 10.0).empty());   // unknown
}

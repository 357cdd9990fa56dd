// What a program records about how it was run: its exact command line and the time, for the
// provenance of the files it writes (SIDs, results.h5, summary.json).
#pragma once
#include <string>

namespace isosid::common {

/// This process's command line as a shell would take it back: its arguments from
/// /proc/self/cmdline, each single-quoted unless it is plain (letters, digits, and -_./=:,+@%).
/// Empty where /proc is not mounted.
std::string command_line();

/// The current time in UTC, ISO 8601 to the second ("2026-11-28T05:10:00Z").
std::string utc_now();

}  // namespace isosid::common

// What a finished (or failed) run leaves behind: results.h5 and summary.json in the results
// folder, each written atomically, and the lines that compare it with its reference values.
#pragma once
#include "output/recorder.hpp"
#include "solve/simulation.hpp"

#include <nlohmann/json.hpp>
#include <string>

namespace isosid::run {

/// Writes dir/results.h5 and dir/summary.json and returns the summary.
nlohmann::json write_run_report(const std::string& dir, const Recorder& recorder, const Simulation& simulation,
                                const RunOutcome& outcome);

/// One line per reference value of a summary: measured, reference and the signed relative
/// error in percent (positive: the run measures more).
std::string reference_lines(const nlohmann::json& summary);

}  // namespace isosid::run

// One run's results from its phases ([R2] in docs/references.md: coarse phases between impacts,
// refined ones during them). Each phase leaves a results folder of its own, as a plain run would;
// these join them into the run's results.h5 and summary.json, so an adaptive run reads like any
// other.
#pragma once
#include "output/run_provenance.hpp"

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace isosid::run {

/// Writes `path` (atomically): the time series of the phases' results.h5 files joined in time.
/// Each later phase's first sample repeats the last of the phase before and is dropped. A
/// series whose width changes between phases (the elastic coordinates and modal energies of a
/// body whose model changed) stays in the phases' files only. Contact force spectra are
/// computed again over the joined force.
void join_phase_results(const std::vector<std::string>& phase_files, const std::string& path, double output_interval,
                        const RunProvenance& provenance);

/// The run's summary from its phases' summaries, in order, and the joined results.h5: the
/// run's wall and CPU time as given (refused tries and preprocessing included), sums of
/// counts and of the RHS time split (RHS cost weighted), each contact's first onset and last release (a
/// contact closed across a switch is one interval), largest peak with that phase's penalty and
/// Hertz estimate, summed impulse, every touch; each joint's largest force, torque and errors;
/// each velocity monitor's arrival and reversal against the run's start over the joined
/// samples, each stress monitor's largest stress; the final state of the last phase; the
/// energy from the first phase's start to the last phase's end, its largest relative change
/// over the joined series. The caller adds the reference comparison.
nlohmann::json join_phase_summaries(const std::vector<nlohmann::json>& phases, const std::string& joined_results,
                                    double wall_time_s, double cpu_time_s);

}  // namespace isosid::run

// One run's results from its phases (seed 001: coarse phases between impacts, refined ones
// during them). Each phase leaves a results folder of its own, as a plain run would; these
// join them into the run's results.h5 and summary.json, so an adaptive run reads like any other.
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace isosid::run {

/// Writes `path` (atomically): the time series of the phases' results.h5 files joined in time.
/// Each later phase's first sample repeats the last of the phase before and is dropped. A
/// series whose width changes between phases (the elastic coordinates and modal energies of a
/// body whose model changed) stays in the phases' files only. Contact force spectra are
/// computed again over the joined force.
void join_phase_results(const std::vector<std::string>& phase_files, const std::string& path, double output_interval);

/// The run's summary from its phases' summaries, in order: sums of times and counts, each
/// contact's first onset and last release, largest peak and summed impulse, every touch; each
/// monitor's arrival and reversal as the first phase saw them (they are measured against the
/// value at the start), its largest stress; the final state of the last phase; the energy
/// from the first phase's start to the last phase's end, its largest relative change taken
/// from `energy_total` (the joined series). The caller adds the reference comparison.
nlohmann::json join_phase_summaries(const std::vector<nlohmann::json>& phases, const std::vector<double>& energy_total);

}  // namespace isosid::run

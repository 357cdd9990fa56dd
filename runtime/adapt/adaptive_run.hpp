// A run whose adaptive bodies change their model at each impact ([R2] Fig. 2, docs/references.md):
// coarse phases between impacts on each body's coarse model, stopped where a contact's exact
// surfaces first touch; a fine model refined around that point (isosid-prep, cached) for the
// impact; the state moved into it with the refined SID's transfer, the impact run until its
// surfaces are apart again, and the state moved back. Each phase writes a results folder of its own
// (phases/NN-...); the run's results.h5 and summary.json join them and log every decision.
#pragma once
#include "output/run_folder.hpp"
#include "scene/scene.hpp"
#include "solve/simulation.hpp"

#include <functional>
#include <nlohmann/json.hpp>
#include <string>

namespace isosid::run {

class AdaptiveRun {
public:
  /// `scene` must have adaptive bodies; results go to `folder` (started once the first
  /// phase is accepted; it must outlive the run).
  AdaptiveRun(Scene scene, RunFolder& folder, bool quiet);

  struct Result {
    RunOutcome outcome;     ///< of the run: "completed", or the failure or stop of the phase that ended it
    nlohmann::json summary; ///< as written to summary.json
    double end_time = 0;    ///< s, where the run ended
  };
  /// Runs every phase; `stop_requested` is asked between output samples (a signal).
  Result run(const std::function<bool()>& stop_requested);

private:
  Scene scene_;
  RunFolder& folder_;
  std::string out_dir_;
  bool quiet_;
};

}  // namespace isosid::run

// One pipeline for every run of a scene: isosid-run calls it, and so will the sweep engine and
// the Python package. A scene with adaptive bodies runs phase by phase (adapt/adaptive_run),
// any other as one simulation; both leave results.h5 and summary.json in the results folder.
#pragma once
#include "output/run_folder.hpp"
#include "scene/scene.hpp"
#include "solve/simulation.hpp"

#include <functional>
#include <nlohmann/json.hpp>

namespace isosid::run {

struct RunOptions {
  bool quiet = false;  ///< no progress and no set-up notes on stderr
  /// Asked at every step and sample (a signal arrived): the run stops there and keeps its
  /// results so far ("interrupted").
  std::function<bool()> stop_requested = [] { return false; };
};

struct RunResult {
  RunOutcome outcome;         ///< completed, failed (with its cause) or interrupted
  nlohmann::json summary;     ///< as written to summary.json (empty if the run stopped before it started)
  double end_time = 0;        ///< s, where the run ended
  bool started = true;        ///< false: stopped before the first step, nothing written
};

/// Runs `scene` into `folder` (created by the caller before any work, started here once the
/// scene's bodies are accepted). Bad input the loaded bodies reveal throws InputError before
/// anything is written; a failed computation returns its outcome with the results so far.
RunResult run_scene(Scene scene, RunFolder& folder, const RunOptions& options);

}  // namespace isosid::run

// A run whose accepted steps have collapsed many decades below the time scale of its contacts
// would crawl for hours toward max_steps: it is ended as failed, with a diagnosis, once that
// has lasted long enough not to be a dip at an event. Penalties far too stiff, its usual cause,
// are refused before the run (solve/run_checks.hpp); this is the net behind that refusal.
#pragma once

namespace isosid::run {

/// Steps shorter than this fraction of the time scale count as collapsed: nine decades (scene
/// A's steps are 1e-3 to 1e-5 of its Hertz contact time, 1e-6 at a penalty 1e7 times stiffer
/// than the derived one; a penalty of 1e40 into an initial overlap steps at 1e-14 of it).
constexpr double kCollapsedStepRatio = 1e-9;
/// Collapsed steps in a row that end the run (at 1e-18 s per step, well under a second).
constexpr long kCollapsedSteps = 1000;

class StepCollapse {
public:
  /// `time_scale`: s, the shortest time the run must resolve (Hertz contact times, the output interval).
  explicit StepCollapse(double time_scale) : time_scale_(time_scale) {}
  /// An accepted step ending at t. Throws ComputationError once kCollapsedSteps steps in a row
  /// were shorter than kCollapsedStepRatio of the time scale.
  void observe(double t);

private:
  double time_scale_, last_t_ = -1;
  long in_a_row_ = 0;
};

}  // namespace isosid::run

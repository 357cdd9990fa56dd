// The collapse of a run's steps; see step_collapse.hpp.
#include "solve/step_collapse.hpp"

#include "isosid/common/number_text.hpp"
#include "isosid/format/error.hpp"

#include <string>

namespace isosid::run {

void StepCollapse::observe(double t) {
  const double step = t - last_t_;
  const bool first = last_t_ < 0;
  last_t_ = t;
  if (first || step >= kCollapsedStepRatio * time_scale_) {
    in_a_row_ = 0;
    return;
  }
  if (++in_a_row_ < kCollapsedSteps) return;
  throw format::ComputationError("the steps collapsed to " + common::number_text(step) + " s, " + common::number_text(step / time_scale_) +
                                 " of the time the run must resolve (" + common::number_text(time_scale_) + " s: the shortest Hertz contact "
                                 "time or output interval), for " + std::to_string(kCollapsedSteps) +
                                 " steps in a row: a penalty far too stiff for the contact, or bodies started deep in each other?");
}

}  // namespace isosid::run

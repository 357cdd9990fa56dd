// The adaptive penalty's trial; see penalty_search.hpp.
#include "adapt/penalty_search.hpp"

#include "isosid/common/number_text.hpp"

#include <cmath>

namespace isosid::run {

PenaltyFactor PenaltyFactor::lowered() const {
  if (!(value_ > 0)) return *this;
  // the leading digit's unit, from the value's decimal exponent (guarded against log10's
  // round-off at exact powers of ten)
  double unit = std::pow(10.0, std::floor(std::log10(value_)));
  if (unit > value_) unit /= 10;
  else if (10 * unit <= value_) unit *= 10;
  return PenaltyFactor(value_ - (value_ >= 2 * unit ? unit : unit / 10));
}

void PenaltySearch::record(PenaltyProbe probe) {
  using common::number_text;
  if (done_) return;
  probes_.push_back(std::move(probe));
  const PenaltyProbe& p = probes_.back();
  const PenaltyProbe* before = probes_.size() > 1 ? &probes_[probes_.size() - 2] : nullptr;
  if (p.error.empty() && before && p.steps > kStepGrowth * before->steps)
    probes_.back().error = "steps grew from " + std::to_string(before->steps) + " to " + std::to_string(p.steps);
  if (!p.error.empty()) {
    done_ = true;
    // [R2]'s slow decrease starts from the penalty that failed; after a good decade the
    // search keeps that one instead (it ran without error, and the next is ten times stiffer)
    result_ = before ? before->penalty : p.penalty.lowered();
    reason_ = "error at " + number_text(p.penalty.value()) + " N/m^3 (" + p.error + ")";
    return;
  }
  if (before && std::abs(p.force - before->force) <= kForceTolerance * std::abs(p.force)) {
    done_ = true;
    result_ = before->penalty;
    reason_ = "converged: force " + number_text(before->force) + " N against " + number_text(p.force) + " N ten times stiffer";
    return;
  }
  if (int(probes_.size()) == kMaxProbes) {
    done_ = true;
    result_ = p.penalty;
    reason_ = "not converged after " + std::to_string(kMaxProbes) + " decades: the last taken";
    return;
  }
  next_ = p.penalty.raised();
}

}  // namespace isosid::run

// The events of a monitored velocity against its value at the start: a wave front's arrival
// (it first leaves the initial value by 1 %) and its reversal (its component along the initial
// velocity changes sign), each interpolated linearly within the interval that holds it. Fed
// at every accepted step by the recorder, or sample by sample over an adaptive run's phases.
#pragma once
#include <Eigen/Dense>

namespace isosid::run {

class VelocityEvents {
public:
  /// The velocity at the start, t.
  void start(double t, const Eigen::Vector3d& v);
  /// The velocity v at time t, after the last call.
  void add(double t, const Eigen::Vector3d& v);
  double arrival() const { return arrival_; }    ///< s, or -1 if none (also without a start velocity)
  double reversal() const { return reversal_; }  ///< s, or -1 if none

private:
  Eigen::Vector3d initial_ = Eigen::Vector3d::Zero(), last_ = Eigen::Vector3d::Zero();
  double last_t_ = 0, arrival_ = -1, reversal_ = -1;
};

}  // namespace isosid::run

// Velocity events; see velocity_events.hpp.
#include "output/velocity_events.hpp"

#include <algorithm>

namespace isosid::run {

void VelocityEvents::start(double t, const Eigen::Vector3d& v) {
  initial_ = last_ = v;
  last_t_ = t;
}

void VelocityEvents::add(double t, const Eigen::Vector3d& v) {
  if (reversal_ >= 0) return;  // nothing more to find
  const Eigen::Vector3d& v0 = initial_;
  const double v0v0 = v0.squaredNorm(), dt = t - last_t_;
  const double now = v.dot(v0), before = last_.dot(v0);
  const double change_now = 1 - now / std::max(v0v0, 1e-300), change_before = 1 - before / std::max(v0v0, 1e-300);
  if (v0v0 > 0 && arrival_ < 0 && change_now > 0.01 && change_before <= 0.01)
    arrival_ = last_t_ + dt * (0.01 - change_before) / (change_now - change_before);
  if (v0v0 > 0 && now < 0 && before >= 0) reversal_ = last_t_ + dt * before / (before - now);
  last_ = v;
  last_t_ = t;
}

}  // namespace isosid::run

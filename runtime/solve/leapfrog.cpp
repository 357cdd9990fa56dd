// Leapfrog time stepping; see leapfrog.hpp.
#include "solve/leapfrog.hpp"

#include "isosid/format/error.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace isosid::run {

Leapfrog::Leapfrog(const MultibodySystem& system, double step, Eigen::VectorXd y0, long max_steps, double t0)
    : TimeIntegrator(std::move(y0), max_steps), system_(system), step_(step), ydot_(Eigen::VectorXd::Zero(y_.size())) {
  for (const auto& b : system_.bodies()) {
    // a body's state: r (3), quaternion (4), q (nd), then v (3), omega (3), qdot (nd)
    const Eigen::Index velocities = b->offset() + 7 + b->n_dynamic();
    for (Eigen::Index i = 0; i < 6 + b->n_dynamic(); ++i) velocities_.push_back(velocities + i);
  }
  system_.rhs(t0, y_.data(), ydot_.data());
  ++evaluations_;
  gaps_.resize(system_.contacts().size());
  new_gaps_.resize(gaps_.size());
  system_.gaps(y_.data(), gaps_.data());
}

std::vector<TimeIntegrator::GapEvent> Leapfrog::advance(double tout, double& t) {
  std::vector<GapEvent> changed;
  while (t < tout * (1 - 1e-12) && changed.empty()) {
    if (steps_ >= max_steps_) throw format::ComputationError("the step limit max_steps = " + std::to_string(max_steps_) + " was reached");
    const double left = tout - t, steps = std::ceil(left / step_ * (1 - 1e-9));
    step(t, left / std::max(steps, 1.0), changed);
    if (step_callback_) step_callback_(t, y_.data());
  }
  return changed;
}

IntegratorStats Leapfrog::stats() const {
  IntegratorStats s;
  s.steps = s.attempts = steps_;
  s.rhs_evaluations = evaluations_;
  return s;
}

void Leapfrog::step(double& t, double dt, std::vector<GapEvent>& changed) {
  const Eigen::Index last = y_.size() - 1;  // the dissipated energy, integrated by the trapezoidal rule
  const double dissipation_before = ydot_(last);
  // kick: v(n + 1/2) = v(n) + dt/2 a(n)
  for (const Eigen::Index i : velocities_) y_(i) += 0.5 * dt * ydot_(i);
  // drift with the half-step velocities: r += dt v, q += dt qdot, and the orientation turned
  // exactly by the body-frame rate over the step, p <- p exp(dt omega / 2)
  for (const auto& b : system_.bodies()) {
    const Eigen::Index o = b->offset(), nd = b->n_dynamic();
    for (Eigen::Index i = 0; i < 3; ++i) y_(o + i) += dt * y_(o + 7 + nd + i);
    for (Eigen::Index i = 0; i < nd; ++i) y_(o + 7 + i) += dt * y_(o + 13 + nd + i);
    const Eigen::Vector3d w(y_(o + 10 + nd), y_(o + 11 + nd), y_(o + 12 + nd));
    const double angle = w.norm() * dt;
    if (angle > 0) {
      const Eigen::Quaterniond p(y_(o + 3), y_(o + 4), y_(o + 5), y_(o + 6));
      const Eigen::Quaterniond turned = (p * Eigen::Quaterniond(Eigen::AngleAxisd(angle, w.normalized()))).normalized();
      y_(o + 3) = turned.w(), y_(o + 4) = turned.x(), y_(o + 5) = turned.y(), y_(o + 6) = turned.z();
    }
  }
  t += dt;
  // the static sub-problems and accelerations at the new positions (half-step velocities)
  system_.rhs(t, y_.data(), ydot_.data());
  ++evaluations_;
  // kick: v(n + 1) = v(n + 1/2) + dt/2 a(n + 1)
  for (const Eigen::Index i : velocities_) y_(i) += 0.5 * dt * ydot_(i);
  y_(last) += 0.5 * dt * (dissipation_before + ydot_(last));
  system_.keep_static_solution(y_.data());
  ++steps_;
  // contact onset and release within the step, with the static solve of the rhs at these
  // positions (the kick since changed only velocities)
  system_.gaps(y_.data(), new_gaps_.data());
  for (std::size_t k = 0; k < gaps_.size(); ++k) {
    const bool was_open = gaps_[k] > 0, is_open = new_gaps_[k] > 0;
    if (was_open == is_open) continue;
    const double fraction = gaps_[k] / (gaps_[k] - new_gaps_[k]);  // in [0, 1]: the signs differ
    changed.push_back({int(k), was_open, t - dt + fraction * dt});
  }
  std::swap(gaps_, new_gaps_);
}

}  // namespace isosid::run

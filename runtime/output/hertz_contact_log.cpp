// A Hertz contact's report; see hertz_contact_log.hpp.
#include "output/hertz_contact_log.hpp"

#include <algorithm>
#include <cmath>

namespace isosid::run {

namespace {

struct Extremum {
  double time, value;
};

/// The least value of the cubic Hermite interpolant of g between (t0, g0, rate r0 < 0) and
/// (t1, g1, rate r1 >= 0), where its slope crosses zero.
Extremum hermite_minimum(double t0, double g0, double r0, double t1, double g1, double r1) {
  const double h = t1 - t0;
  // g(s) = a s^3 + b s^2 + c s + g0 on s in [0, 1]; g'(s) = 3a s^2 + 2b s + c, g'(0) < 0 <= g'(1)
  const double a = 2 * (g0 - g1) + h * (r0 + r1), b = 3 * (g1 - g0) - h * (2 * r0 + r1), c = h * r0;
  double s = 1;
  if (std::abs(a) <= 1e-12 * (std::abs(b) + std::abs(c))) {
    if (b > 0) s = -c / (2 * b);
  } else {
    // of the slope's two roots, the one in [0, 1] where it rises (g'' >= 0); q keeps the
    // quadratic formula free of cancellation
    const double disc = std::max(0.0, b * b - 3 * a * c);
    const double q = -(b + std::copysign(std::sqrt(disc), b));
    const double first = q / (3 * a), second = q != 0 ? c / q : first;
    for (const double root : {first, second})
      if (root >= 0 && root <= 1 && 6 * a * root + 2 * b >= 0) s = root;
  }
  s = std::clamp(s, 0.0, 1.0);
  return {t0 + s * h, ((a * s + b) * s + c) * s + g0};
}

}  // namespace

void HertzContactLog::sample(const ContactState& state) {
  for (int a = 0; a < 3; ++a) force_.push_back(state.force(a));
  overlap_.push_back(state.max_penetration);
}

void HertzContactLog::step(double t, const double* y, const ContactState& state) {
  const double gap = contact_.gap(y), rate = contact_.gap_rate(y), force = state.force.norm();
  // the zero of the gap between the last step and this one
  auto crossing = [&] { return last_gap_ != gap ? last_t_ + (t - last_t_) * last_gap_ / (last_gap_ - gap) : t; };
  if (!started_) {  // a run (or a phase) may start in contact
    if (gap < 0) impacts_.push_back({t}), touching_ = true;
  } else {
    if (!touching_ && gap < 0) impacts_.push_back({crossing()}), touching_ = true;
    if (touching_) impacts_.back().impulse += 0.5 * (force + last_force_) * (t - last_t_);
    if (touching_ && gap >= 0) impacts_.back().end = crossing(), touching_ = false;
  }
  if (touching_ && force > impacts_.back().peak_force) impacts_.back().peak_force = force, impacts_.back().peak_time = t;
  if (touching_ && started_ && last_rate_ < 0 && rate >= 0 && t > last_t_) {  // the deepest overlap lies between the steps
    const Extremum deepest = hermite_minimum(last_t_, last_gap_, last_rate_, t, gap, rate);
    const double peak = deepest.value < 0 ? contact_.stiffness() * std::pow(-deepest.value, 1.5) : 0.0;
    if (peak > impacts_.back().peak_force) impacts_.back().peak_force = peak, impacts_.back().peak_time = deepest.time;
  }
  started_ = true;
  last_t_ = t, last_gap_ = gap, last_rate_ = rate, last_force_ = force;
}

void HertzContactLog::write(format::h5::Writer& w) const {
  const std::string g = "/hertz_contacts/" + contact_.name();
  const auto n = Eigen::Index(overlap_.size());
  w.group(g);
  w.matrix(g + "/force", Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(force_.data(), n, 3), "N");
  w.vector(g + "/overlap", Eigen::Map<const Eigen::VectorXd>(overlap_.data(), n), "m");
}

nlohmann::json HertzContactLog::summary() const {
  using nlohmann::json;
  json impacts = json::array();
  double peak = 0;
  for (const Impact& i : impacts_) {
    impacts.push_back({{"start_s", i.start},
                       {"end_s", i.end < 0 ? json(nullptr) : json(i.end)},
                       {"duration_s", i.end < 0 ? json(nullptr) : json(i.end - i.start)},
                       {"peak_force_n", i.peak_force},
                       {"peak_time_s", i.peak_time},
                       {"impulse_ns", i.impulse}});
    peak = std::max(peak, i.peak_force);
  }
  return {{"name", contact_.name()}, {"stiffness_n_m1_5", contact_.stiffness()}, {"peak_force_n", peak}, {"impacts", impacts}};
}

}  // namespace isosid::run

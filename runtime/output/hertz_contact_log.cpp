// A Hertz contact's report; see hertz_contact_log.hpp.
#include "output/hertz_contact_log.hpp"

namespace isosid::run {

void HertzContactLog::sample(const ContactState& state) {
  for (int a = 0; a < 3; ++a) force_.push_back(state.force(a));
  overlap_.push_back(state.max_penetration);
}

void HertzContactLog::step(double t, const double* y, const ContactState& state) {
  const double gap = contact_.gap(y), force = state.force.norm();
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
  started_ = true;
  last_t_ = t, last_gap_ = gap, last_force_ = force;
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

// What a run's recorder says at its end: its warnings and summary.json; see recorder.hpp.
#include "output/recorder.hpp"

#include "output/warning_list.hpp"

#include "contact/default_penalty.hpp"
#include "contact/impact_estimate.hpp"
#include "isosid/common/number_text.hpp"
#include "output/reference_comparison.hpp"

#include <cmath>
#include <optional>

namespace isosid::run {

namespace {
/// The deepest penetration of a contact's points over its Hertz approach, or nullopt where the
/// estimate has none (line contact, no approach).
std::optional<double> penetration_per_approach(double max_penetration, const std::optional<ImpactEstimate>& estimate) {
  if (!estimate || !(estimate->approach > 0)) return std::nullopt;
  return max_penetration / estimate->approach;
}
}  // namespace

std::string Recorder::never_closed_warning(const std::string& contact) {
  return "contact '" + contact + "' never closed: it reports no force, duration or rebound; check the bodies' start positions and "
         "velocities against simulation.end_time, or leave the contact out";
}

std::vector<RunWarning> Recorder::warnings() const {
  std::vector<RunWarning> out = system_.warnings();
  for (std::size_t k = 0; k < edge_reached_.size(); ++k) {
    if (edge_reached_[k] < 0) continue;
    const SurfaceContact& c = system_.contacts()[k];
    out.push_back({"edge_reached", "contact '" + c.name() + "' loaded the edge elements of surface '" + c.surface().name + "' of body '" +
                  c.body().name() + "' at t = " + common::number_text(edge_reached_[k]) +
                  " s: the surface beyond is not checked for contact, so forces may be cut off; widen its interval"});
  }
  for (std::size_t k = 0; k < max_penetration_.size(); ++k) {
    const auto& estimate = system_.impact_estimates()[k];
    const auto ratio = penetration_per_approach(max_penetration_[k], estimate);
    if (!ratio || *ratio <= kMaxPenetrationPerApproach) continue;
    const SurfaceContact& c = system_.contacts()[k];
    out.push_back({"penalty_too_soft", "contact '" + c.name() + "' penetrated " + common::number_text(max_penetration_[k]) + " m, " + common::number_text(*ratio) +
                  " times the Hertz approach of the bodies (" + common::number_text(estimate->approach) +
                  " m): its penalty (" + common::number_text(c.penalty()) + " N/m^3, " + c.penalty_source() +
                  ") is too soft, and the forces and contact time are the penalty layer's, not the bodies'"});
  }
  for (std::size_t k = 0; k < intervals_.size(); ++k)
    if (intervals_[k].empty()) out.push_back({"never_closed", never_closed_warning(system_.contacts()[k].name())});
  for (std::size_t k = 0; k < intervals_.size(); ++k) {
    if (!closed_at_end(k)) continue;
    const auto& estimate = system_.impact_estimates()[k];
    out.push_back({"closed_at_end", "contact '" + system_.contacts()[k].name() + "' is still closed at the end of the run (t = " +
                  common::number_text(time_.empty() ? 0.0 : time_.back()) + " s): its duration and the bodies' rebound are not final" +
                  (estimate && estimate->contact_time > 0 ? " (the Hertz estimate puts the contact time at " +
                                                                 common::number_text(estimate->contact_time) + " s)"
                                                           : std::string()) +
                  "; extend simulation.end_time"});
  }
  if (scene_.reference_from_hertz) {
    const auto& estimates = system_.impact_estimates();
    if (estimates.empty() || !estimates[0])
      out.push_back({"reference", "[reference] source = \"hertz\": the first contact has no Hertz estimate, so its peak force and contact "
                    "time are not compared"});
    else if (estimates[0]->line_contact)
      out.push_back({"reference", "[reference] source = \"hertz\": the first contact is a line contact, whose Hertz estimate has no contact "
                    "time; only its peak force is compared"});
  }
  if (const double error = energy_error_per_motion(); error > kMaxEnergyError)
    out.push_back({"energy", "the energy balance is off by " + common::number_text(error) +
                  " of the largest energy in motion: the integration did not follow the motion, so forces and velocities are not "
                  "to be trusted; tighten simulation.rtol (or shorten simulation.step for the leapfrog)"});
  for (std::size_t k = 0; k < interface_left_.size(); ++k) {
    if (interface_left_[k] < 0) continue;
    const SurfaceContact& c = system_.contacts()[k];
    out.push_back({"interface_left", "contact '" + c.name() + "' loaded points of surface '" + c.surface().name + "' of body '" + c.body().name() +
                  "' beyond its Craig-Bampton interface at t = " + common::number_text(interface_left_[k]) +
                  " s: only normal modes deform the surface there, so it presses like a rigid one and the forces come out too "
                  "high; widen the interface (reduction.interface_points) or move its interface_center over where the contact goes"});
  }
  return out;
}

nlohmann::json Recorder::contact_summary(std::size_t k) const {
  using nlohmann::json;
  json c;
  c["name"] = system_.contacts()[k].name();
  const auto& list = intervals_[k];
  c["start_s"] = list.empty() ? json(nullptr) : json(list.front().start);
  c["end_s"] = list.empty() || list.back().end < 0 ? json(nullptr) : json(list.back().end);
  // one impact may open and close several times at onset (single Gauss points bouncing):
  // the contact lasts from the first onset to the last release
  c["duration_s"] = list.empty() || list.back().end < 0 ? json(nullptr) : json(list.back().end - list.front().start);
  c["intervals"] = list.size();
  // the exact surfaces' first instants of contact, one per impact
  c["touches"] = json::array();
  for (const auto& entry : touches_[k]) {
    const Touch& touch = entry.second;  // (a structured binding could not be captured below in C++17)
    auto parameters = [&](const Eigen::Vector2d& u) {
      if (std::isnan(u(0))) return json(nullptr);
      json values = json::array();
      for (int a = 0; a < touch.parameter_dim; ++a) values.push_back(u(a));
      return values;
    };
    c["touches"].push_back({{"time_s", entry.first}, {"gap_m", touch.gap}, {"slave_parameter", parameters(touch.slave_parameter)},
                            {"target_parameter", parameters(touch.target_parameter)},
                            {"point_m", {touch.point.x(), touch.point.y(), touch.point.z()}}});
  }
  c["penalty_n_m3"] = system_.contacts()[k].penalty();
  c["penalty_source"] = system_.contacts()[k].penalty_source();
  c["peak_force_n"] = peak_force_[k];
  c["points_at_peak"] = points_at_peak_[k];  // Gauss points carrying load at the peak-force step
  const SurfaceContact& contact = system_.contacts()[k];
  c["formulation"] = contact.gap_space() ? "gap-space" : "general";
  c["law"] = contact.law_name();
  if (contact.gap_space()) {
    // pairings: once per impact, more where the points slid beyond what a pairing holds
    const GapPairing& pairing = contact.gap_pairing();
    c["pairs"] = pairing.largest_pairing();
    c["pairings"] = pairing.pairings();
    c["repairings"] = pairing.repairings();
    c["condensed_points"] = pairing.largest_condensed();
    c["reach_widenings"] = pairing.widenings();
  }
  c["edge_reached_s"] = edge_reached_[k] < 0 ? json(nullptr) : json(edge_reached_[k]);
  c["interface_left_s"] = interface_left_[k] < 0 ? json(nullptr) : json(interface_left_[k]);
  if (const auto& e = system_.impact_estimates()[k])
    c["hertz_estimate"] = {{"approach_speed_m_s", e->approach_speed},
                           {e->line_contact ? "contact_half_width_m" : "contact_radius_m", e->contact_radius},
                           {"peak_force_n", e->peak_force},
                           {"contact_time_s", e->line_contact ? json(nullptr) : json(e->contact_time)},
                           {"contact_element_m", e->element_size},
                           {"elements_per_radius", e->elements_per_radius()}};
  if (impact_modes_[k] && impact_modes_[k]->report()) c["impact_modes"] = impact_modes_summary(*impact_modes_[k]->report());
  c["impulse_ns"] = impulse_[k];
  c["max_penetration_m"] = max_penetration_[k];
  const auto ratio = penetration_per_approach(max_penetration_[k], system_.impact_estimates()[k]);
  c["penetration_per_hertz_approach"] = ratio ? json(*ratio) : json(nullptr);
  c["penalty_too_soft"] = ratio && *ratio > kMaxPenetrationPerApproach;
  c["closed_at_end"] = closed_at_end(k);
  c["never_closed"] = list.empty();
  return c;
}

nlohmann::json Recorder::joint_summary(std::size_t k) const {
  using nlohmann::json;
  double peak_force = 0, peak_torque = 0, position_error = 0, angle_error = 0;
  for (std::size_t i = 0; i + 2 < joint_force_[k].size(); i += 3) {
    peak_force = std::max(peak_force, Eigen::Vector3d(&joint_force_[k][i]).norm());
    peak_torque = std::max(peak_torque, Eigen::Vector3d(&joint_torque_[k][i]).norm());
  }
  for (std::size_t i = 0; i + 1 < joint_error_[k].size(); i += 2)
    position_error = std::max(position_error, joint_error_[k][i]), angle_error = std::max(angle_error, joint_error_[k][i + 1]);
  json jt = {{"name", system_.joints().joints()[k].name()}, {"peak_force_n", peak_force}, {"peak_torque_n_m", peak_torque},
             {"max_position_error_m", position_error}, {"max_angle_error_rad", angle_error}};
  if (joint_force_[k].size() >= 3) {
    const std::size_t last = joint_force_[k].size() - 3;
    jt["final_force_n"] = {joint_force_[k][last], joint_force_[k][last + 1], joint_force_[k][last + 2]};
  }
  return jt;
}

nlohmann::json Recorder::body_summary(std::size_t body, const double* y) const {
  using nlohmann::json;
  const FloatingBody& b = *system_.bodies()[body];
  const Eigen::Vector3d v = b.v(y), w = b.omega(y), r = b.r(y);
  json entry = {{"name", b.name()},
                {"nq", b.nq()},
                {"quasistatic_modes", b.n_quasistatic()},
                {"final_position", {r.x(), r.y(), r.z()}},
                {"final_velocity", {v.x(), v.y(), v.z()}},
                {"final_angular_velocity", {w.x(), w.y(), w.z()}}};
  if (b.nq() > 0 && !body_q_[body].empty()) {  // of the last sample
    const Eigen::Map<const Eigen::VectorXd> q(body_q_[body].data() + body_q_[body].size() - std::size_t(b.nq()), b.nq());
    const Eigen::VectorXd E = b.modal_energies(q, b.qdot(y));
    entry["final_modal_energy_j"] = std::vector<double>(E.data(), E.data() + E.size());
  }
  return entry;
}

nlohmann::json Recorder::monitor_summary(std::size_t m) const {
  using nlohmann::json;
  const auto& v = monitor_values_[m];
  json mon = {{"name", scene_.monitors[m].name}, {"quantity", scene_.monitors[m].quantity}};
  if (!v.empty()) mon["final"] = {v[v.size() - 3], v[v.size() - 2], v[v.size() - 1]};
  mon["arrival_s"] = monitor_events_[m].arrival() >= 0 ? json(monitor_events_[m].arrival()) : json(nullptr);
  mon["reversal_s"] = monitor_events_[m].reversal() >= 0 ? json(monitor_events_[m].reversal()) : json(nullptr);
  return mon;
}

nlohmann::json Recorder::summary(const IntegratorStats& stats, const RunOutcome& outcome, const double* y) const {
  using nlohmann::json;
  json j;
  j["scene"] = scene_.file;
  j["provenance"] = to_json(provenance_);
  j["status"] = outcome.status;
  if (!outcome.failure.empty()) j["failure"] = outcome.failure;
  const double wall_time = outcome.wall_time_s;
  j["wall_time_s"] = wall_time;
  j["cpu_time_s"] = outcome.cpu_time_s;
  j["warnings"] = json::array();
  j["expected_warnings"] = json::array();
  for (const RunWarning& w : warnings()) add_warning(j, w, scene_.output.expected_warnings);
  j["end_time_s"] = time_.empty() ? 0.0 : time_.back();
  j["steps"] = stats.steps;
  j["rejected_steps"] = stats.attempts - stats.steps;
  j["restarted_steps"] = stats.restarts;
  j["rhs_evaluations"] = stats.rhs_evaluations;
  j["newton_iterations"] = stats.newton_iterations + system_.quasistatic_iterations();
  j["jacobian_setups"] = stats.jacobian_setups;
  j["time_per_step_s"] = stats.steps ? wall_time / double(stats.steps) : 0.0;
  const MultibodySystem::RhsCost& cost = system_.rhs_cost();
  j["time_split_s"] = {{"static_solve", cost.static_solve_s}, {"contacts", cost.contacts_s}, {"joints", cost.joints_s},
                       {"floating_frame", cost.floating_frame_s}, {"output", output_s_}};
  j["step_time_s"] = {{"loaded", step_time_.loaded_s},
                      {"loaded_steps", step_time_.loaded_steps},
                      {"unloaded", step_time_.unloaded_s},
                      {"unloaded_steps", step_time_.unloaded_steps}};
  j["rhs_cost"] = {{"evaluations", cost.evaluations},
                   {"repeated", cost.repeated},
                   {"quasistatic_passes", system_.quasistatic_passes()},
                   {"kept_contact_loads", cost.kept_contact_loads},
                   {"mean_active_points", cost.evaluations ? double(cost.active_points) / double(cost.evaluations) : 0.0}};
  j["contacts"] = json::array();
  for (std::size_t k = 0; k < system_.contacts().size(); ++k) j["contacts"].push_back(contact_summary(k));
  j["hertz_contacts"] = json::array();
  for (const HertzContactLog& h : hertz_logs_) j["hertz_contacts"].push_back(h.summary());
  j["joints"] = json::array();
  for (std::size_t k = 0; k < joint_force_.size(); ++k) j["joints"].push_back(joint_summary(k));
  j["bodies"] = json::array();
  for (std::size_t body = 0; body < system_.bodies().size(); ++body) j["bodies"].push_back(body_summary(body, y));
  const double e0 = energies_.empty() ? 0.0 : energies_.front()[5], e1 = energies_.empty() ? 0.0 : energies_.back()[5];
  const double energy_error = energy_error_per_motion();
  j["energy"] = {{"initial_j", e0}, {"final_j", e1}, {"max_rel_error", max_relative_energy_error()},
                 {"dissipated_j", energies_.empty() ? 0.0 : energies_.back()[4]},
                 {"error_per_energy_in_motion", energy_error}, {"error_too_large", energy_error > kMaxEnergyError}};
  j["monitors"] = json::array();
  for (std::size_t m = 0; m < monitor_values_.size(); ++m) j["monitors"].push_back(monitor_summary(m));
  for (const StressMonitor& s : stress_monitors_) j["monitors"].push_back(s.summary());
  j["reference"] = compare_with_reference(j, scene_.reference, scene_.reference_from_hertz);
  return j;
}

}  // namespace isosid::run

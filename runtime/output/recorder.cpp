// Recording and reporting a run; see recorder.hpp.
#include "output/recorder.hpp"

#include "output/warning_list.hpp"

#include "isosid/format/atomic_output.hpp"
#include "isosid/format/error.hpp"
#include "isosid/format/hdf5_file.hpp"
#include "contact/default_penalty.hpp"
#include "contact/deformed_patch.hpp"
#include "contact/impact_estimate.hpp"
#include "output/force_spectrum.hpp"
#include "output/paraview_series.hpp"
#include "output/reference_comparison.hpp"
#include "output/velocity_events.hpp"
#include "isosid/common/number_text.hpp"

#include <cmath>
#include <optional>

namespace isosid::run {

namespace {
/// A monitor on a master patch as a node: at a fixed parameter the patch point moves as
/// X(u) + Psi(u) q, with Psi = sum R_i Phi_i, exactly like a SID node.
format::Node surface_node(const FloatingBody& body, const MonitorSpec& m, const std::string& scene_file) {
  const std::string field = "monitor " + m.name;
  const format::ContactSurface* surface = body.contact_surface(m.surface);
  if (!surface) throw format::InputError(scene_file, field, "the SID of '" + m.body + "' has no contact surface '" + m.surface + "'");
  const format::MasterPatch* patch = format::find_master_patch(body.sid(), surface->master_patch);
  if (!patch) throw format::InputError(scene_file, field, "the SID of '" + m.body + "' has no master patch for '" + m.surface + "'");
  const int dim = body.sid().dim();
  const DeformedPatch geometry(*patch, dim);
  if (int(m.parameter.size()) != geometry.parameter_dim())
    throw format::InputError(scene_file, field + ".parameter", "needs " + std::to_string(geometry.parameter_dim()) + " value(s)");
  Eigen::Vector2d u = Eigen::Vector2d::Zero();
  for (int d = 0; d < geometry.parameter_dim(); ++d) {
    u(d) = m.parameter[std::size_t(d)];
    if (u(d) < geometry.lower(d) || u(d) > geometry.upper(d))
      throw format::InputError(scene_file, field + ".parameter", "outside the patch's parameter range");
  }
  DeformedPatch::Point point;
  geometry.evaluate(u, point);
  Eigen::MatrixXd Psi;
  geometry.shape_rows(point, Psi);
  format::Node node;
  node.name = m.name;
  node.origin.M0 = point.C;
  node.phi = Eigen::MatrixXd::Zero(3, body.nq());
  node.phi.topRows(dim) = Psi;
  return node;
}

/// The deepest penetration of a contact's points over its Hertz approach, or nullopt where the
/// estimate has none (line contact, no approach).
std::optional<double> penetration_per_approach(double max_penetration, const std::optional<ImpactEstimate>& estimate) {
  if (!estimate || !(estimate->approach > 0)) return std::nullopt;
  return max_penetration / estimate->approach;
}
}  // namespace

Recorder::Recorder(const MultibodySystem& system, const Scene& scene)
    : system_(system), scene_(scene), provenance_(run_provenance(scene)) {
  const std::size_t nc = system.contacts().size();
  contact_force_.resize(nc);
  contact_points_.resize(nc);
  contact_penetration_.resize(nc);
  body_q_.resize(system_.bodies().size());
  intervals_.resize(nc);
  touches_.resize(nc);
  peak_force_.assign(nc, 0);
  points_at_peak_.assign(nc, 0);
  edge_reached_.assign(nc, -1);
  interface_left_.assign(nc, -1);
  for (const HertzContact& h : system.hertz_contacts()) hertz_logs_.emplace_back(h);
  const std::size_t nj = system.joints().joints().size();
  joint_force_.resize(nj);
  joint_torque_.resize(nj);
  joint_error_.resize(nj);
  impulse_.assign(nc, 0);
  max_penetration_.assign(nc, 0);
  active_.assign(nc, false);
  last_force_.assign(nc, 0);
  monitor_nodes_.reserve(scene.monitors.size());
  for (const MonitorSpec& m : scene.monitors) {
    const FloatingBody& b = system.body(m.body);
    if (m.surface.empty()) {
      const format::Node* node = b.node(m.node);
      if (!node) throw format::InputError(scene.file, "monitor " + m.name, "the SID of '" + m.body + "' has no node '" + m.node + "'");
      monitor_nodes_.push_back(*node);
    } else {
      monitor_nodes_.push_back(surface_node(b, m, scene.file));
    }
    monitor_bodies_.push_back(&b);
    monitor_body_index_.push_back(system.body_index(m.body));
  }
  quasistatic_last_.resize(system.bodies().size());
  for (const auto& b : system.bodies()) quasistatic_rate_.push_back(Eigen::VectorXd::Zero(b->n_quasistatic()));
  for (const StressMonitorSpec& s : scene.stress_monitors) stress_monitors_.emplace_back(s, system.body(s.body), scene.file);
  impact_modes_.resize(nc);
  for (std::size_t k = 0; k < nc; ++k)
    if (const FloatingBody* target = system.contacts()[k].target().body())
      impact_modes_[k].emplace(system, int(k), *target, scene.contacts[k].target_surface);
  monitor_values_.resize(scene.monitors.size());
  monitor_events_.resize(scene.monitors.size());
}

void Recorder::sample(double t, const double* y) {
  const OutputClock clock(output_s_);
  // everything that may fail first (the quasistatic solve may not converge): a failed sample
  // adds nothing, and every series keeps one entry per time
  const auto states = system_.contact_states(y);  // also solves the quasistatic coordinates for y
  const auto hertz = system_.hertz_states(y);
  const auto joints = system_.joint_states(y);
  const Energies e = system_.energies(y, states);
  const bool first = time_.empty();
  if (first) update_quasistatic_rates(t, y);  // the start: no rate yet
  std::vector<Eigen::Vector3d> monitored;
  for (std::size_t m = 0; m < monitor_nodes_.size(); ++m) monitored.push_back(monitor_value(m, y));

  time_.push_back(t);
  body_states_.emplace_back(y, y + system_.size());
  for (std::size_t b = 0; b < body_q_.size(); ++b) {
    const Eigen::VectorXd& q = system_.bodies()[b]->q(y);
    body_q_[b].insert(body_q_[b].end(), q.data(), q.data() + q.size());
  }
  if (first) last_step_t_ = t;  // a run (or a later phase of one) starts here, not at 0
  for (std::size_t k = 0; k < states.size(); ++k) {
    if (first) last_force_[k] = states[k].force.norm();  // a phase may start loaded
    if (first && impact_modes_[k]) impact_modes_[k]->step(t, y, states[k].force.norm(), false);  // the start
    for (int a = 0; a < 3; ++a) contact_force_[k].push_back(states[k].force(a));
    contact_points_[k].push_back(states[k].active_points);
    contact_penetration_[k].push_back(states[k].max_penetration);
  }
  for (std::size_t k = 0; k < hertz.size(); ++k) hertz_logs_[k].sample(hertz[k]);
  for (std::size_t k = 0; k < joints.size(); ++k) {
    for (int a = 0; a < 3; ++a) joint_force_[k].push_back(joints[k].force(a)), joint_torque_[k].push_back(joints[k].torque(a));
    joint_error_[k].push_back(joints[k].position_error);
    joint_error_[k].push_back(joints[k].angle_error);
  }
  energies_.push_back({e.kinetic, e.elastic, e.gravity, e.penalty, e.dissipated, e.total()});
  for (std::size_t m = 0; m < monitor_nodes_.size(); ++m) {
    for (int a = 0; a < 3; ++a) monitor_values_[m].push_back(monitored[m](a));
    if (first) monitor_events_[m].start(t, monitored[m]);
  }
  for (StressMonitor& s : stress_monitors_) s.sample(y);
  if (frames_) frames_->sample(t, y);  // the quasistatic coordinates are y's (contact_states above)
}

void Recorder::step(double t, const double* y) {
  const OutputClock clock(output_s_);
  const auto states = system_.contact_states(y);
  const double dt = t - last_step_t_;
  for (std::size_t k = 0; k < states.size(); ++k) {
    const double f = states[k].force.norm();
    const bool new_peak = f > peak_force_[k];
    if (new_peak) peak_force_[k] = f, points_at_peak_[k] = states[k].active_points;
    if (impact_modes_[k]) impact_modes_[k]->step(t, y, f, new_peak);
    impulse_[k] += 0.5 * (f + last_force_[k]) * dt;  // trapezoid over accepted steps
    last_force_[k] = f;
    max_penetration_[k] = std::max(max_penetration_[k], states[k].max_penetration);
    if (states[k].edge_points > 0 && edge_reached_[k] < 0) edge_reached_[k] = t;
    if (states[k].outside_interface > 0 && interface_left_[k] < 0) interface_left_[k] = t;
  }
  const auto hertz = system_.hertz_states(y);
  for (std::size_t k = 0; k < hertz.size(); ++k) hertz_logs_[k].step(t, y, hertz[k]);
  update_quasistatic_rates(t, y);
  for (std::size_t m = 0; m < monitor_nodes_.size(); ++m) {
    if (scene_.monitors[m].quantity == "velocity") monitor_events_[m].add(t, monitor_value(m, y));
  }
  for (StressMonitor& s : stress_monitors_) s.step(t, y);
  last_step_t_ = t;
}

Eigen::Vector3d Recorder::monitor_value(std::size_t m, const double* y) const {
  const auto [position, velocity] =
      monitor_bodies_[m]->node_state(monitor_nodes_[m], y, &quasistatic_rate_[monitor_body_index_[m]]);
  return scene_.monitors[m].quantity == "velocity" ? velocity : position;
}

void Recorder::update_quasistatic_rates(double t, const double* y) {
  // after contact_states(y): the quasistatic coordinates are those solved for y
  for (std::size_t i = 0; i < system_.bodies().size(); ++i) {
    const FloatingBody& b = *system_.bodies()[i];
    if (b.n_quasistatic() == 0) continue;
    const auto now = b.q(y).tail(b.n_quasistatic());
    if (quasistatic_last_[i].size() == now.size() && t > quasistatic_last_t_)
      quasistatic_rate_[i] = (now - quasistatic_last_[i]) / (t - quasistatic_last_t_);
    quasistatic_last_[i] = now;  // resized once, then in place
  }
  quasistatic_last_t_ = t;
}

void Recorder::contact_event(int k, bool closing, double t) {
  // by the direction of the crossing, not by toggling: a root reported twice cannot
  // swap onset and release
  auto& list = intervals_[std::size_t(k)];
  if (closing && !active_[std::size_t(k)]) list.push_back({t, -1});
  if (!closing && active_[std::size_t(k)] && !list.empty()) list.back().end = t;
  active_[std::size_t(k)] = closing;
}

void Recorder::touch(int k, double t, const Touch& touch) { touches_[std::size_t(k)].emplace_back(t, touch); }

double Recorder::max_relative_energy_error() const {
  if (energies_.empty()) return 0;
  const double e0 = energies_.front()[5];
  double worst = 0;
  for (const auto& e : energies_) worst = std::max(worst, std::abs(e[5] - e0));
  return e0 != 0 ? worst / std::abs(e0) : worst;
}

double Recorder::energy_error_per_motion() const {
  if (energies_.empty()) return 0;
  const double e0 = energies_.front()[5];
  double worst = 0, motion = 0;
  for (const auto& e : energies_) {
    worst = std::max(worst, std::abs(e[5] - e0));
    motion = std::max(motion, e[0] + e[1] + e[3]);  // kinetic, elastic and penalty: independent of gravity's datum
  }
  return motion > 0 ? worst / motion : 0.0;
}

bool Recorder::closed_at_end(std::size_t k) const { return !intervals_[k].empty() && intervals_[k].back().end < 0; }

void Recorder::write_results(const std::string& path) const {
  format::AtomicOutput out(path);
  {
    format::h5::Writer w(out.temp_path());
    const auto n = Eigen::Index(time_.size());
    w.vector("/time", Eigen::Map<const Eigen::VectorXd>(time_.data(), n), "s");
    write_provenance(w, provenance_);
    for (std::size_t body = 0; body < system_.bodies().size(); ++body) {
      const FloatingBody* b = system_.bodies()[body].get();
      const std::string g = "/bodies/" + b->name();
      Eigen::MatrixXd r(n, 3), angles(n, 3), quat(n, 4), v(n, 3), w3(n, 3), q(n, b->nq()), qd(n, b->nq());
      for (Eigen::Index i = 0; i < n; ++i) {
        const double* y = body_states_[std::size_t(i)].data();
        r.row(i) = b->r(y).transpose();
        const Eigen::Quaterniond p = b->orientation(y);
        quat.row(i) << p.w(), p.x(), p.y(), p.z();
        angles.row(i) = tait_bryan_angles(p.toRotationMatrix()).transpose();
        v.row(i) = b->v(y).transpose();
        w3.row(i) = b->omega(y).transpose();
        q.row(i) = Eigen::Map<const Eigen::RowVectorXd>(body_q_[body].data() + i * b->nq(), b->nq());
        qd.row(i) = b->qdot(y).transpose();
      }
      w.group(g);
      w.matrix(g + "/position", r, "m");
      w.matrix(g + "/quaternion", quat, "1");
      w.matrix(g + "/tait_bryan", angles, "rad");
      w.matrix(g + "/velocity", v, "m/s");
      w.matrix(g + "/angular_velocity", w3, "rad/s");
      w.matrix(g + "/q", q, "[q]");
      w.matrix(g + "/qdot", qd, "[q]/s");
      Eigen::MatrixXd modal(n, b->nq() - b->sid().refmod.n_massless());
      for (Eigen::Index i = 0; i < n; ++i) modal.row(i) = b->modal_energies(q.row(i).transpose(), qd.row(i).transpose()).transpose();
      w.matrix(g + "/modal_energy", modal, "J");
    }
    for (std::size_t k = 0; k < system_.contacts().size(); ++k) {
      const std::string g = "/contacts/" + system_.contacts()[k].name();
      w.group(g);
      w.matrix(g + "/force", Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(contact_force_[k].data(), n, 3), "N");
      w.vector(g + "/active_points", Eigen::Map<const Eigen::VectorXd>(contact_points_[k].data(), n), "1");
      w.vector(g + "/max_penetration", Eigen::Map<const Eigen::VectorXd>(contact_penetration_[k].data(), n), "m");
      std::vector<double> magnitude(static_cast<std::size_t>(n));
      for (Eigen::Index i = 0; i < n; ++i) magnitude[std::size_t(i)] = Eigen::Vector3d(&contact_force_[k][std::size_t(3 * i)]).norm();
      const Spectrum spectrum = force_spectrum(time_, magnitude, scene_.simulation.output_interval);
      w.vector(g + "/spectrum_frequency", spectrum.frequency_hz, "Hz");
      w.vector(g + "/spectrum_amplitude", spectrum.amplitude_ns, "N s");
      if (impact_modes_[k] && impact_modes_[k]->report()) write_impact_modes(w, g + "/impact_modes", *impact_modes_[k]->report());
    }
    for (const HertzContactLog& h : hertz_logs_) h.write(w);
    for (std::size_t k = 0; k < joint_force_.size(); ++k) {
      using Rows3 = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
      using Rows2 = Eigen::Matrix<double, Eigen::Dynamic, 2, Eigen::RowMajor>;
      const std::string g = "/joints/" + system_.joints().joints()[k].name();
      w.group(g);
      w.matrix(g + "/force", Eigen::Map<const Rows3>(joint_force_[k].data(), n, 3), "N");
      w.matrix(g + "/torque", Eigen::Map<const Rows3>(joint_torque_[k].data(), n, 3), "N m");
      const Eigen::Map<const Rows2> error(joint_error_[k].data(), n, 2);
      w.vector(g + "/position_error", error.col(0), "m");
      w.vector(g + "/angle_error", error.col(1), "rad");
    }
    Eigen::MatrixXd e(n, 6);
    for (Eigen::Index i = 0; i < n; ++i)
      for (int c = 0; c < 6; ++c) e(i, c) = energies_[std::size_t(i)][std::size_t(c)];
    w.group("/energy");
    const char* names[6] = {"kinetic", "elastic", "gravity", "penalty", "dissipated", "total"};
    for (int c = 0; c < 6; ++c) w.vector(std::string("/energy/") + names[c], e.col(c), "J");
    for (std::size_t m = 0; m < monitor_values_.size(); ++m) {
      const std::string g = "/monitors/" + scene_.monitors[m].name;
      w.matrix(g, Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(monitor_values_[m].data(), n, 3),
               scene_.monitors[m].quantity == "velocity" ? "m/s" : "m");
    }
    for (const StressMonitor& s : stress_monitors_)
      w.matrix("/monitors/" + s.name(),
               Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(s.samples().data(), n, s.points()),
               "Pa");
    w.close();
  }
  out.commit();
}

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

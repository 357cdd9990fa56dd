// Recording and reporting a run; see recorder.hpp.
#include "output/recorder.hpp"


#include "isosid/format/atomic_output.hpp"
#include "isosid/format/error.hpp"
#include "isosid/format/hdf5_file.hpp"
#include "contact/deformed_patch.hpp"
#include "output/force_spectrum.hpp"
#include "output/velocity_events.hpp"

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
  if (first) last_step_t_ = t, step_time_.start();  // a run (or a later phase of one) starts here, not at 0
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
}

void Recorder::step(double t, const double* y) {
  const OutputClock clock(output_s_);
  const auto states = system_.contact_states(y);
  const double dt = t - last_step_t_;
  bool loaded = false;
  for (std::size_t k = 0; k < states.size(); ++k) {
    const double f = states[k].force.norm();
    loaded = loaded || f > 0;
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
  for (std::size_t k = 0; k < hertz.size(); ++k) {
    hertz_logs_[k].step(t, y, hertz[k]);
    loaded = loaded || hertz[k].force.norm() > 0;
  }
  update_quasistatic_rates(t, y);
  for (std::size_t m = 0; m < monitor_nodes_.size(); ++m) {
    if (scene_.monitors[m].quantity == "velocity") monitor_events_[m].add(t, monitor_value(m, y));
  }
  for (StressMonitor& s : stress_monitors_) s.step(t, y);
  last_step_t_ = t;
  step_time_.add(loaded);
}

void Recorder::StepTime::add(bool loaded) {
  const auto now = std::chrono::steady_clock::now();
  if (started) {
    const double seconds = std::chrono::duration<double>(now - last).count();
    (loaded ? loaded_s : unloaded_s) += seconds;
    ++(loaded ? loaded_steps : unloaded_steps);
  }
  last = now, started = true;
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

}  // namespace isosid::run

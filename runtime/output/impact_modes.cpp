// Modal energies, modal restitution and bending-mode labels of an impact; see impact_modes.hpp.
#include "output/impact_modes.hpp"

#include <Eigen/Cholesky>
#include <cmath>
#include <exception>

namespace isosid::run {

ImpactModes::ImpactModes(const MultibodySystem& system, int contact, const FloatingBody& target, std::string target_surface)
    : system_(system), contact_(contact), target_(target), target_surface_(std::move(target_surface)) {}

void ImpactModes::step(double t, const double* y, double force, bool new_peak) {
  const std::size_t n = std::size_t(system_.size());
  if (phase_ == Phase::Before && force <= 0) before_.assign(y, y + n), t_before_ = t;
  else if (phase_ == Phase::Before) phase_ = Phase::In, peak_.assign(y, y + n);
  else if (phase_ == Phase::In && force > 0 && new_peak) peak_.assign(y, y + n);
  else if (phase_ == Phase::In && force <= 0) phase_ = Phase::Done, after_.assign(y, y + n), t_after_ = t;
}

const std::optional<ImpactModes::Report>& ImpactModes::report() const {
  if (phase_ != Phase::Done || evaluated_) return report_;
  evaluated_ = true;
  try {
    report_ = evaluate();
  } catch (const std::exception&) {  // the quasistatic solve of a kept state failed: no report
    report_.reset();
  }
  return report_;
}

std::optional<ImpactModes::Report> ImpactModes::evaluate() const {
  if (before_.empty()) return std::nullopt;
  const SurfaceContact& contact = system_.contacts()[std::size_t(contact_)];
  const FloatingBody& slave = contact.body();
  const format::ContactSurface* surface = target_.contact_surface(target_surface_);
  if (!surface) return std::nullopt;
  const int dim = target_.sid().dim();
  Report out;
  out.target = target_.name();
  out.start_s = t_before_;
  out.end_s = t_after_;

  // before the onset: the impact direction and the slave's energy
  const Eigen::Vector3d approach = slave.v(before_.data()) - target_.v(before_.data());
  if (approach.norm() == 0) return std::nullopt;
  out.direction = approach.normalized();
  out.approach_speed = slave.v(before_.data()).dot(out.direction);
  if (!(out.approach_speed > 0)) return std::nullopt;  // a target running into a receding slave
  out.kinetic_energy_j = 0.5 * slave.sid().refmod.mass * out.approach_speed * out.approach_speed;

  // at the peak: the force centroid, and the target's contact point nearest to it
  system_.contact_states(peak_.data());  // solves the quasistatic coordinates for the point loads
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  double total = 0;
  for (const PointLoad& load : contact.point_loads(peak_.data())) {
    centroid += load.force.norm() * load.position;
    total += load.force.norm();
  }
  if (total <= 0) return std::nullopt;
  centroid /= total;
  const Eigen::Vector3d local = target_.orientation(peak_.data()).toRotationMatrix().transpose() * (centroid - target_.r(peak_.data()));
  Eigen::Index nearest = 0;
  (surface->position.rowwise() - local.head(dim).transpose()).rowwise().squaredNorm().minCoeff(&nearest);
  out.point.setZero();
  out.point.head(dim) = surface->position.row(nearest).transpose();

  // after the release: modal energies and velocities
  system_.contact_states(after_.data());
  const Eigen::VectorXd q = target_.q(after_.data()), qdot = target_.qdot(after_.data());
  const Eigen::VectorXd energy = target_.modal_energies(q, qdot);
  out.separation_velocity = slave.v(after_.data()).dot(out.direction);
  const Eigen::Vector3d d = target_.orientation(after_.data()).toRotationMatrix().transpose() * out.direction;

  // phi_k(P) along d, the quasistatic (or massless) coordinates following mode k statically:
  // u_h = -K_hh^-1 K_hk
  const Eigen::Index n = target_.n_dynamic(), nh = target_.nq() - n;
  const Eigen::MatrixXd Psi = surface->Psi.middleRows(nearest * dim, dim);
  Eigen::RowVectorXd phi_d = d.head(dim).transpose() * Psi.leftCols(n);
  if (nh > 0) {
    const Eigen::MatrixXd& K = target_.sid().Ke.M0;
    const Eigen::MatrixXd follow = -K.bottomRightCorner(nh, nh).ldlt().solve(K.bottomLeftCorner(nh, n));
    phi_d += d.head(dim).transpose() * Psi.rightCols(nh) * follow;
  }

  // bending modes in d: sections translating along d with most of the mode's kinetic energy
  const format::RefMod& refmod = target_.sid().refmod;
  const bool labelled = refmod.section_translation.rows() == target_.nq() && std::abs(refmod.long_axis.dot(d)) < 0.5;
  int bending = 0;
  for (Eigen::Index k = 0; k < n && k < energy.size(); ++k) {
    Mode m;
    m.index = int(k);
    m.frequency_hz = refmod.frequencies_hz(k);
    m.energy_ratio = energy(k) / out.kinetic_energy_j;
    m.restitution = -(out.separation_velocity - phi_d(k) * qdot(k)) / out.approach_speed;
    if (labelled && refmod.section_translation.row(k).dot(d.cwiseAbs2().transpose()) >= 0.5) m.label = std::to_string(++bending) + "F";
    out.modes.push_back(m);
  }
  return out;
}

nlohmann::json impact_modes_summary(const ImpactModes::Report& r) {
  nlohmann::json modes = nlohmann::json::array();
  double total = 0;
  for (const ImpactModes::Mode& m : r.modes) {
    total += m.energy_ratio;
    modes.push_back({{"index", m.index}, {"frequency_hz", m.frequency_hz}, {"label", m.label.empty() ? nlohmann::json(nullptr) : nlohmann::json(m.label)},
                     {"energy_ratio", m.energy_ratio}, {"restitution", m.restitution}});
  }
  return {{"target", r.target},
          {"start_s", r.start_s},
          {"end_s", r.end_s},
          {"kinetic_energy_j", r.kinetic_energy_j},
          {"direction", {r.direction.x(), r.direction.y(), r.direction.z()}},
          {"approach_speed_m_s", r.approach_speed},
          {"separation_velocity_m_s", r.separation_velocity},
          {"point_m", {r.point.x(), r.point.y(), r.point.z()}},
          {"energy_ratio_total", total},
          {"modes", modes}};
}

void write_impact_modes(format::h5::Writer& w, const std::string& g, const ImpactModes::Report& r) {
  const auto n = Eigen::Index(r.modes.size());
  Eigen::VectorXd f(n), energy(n), restitution(n);
  Eigen::VectorXi index(n);
  std::vector<std::string> labels;
  for (Eigen::Index k = 0; k < n; ++k) {
    const ImpactModes::Mode& m = r.modes[std::size_t(k)];
    f(k) = m.frequency_hz, energy(k) = m.energy_ratio, restitution(k) = m.restitution, index(k) = m.index;
    labels.push_back(m.label);
  }
  w.group(g);
  w.string(g + "/target", r.target);
  w.integers(g + "/index", index);
  w.vector(g + "/frequency_hz", f, "Hz");
  w.vector(g + "/energy_ratio", energy, "1");
  w.vector(g + "/restitution", restitution, "1");
  w.strings(g + "/label", labels);
  w.scalar(g + "/start_s", r.start_s, "s");
  w.scalar(g + "/end_s", r.end_s, "s");
  w.scalar(g + "/kinetic_energy", r.kinetic_energy_j, "J");
  w.vector(g + "/direction", r.direction, "1");
  w.scalar(g + "/approach_speed", r.approach_speed, "m/s");
  w.scalar(g + "/separation_velocity", r.separation_velocity, "m/s");
  w.vector(g + "/point", r.point, "m");
}

}  // namespace isosid::run

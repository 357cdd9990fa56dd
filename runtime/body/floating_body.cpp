// Floating-frame equations of motion from SID terms; see floating_body.hpp.
#include "body/floating_body.hpp"

#include "isosid/format/error.hpp"
#include "isosid/format/skew.hpp"

#include <algorithm>
#include <cmath>

namespace isosid::run {

using Eigen::Index;
using Eigen::Matrix3d;
using Eigen::MatrixXd;
using Eigen::Vector3d;
using Eigen::VectorXd;
using format::skew;

std::array<bool, 6> locked_dofs(Dimension dimension, const std::vector<std::string>& locked) {
  std::array<bool, 6> out{};
  if (dimension == Dimension::Axisymmetric) out = {true, false, true, true, true, true};  // only along the axis
  if (dimension == Dimension::Planar) out = {false, false, true, true, true, false};      // in the x-y plane
  for (const std::string& l : locked)
    for (std::size_t i = 0; i < out.size(); ++i)
      if (l == kFrameDofNames[i]) out[i] = true;
  return out;
}

Matrix3d tait_bryan_matrix(const Vector3d& a) {
  return (Eigen::AngleAxisd(a.x(), Vector3d::UnitX()) * Eigen::AngleAxisd(a.y(), Vector3d::UnitY()) *
          Eigen::AngleAxisd(a.z(), Vector3d::UnitZ()))
      .toRotationMatrix();
}

Vector3d tait_bryan_angles(const Matrix3d& A) {
  const double beta = std::asin(std::clamp(A(0, 2), -1.0, 1.0));
  return {std::atan2(-A(1, 2), A(2, 2)), beta, std::atan2(-A(0, 1), A(0, 0))};
}

namespace {
/// The SID's inertia terms involve only the first m coordinates: every term is exactly zero
/// in the rows, blocks and first-order coefficients of the others (a massless boundary as
/// isosid-prep writes it; a SID from elsewhere may not, and is then evaluated in full).
bool inertia_only_in_leading(const format::Sid& s, Index m) {
  auto zero_after = [m](const format::Taylor& t, Index row_block, Index col_block) {
    auto tail_zero = [&](const MatrixXd& A) {
      return (row_block == 0 || A.bottomRows(A.rows() - row_block * m).isZero(0.0)) &&
             (col_block == 0 || A.rightCols(A.cols() - col_block * m).isZero(0.0));
    };
    if (!tail_zero(t.M0)) return false;
    for (std::size_t j = 0; j < t.M1.size(); ++j)
      if (Index(j) >= m ? !t.M1[j].isZero(0.0) : !tail_zero(t.M1[j])) return false;
    return true;
  };
  // row_block / col_block: 1 where rows / columns run over the coordinates (3 per coordinate for 3 x 3nq terms)
  return zero_after(s.mdCM, 0, 0) && zero_after(s.J, 0, 0) && zero_after(s.Ct, 1, 0) && zero_after(s.Cr, 1, 0) &&
         zero_after(s.Gr, 0, 3) && zero_after(s.Ge, 1, 3) && zero_after(s.Oe, 1, 0);
}
}  // namespace

FloatingBody::FloatingBody(const BodySpec& spec, format::Sid sid, Dimension dimension)
    : name_(spec.name), sid_(std::move(sid)), spec_(spec), stiffness_(sid_.Ke.M0), damping_(sid_.De.M0),
      B_(sid_.nq(), 6), hq_(sid_.nq()) {
  const Index n = nq();
  // the Schur-complement solve below relies on the SID's normal form Me = I (a MacNeal SID:
  // I on the modes, zero on the massless boundary)
  const Index massless = sid_.refmod.n_massless();
  MatrixXd normal_form = MatrixXd::Identity(n, n);
  normal_form.bottomRightCorner(massless, massless).setZero();
  if (n > 0 && (sid_.Me.M0 - normal_form).cwiseAbs().maxCoeff() > 1e-8)
    throw format::InputError(spec.sid_file, "/terms/Me/M0",
                             massless ? "the runtime needs mass-normalized modes and a massless boundary (Me = diag(I, 0))"
                                      : "the runtime needs mass-normalized modes (Me = I)");
  const bool axisymmetric_sid = sid_.analysis == format::AnalysisType::Axisymmetric;
  if ((dimension == Dimension::Axisymmetric) != axisymmetric_sid)
    throw format::InputError(spec.sid_file, "/body/analysis_type",
                             "a " + format::to_string(sid_.analysis) + " body in a " + to_string(dimension) + " scene");
  if (dimension == Dimension::Planar && sid_.dim() != 2)
    throw format::InputError(spec.sid_file, "/body/analysis_type", "a solid body in a planar scene");
  locked_ = locked_dofs(dimension, spec.locked);
  rotates_ = !(locked_[3] && locked_[4] && locked_[5]);
  // coordinates without mass cannot be integrated: a massless boundary is always solved statically
  n_dynamic_ = n - massless;
  if (spec.high_modes == "quasistatic") {
    n_dynamic_ = sid_.refmod.n_low;
    if (spec.quasistatic_above_hz > 0) {
      n_dynamic_ = 0;
      while (n_dynamic_ < n - massless && sid_.refmod.frequencies_hz(n_dynamic_) <= spec.quasistatic_above_hz) ++n_dynamic_;
    }
  }
  // the massless boundary carries no inertia: the floating-frame terms (quadratic in nq)
  // then run over the modes alone (the beam of [R3], docs/references.md: 40 of 283 coordinates)
  n_inertial_ = massless > 0 && inertia_only_in_leading(sid_, n - massless) ? n - massless : n;
  B_.setZero();  // rows beyond n_inertial_ stay zero
  if (rotates_ && !sid_.Oe.M1.empty()) {
    const Index ni = std::min(n_inertial_, Index(sid_.Oe.M1.size()));
    oe1_.resize(n_inertial_, 6 * ni);  // rows beyond n_inertial_ carry no inertia
    for (Index j = 0; j < ni; ++j) oe1_.middleCols(6 * j, 6) = sid_.Oe.M1[std::size_t(j)].topRows(n_inertial_);
  }
  form_rotation_bound();
  // in the normal form Ke's off-diagonal entries are round-off, dropped as ModalMatrix drops
  // them: the integrated modes couple to the quasistatic ones only beyond its diagonal rows
  const MatrixXd coupling = sid_.Ke.M0.bottomLeftCorner(n - n_dynamic_, n_dynamic_);
  if (stiffness_.diagonal_rows() < n_dynamic_ && !coupling.isZero(0.0)) quasistatic_coupling_ = coupling;
  // all of Ke dense (nothing dropped as round-off): its energy through the held block's condensation
  if (quasistatic_coupling_.size() && stiffness_.diagonal_rows() == 0) condensed_energy_ = CondensedEnergy::of(sid_.Ke.M0, n_dynamic_);
  // a held frame neither moves nor turns: gravity alone loads the quasistatic modes through Ct
  // (a clamped SID's modes; a free-free SID's normal modes have Ct = 0). A frame that turns
  // about a held origin would also load them by -Cr_h dw/dt, which the static solve does not know.
  if (locked_[0] && locked_[1] && locked_[2] && !rotates_) {
    const MatrixXd gravity_rows = sid_.Ct.M0.bottomRows(n - n_dynamic_);
    if (!gravity_rows.isZero(0.0)) held_gravity_rows_ = gravity_rows;
  }
  q_full_ = VectorXd::Zero(n);
  qdot_full_ = VectorXd::Zero(n);
  if (spec.q0.size() && spec.q0.size() != n_dynamic_)
    throw format::InputError(spec.sid_file, spec.name + ".q0", "needs " + std::to_string(n_dynamic_) + " entries (the integrated modes)");
  if (spec.qdot0.size() && spec.qdot0.size() != n_dynamic_)
    throw format::InputError(spec.sid_file, spec.name + ".qdot0", "needs " + std::to_string(n_dynamic_) + " entries (the integrated modes)");
}

void FloatingBody::initial_state(double* y) const {
  double* s = y + offset_;
  Eigen::Map<Vector3d>(s + 0) = spec_.position;
  const Eigen::Quaterniond p(tait_bryan_matrix(spec_.tait_bryan));
  s[3] = p.w(), s[4] = p.x(), s[5] = p.y(), s[6] = p.z();
  const Index nd = n_dynamic_;
  Eigen::Map<VectorXd>(s + 7, nd) = spec_.q0.size() ? spec_.q0 : VectorXd::Zero(nd);
  if (spec_.elastic_start == "steady" && nd > 0) {
    // in equilibrium with the initial spin: Ke q = -Oe(0) w^2 (first order in q), so a
    // spinning body does not start ringing
    VectorXd load = VectorXd::Zero(nd);
    add_rotation_loads(VectorXd::Zero(nq()), VectorXd::Zero(nq()), spec_.angular_velocity, 0, load);
    Eigen::Map<VectorXd>(s + 7, nd) = sid_.Ke.M0.topLeftCorner(nd, nd).ldlt().solve(load);
  }
  Vector3d v = spec_.velocity, w = spec_.angular_velocity;
  for (int a = 0; a < 3; ++a) {
    if (locked_[std::size_t(a)]) v(a) = 0;
    if (locked_[std::size_t(3 + a)]) w(a) = 0;
  }
  Eigen::Map<Vector3d>(s + 7 + nd) = v;
  Eigen::Map<Vector3d>(s + 10 + nd) = w;
  Eigen::Map<VectorXd>(s + 13 + nd, nd) = spec_.qdot0.size() ? spec_.qdot0 : VectorXd::Zero(nd);
}

const VectorXd& FloatingBody::q(const double* y) const {
  q_full_.head(n_dynamic_) = Eigen::Map<const VectorXd>(y + offset_ + 7, n_dynamic_);
  return q_full_;  // its tail: the quasistatic modes as set
}

const VectorXd& FloatingBody::qdot(const double* y) const {
  qdot_full_.head(n_dynamic_) = Eigen::Map<const VectorXd>(y + offset_ + 13 + n_dynamic_, n_dynamic_);
  return qdot_full_;  // quasistatic modes: zero
}

Eigen::Quaterniond FloatingBody::orientation(const double* y) const {
  const double* p = y + offset_ + 3;
  return Eigen::Quaterniond(p[0], p[1], p[2], p[3]).normalized();
}

double FloatingBody::derivatives(const double* y, const GeneralizedForce& applied, const Vector3d& gravity, double* ydot) const {
  const Index nd = n_dynamic_;
  const VectorXd& qv = q(y);
  const VectorXd& qd = qdot(y);
  const Vector3d w = omega(y);
  const Eigen::Quaterniond p = orientation(y);
  const Matrix3d A = p.toRotationMatrix();
  double* d = ydot + offset_;

  // kinematics: r' = v, p' = 1/2 p (0, omega) with a pull back onto |p| = 1, q' = qdot
  Eigen::Map<Vector3d>(d + 0) = v(y);
  const double* pr = y + offset_ + 3;
  const double norm2 = pr[0] * pr[0] + pr[1] * pr[1] + pr[2] * pr[2] + pr[3] * pr[3];
  const Eigen::Quaterniond pdot = Eigen::Quaterniond(pr[0], pr[1], pr[2], pr[3]) * Eigen::Quaterniond(0, w.x(), w.y(), w.z());
  const double k = 10.0 * (1.0 - norm2) * std::max(1.0, w.norm());  // drift correction
  d[3] = 0.5 * pdot.w() + k * pr[0], d[4] = 0.5 * pdot.x() + k * pr[1], d[5] = 0.5 * pdot.y() + k * pr[2],
  d[6] = 0.5 * pdot.z() + k * pr[3];
  Eigen::Map<VectorXd>(d + 7, nd) = qd.head(nd);

  // mass matrix blocks at q (SID Taylor terms), into the preallocated workspace: the
  // right-hand side runs millions of times and must not allocate
  const double m = sid_.refmod.mass;
  const Index ni = n_inertial_, nv = std::min(nd, ni);
  Vector3d mc;
  Matrix3d J;
  MatrixXd& B = B_;  // [Ct, Cr], each evaluated in place
  auto Ct = B.leftCols(3), Cr = B.rightCols(3);
  inertia_at(qv, mc, Ct, Cr, J);
  Eigen::Matrix<double, 6, 6> A6 = Eigen::Matrix<double, 6, 6>::Zero();
  A6.topLeftCorner<3, 3>() = m * Matrix3d::Identity();
  A6.topRightCorner<3, 3>() = skew(mc).transpose();
  A6.bottomLeftCorner<3, 3>() = skew(mc);
  A6.bottomRightCorner<3, 3>() = J;

  // right-hand side h = h_omega + h_g - h_e + applied (body components)
  const Vector3d gK = A.transpose() * gravity;
  Eigen::Matrix<double, 6, 1> hr;
  hr.head<3>() = m * gK + applied.force;
  hr.tail<3>() = mc.cross(gK) + applied.torque;
  auto hq = hq_.head(nd);  // the integrated modes' rows (the quasistatic ones are the static solve's)
  hq = applied.elastic.head(nd) - sid_.ksigma.M0.col(0).head(nd);
  stiffness_.subtract_product(qv, hq);
  damping_.subtract_product(qd, hq);
  hq.noalias() += B.topLeftCorner(nd, 3) * gK;  // Ct g: gravity on the modes
  if (rotates_) {
    const Matrix3d W = skew(w);
    Vector3d Ct_qdot;
    Ct_qdot.noalias() = Ct.topRows(nv).transpose() * qd.head(nv);  // into a fixed vector: no temporary
    hr.head<3>() += -W * W * mc - 2 * W * Ct_qdot;
    // Gr(q, qdot) = sum_k (Gr0_k + sum_j Gr1_kj q_j) qdot_k. The 3x3 blocks of a 3 x 3nq term
    // are consecutive 9-vectors, so each sum over k is one 9 x nq matrix-vector product
    // (the order-1 part reads 9 nq^2 numbers per call: this is the floating frame's largest term)
    // Only the leading nv coordinates have velocities (quasistatic modes have none): the
    // products stop there.
    using Blocks = Eigen::Map<const Eigen::Matrix<double, 9, Eigen::Dynamic>>;
    Eigen::Matrix<double, 9, 1> gr = Blocks(sid_.Gr.M0.data(), 9, nv) * qd.head(nv);
    for (Index j = 0; j < std::min<Index>(ni, Index(sid_.Gr.M1.size())); ++j)
      if (qv(j) != 0) gr.noalias() += qv(j) * (Blocks(sid_.Gr.M1[std::size_t(j)].data(), 9, nv) * qd.head(nv));
    const Eigen::Map<const Matrix3d> Gr(gr.data());
    hr.tail<3>() += -W * (J * w) - Gr * w;
    add_rotation_loads(qv, qd, w, 0, hq);
  }

  // the rigid DOFs' Schur complement A6 - B^T B (Me = I), over the dynamic modes only
  // (quasistatic modes carry no inertia)
  const auto Bd = B.topRows(nd);
  Eigen::Matrix<double, 6, 6> S = A6;
  S.noalias() -= Bd.transpose() * Bd;
  int free_dofs[6], nf = 0;
  for (int i = 0; i < 6; ++i)
    if (!locked_[std::size_t(i)]) free_dofs[nf++] = i;
  // kept for load_response(): the mass matrix at y, factored once
  mass_.free = nf;
  for (int i = 0; i < nf; ++i) mass_.free_dofs[i] = free_dofs[i];
  if (nf > 0) {
    MassFactor::Small Sf(nf, nf);
    for (int i = 0; i < nf; ++i)
      for (int j = 0; j < nf; ++j) Sf(i, j) = S(free_dofs[i], free_dofs[j]);
    mass_.S.compute(Sf);
  }
  mass_.A = A;
  accelerations_from(hr, hq, d);
  return damping_.quadratic_form(qd);
}

void FloatingBody::accelerations_from(const Eigen::Matrix<double, 6, 1>& hr, const Eigen::Ref<const VectorXd>& hd, double* d) const {
  // with Me = I: (A6 - B^T B) x = hr - B^T hd on the unlocked rigid DOFs, then qddot = hd - B x
  const Index nd = n_dynamic_;
  Eigen::Matrix<double, 6, 1> rhs = hr;
  const auto Bd = B_.topRows(nd);  // [Ct, Cr] as derivatives() evaluated them (nothing else writes B_)
  rhs.noalias() -= Bd.transpose() * hd;
  Eigen::Matrix<double, 6, 1> x = Eigen::Matrix<double, 6, 1>::Zero();
  if (mass_.free > 0) {
    MassFactor::SmallVector rf(mass_.free);
    for (int i = 0; i < mass_.free; ++i) rf(i) = rhs(mass_.free_dofs[i]);
    const MassFactor::SmallVector xf = mass_.S.solve(rf);
    for (int i = 0; i < mass_.free; ++i) x(mass_.free_dofs[i]) = xf(i);
  }
  Eigen::Map<Vector3d>(d + 7 + nd) = mass_.A * x.head<3>();  // v' = A a_K
  Eigen::Map<Vector3d>(d + 10 + nd) = x.tail<3>();
  Eigen::Map<VectorXd> qddot(d + 13 + nd, nd);
  qddot = hd;
  qddot.noalias() -= Bd * x;
}

void FloatingBody::load_response(const GeneralizedForce& load, double* ydot) const {
  Eigen::Matrix<double, 6, 1> hr;
  hr << load.force, load.torque;
  accelerations_from(hr, load.elastic.head(n_dynamic_), ydot + offset_);
}

void FloatingBody::add_quasistatic_loads(const double* y, const Vector3d& gravity, Eigen::Ref<VectorXd> out) const {
  add_uncoupled_quasistatic_loads(y, gravity, out);
  if (quasistatic_coupling_.size()) out.noalias() -= quasistatic_coupling_ * q(y).head(n_dynamic_);
}

bool FloatingBody::add_uncoupled_quasistatic_loads(const double* y, const Vector3d& gravity, Eigen::Ref<VectorXd> out) const {
  const bool rotation = add_rotation_loads(q(y), qdot(y), omega(y), n_dynamic_, out);
  // a held frame's weight on the modes: none in a scene without gravity, whose modes then rest
  // at zero between impacts without a solve
  const bool weight = held_gravity_rows_.size() > 0 && !gravity.isZero(0.0);
  if (weight) out.noalias() += held_gravity_rows_ * (orientation(y).toRotationMatrix().transpose() * gravity);
  return rotation || weight;
}

Eigen::VectorXd FloatingBody::modal_energies(const VectorXd& qv, const VectorXd& qd) const {
  const Index n = nq() - sid_.refmod.n_massless();
  const Eigen::ArrayXd omega = 2 * M_PI * sid_.refmod.frequencies_hz.head(n).array();
  return 0.5 * (qd.head(n).array().square() + omega.square() * qv.head(n).array().square()).matrix();
}

void FloatingBody::inertia_at(const VectorXd& qv, Vector3d& mc, Eigen::Ref<MatrixXd> Ct, Eigen::Ref<MatrixXd> Cr, Matrix3d& J) const {
  // the rows of the coordinates with velocities (nv: quasistatic modes and a massless boundary
  // have none) from the coefficients that carry inertia (ni), so the terms cost O(ni nv) and
  // not O(nq^2)
  const Index ni = n_inertial_, nv = std::min(n_dynamic_, ni);
  sid_.mdCM.evaluate(qv, mc, ni, 3);
  sid_.Ct.evaluate(qv, Ct, ni, nv);
  if (rotates_) {
    sid_.Cr.evaluate(qv, Cr, ni, nv);
    sid_.J.evaluate(qv, J, ni, 3);
  } else {  // a frame that cannot turn: its rotation's coupling is never read
    Cr.setZero();
    J = sid_.J.M0;
  }
}

double FloatingBody::kinetic_energy(const double* y) const {
  const VectorXd& qv = q(y);
  const VectorXd& qd = qdot(y);
  const Vector3d vK = orientation(y).toRotationMatrix().transpose() * v(y), w = omega(y);
  const Index nv = std::min(n_dynamic_, n_inertial_);
  Vector3d mc;
  Matrix3d J;
  Eigen::Matrix<double, Eigen::Dynamic, 3> Ct(nv, 3), Cr(nv, 3);
  inertia_at(qv, mc, Ct, Cr, J);
  const auto qdv = qd.head(nv);
  double T = 0.5 * sid_.refmod.mass * vK.squaredNorm() + 0.5 * qdv.squaredNorm() + vK.dot(Ct.transpose() * qdv);
  if (rotates_) T += 0.5 * w.dot(J * w) + vK.dot(skew(mc).transpose() * w) + w.dot(Cr.transpose() * qdv);
  return T;
}

double FloatingBody::elastic_energy(const double* y) const {
  const VectorXd& qv = q(y);
  return condensed_energy_ ? (*condensed_energy_)(qv) : 0.5 * stiffness_.quadratic_form(qv);
}

double FloatingBody::gravity_potential(const double* y, const Vector3d& gravity) const {
  const Vector3d mc = sid_.mdCM.at(q(y));
  return -gravity.dot(sid_.refmod.mass * r(y) + orientation(y).toRotationMatrix() * mc);
}

Vector3d FloatingBody::point_velocity(const Vector3d& P, const Eigen::Ref<const MatrixXd>& Psi, const double* y) const {
  Vector3d u = Vector3d::Zero();
  u.head(Psi.rows()).noalias() = Psi * qdot(y);
  return v(y) + orientation(y).toRotationMatrix() * (omega(y).cross(P) + u);
}

Vector3d FloatingBody::rigid_point_velocity(const Vector3d& P, const double* y) const {
  return v(y) + orientation(y).toRotationMatrix() * omega(y).cross(P);
}

void FloatingBody::apply_force(const Vector3d& F_world, const Vector3d& P, const Eigen::Ref<const MatrixXd>& Psi,
                               const Matrix3d& A, GeneralizedForce& f) const {
  const Vector3d FK = A.transpose() * F_world;
  f.force += FK;
  f.torque += P.cross(FK);
  // the integrated rows only: the equations read no others (the static solve forms the
  // quasistatic modes' contact loads itself), and a ball integrates 6 of its 36 modes
  const Index rows = std::min(n_dynamic_, Psi.cols());
  add_elastic_force(Psi.leftCols(rows), FK, f.elastic.head(rows));
}

std::pair<Vector3d, Vector3d> FloatingBody::node_state(const format::Node& node, const double* y, const VectorXd* quasistatic_rate) const {
  const Matrix3d A = orientation(y).toRotationMatrix();
  const Vector3d P = node.origin.M0.col(0) + node.phi * q(y);
  Vector3d elastic = node.phi * qdot(y);
  if (quasistatic_rate && quasistatic_rate->size() == n_quasistatic()) elastic += node.phi.rightCols(n_quasistatic()) * *quasistatic_rate;
  const Vector3d vel = v(y) + A * (omega(y).cross(P) + elastic);
  return {r(y) + A * P, vel};
}

const format::Node* FloatingBody::node(const std::string& name) const {
  for (const auto& n : sid_.nodes)
    if (n.name == name) return &n;
  return nullptr;
}

const format::ContactSurface* FloatingBody::contact_surface(const std::string& name) const {
  for (const auto& c : sid_.contact_surfaces)
    if (c.name == name) return &c;
  return nullptr;
}

}  // namespace isosid::run

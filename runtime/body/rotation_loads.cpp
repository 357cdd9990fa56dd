// The rotation loads on a body's quasistatic modes (-Ge(qdot) w - Oe(q) w^2) and the bound
// that leaves out their terms too small to move a point by its position resolution; see
// floating_body.hpp.
#include "body/floating_body.hpp"

#include "isosid/common/dense_decompositions.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace isosid::run {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::Vector3d;
using Eigen::VectorXd;

namespace {
/// w^2 in Oe's order: the components' squares, then xy, yz, zx.
Eigen::Matrix<double, 6, 1> rotation_squares(const Vector3d& w) {
  Eigen::Matrix<double, 6, 1> w2;
  w2 << w.x() * w.x(), w.y() * w.y(), w.z() * w.z(), w.x() * w.y(), w.y() * w.z(), w.z() * w.x();
  return w2;
}
}  // namespace

void FloatingBody::form_rotation_bound() {
  const Index first = n_dynamic_, rows = n_inertial_ - n_dynamic_, n = nq();
  if (!rotates_ || rows <= 0) return;  // no rotation loads on the quasistatic modes to bound
  double size = 0;  // the largest reference coordinate of a point the body reports or contacts with
  double shape = 0;  // the largest displacement of such a point per unit quasistatic coordinate
  auto point_rows = [&](const MatrixXd& modes, Index dim) {
    for (Index r = 0; r + dim <= modes.rows(); r += dim)
      shape = std::max(shape, modes.block(r, first, dim, n - first).norm());
  };
  for (const format::Node& node : sid_.nodes) {
    size = std::max(size, node.origin.M0.cwiseAbs().maxCoeff());
    point_rows(node.phi, 3);
  }
  for (const format::ContactSurface& c : sid_.contact_surfaces) {
    if (c.position.size()) size = std::max(size, c.position.cwiseAbs().maxCoeff());
    point_rows(c.Psi, c.position.cols());
  }
  for (const format::MasterPatch& m : sid_.master_patches) {
    if (m.control_points.size()) size = std::max(size, m.control_points.cwiseAbs().maxCoeff());
    point_rows(m.Phi, m.control_points.cols());
  }
  rotation_bound_.resolution = std::numeric_limits<double>::epsilon() * size;
  // the held coordinates' softest stiffness: the smallest eigenvalue of Ke's held block (its
  // diagonal in the normal form; dense where a massless boundary is held with the modes)
  const MatrixXd held = sid_.Ke.M0.bottomRightCorner(n - first, n - first);
  const double softest = stiffness_.is_diagonal() ? held.diagonal().minCoeff()
                                                  : common::symmetric_eigenvalues(held)(0);
  if (!(softest > 0)) return;
  const Index nv = std::min(n_inertial_, n_dynamic_);
  const Eigen::Map<const MatrixXd> ge(sid_.Ge.M0.data(), 3 * n, nv);
  for (int a = 0; a < 3; ++a) rotation_bound_.ge += ge.middleRows(a * n + first, rows).squaredNorm();
  rotation_bound_.ge = std::sqrt(rotation_bound_.ge);
  rotation_bound_.oe0 = sid_.Oe.M0.middleRows(first, rows).norm();
  rotation_bound_.oe1 = oe1_.size() ? oe1_.middleRows(first, rows).norm() : 0.0;
  rotation_bound_.per_load = shape / softest;
}

std::array<double, 3> FloatingBody::rotation_term_bounds(const VectorXd& qv, const VectorXd& qd, const Vector3d& w) const {
  const RotationBound& b = rotation_bound_;
  constexpr double kNone = std::numeric_limits<double>::infinity();
  if (!(b.per_load > 0)) return {kNone, kNone, kNone};
  // |Ge(qdot) w| <= |w| |Ge rows|_F |qdot|, |Oe0 w^2| <= |w^2| |Oe0 rows|_F,
  // |Oe1(q) w^2| <= |w^2| |Oe1 rows|_F |q|
  const Index nv = std::min(n_inertial_, n_dynamic_), m = oe1_.cols() / 6;
  const double w2 = rotation_squares(w).norm();
  return {b.per_load * w.norm() * b.ge * qd.head(nv).norm(), b.per_load * w2 * b.oe0, b.per_load * w2 * b.oe1 * qv.head(m).norm()};
}

double FloatingBody::rotation_response_bound(const VectorXd& qv, const VectorXd& qd, const Vector3d& w) const {
  const std::array<double, 3> terms = rotation_term_bounds(qv, qd, w);
  return terms[0] + terms[1] + terms[2];
}

bool FloatingBody::add_rotation_loads(const VectorXd& qv, const VectorXd& qd, const Vector3d& w, Index first, Eigen::Ref<VectorXd> out) const {
  // rows beyond n_inertial_ (a massless boundary) carry no inertia
  const Index ni = n_inertial_, rows = std::min(first + out.size(), ni) - first;
  if (!rotates_ || rows <= 0) return false;
  // on the quasistatic modes: the terms left out, smallest first, while the response they
  // could cause together stays within the position resolution
  std::array<bool, 3> formed{true, true, true};  // Ge(qdot) w, Oe0 w^2, Oe1(q) w^2
  if (first == n_dynamic_) {
    const std::array<double, 3> bounds = rotation_term_bounds(qv, qd, w);
    std::array<int, 3> order{0, 1, 2};
    std::sort(order.begin(), order.end(), [&](int a, int b) { return bounds[std::size_t(a)] < bounds[std::size_t(b)]; });
    double left_out = 0;
    for (const int t : order) {
      if (!(left_out + bounds[std::size_t(t)] <= rotation_bound_.resolution)) break;
      left_out += bounds[std::size_t(t)], formed[std::size_t(t)] = false;
    }
    if (!formed[0] && !formed[1] && !formed[2]) return false;
  }
  auto part = out.head(rows);
  // Ge(qdot) w = sum_a w_a sum_j Ge_j(:, a) qdot_j: the SID's nq x 3 blocks Ge_j lie one after
  // the other, so column a of all of them is a 3nq-strided matrix; the sum runs over the
  // coordinates with velocities (quasistatic modes have none)
  const Index nv = std::min(ni, n_dynamic_);
  const Eigen::Map<const MatrixXd> ge(sid_.Ge.M0.data(), 3 * nq(), nv);
  for (int a = 0; a < 3 && formed[0]; ++a)
    if (w(a) != 0) part.noalias() -= w(a) * (ge.middleRows(a * nq() + first, rows) * qd.head(nv));
  // Oe(q) w^2 = Oe0 w^2 + sum_c w2_c [Oe1_0(:, c) ... Oe1_(ni-1)(:, c)] q: column c of every
  // first-order term, read once per component of w^2 that is not zero (a planar spin needs one
  // of the six), instead of summing the matrix first (the floating frame's largest term)
  const Eigen::Matrix<double, 6, 1> w2 = rotation_squares(w);
  if (formed[1]) part.noalias() -= sid_.Oe.M0.middleRows(first, rows) * w2;
  // up to the last coordinate that is not zero: quasistatic modes rest at zero between
  // impacts where nothing else loads them, and their columns then add nothing
  Index m = formed[2] ? oe1_.cols() / 6 : 0;
  while (m > 0 && qv(m - 1) == 0) --m;
  for (int c = 0; c < 6 && m > 0; ++c) {
    if (w2(c) == 0) continue;
    const Eigen::Map<const MatrixXd, 0, Eigen::OuterStride<>> column(oe1_.data() + c * oe1_.rows(), oe1_.rows(), m,
                                                                     Eigen::OuterStride<>(6 * oe1_.rows()));
    part.noalias() -= w2(c) * (column.middleRows(first, rows) * qv.head(m));
  }
  return true;
}

}  // namespace isosid::run

// Evaluation of a deformed master patch; see deformed_patch.hpp.
#include "contact/deformed_patch.hpp"

#include "isosid/format/bspline_basis.hpp"

#include <algorithm>
#include <cmath>

namespace isosid::run {

DeformedPatch::DeformedPatch(const format::MasterPatch& patch, int dim)
    : patch_(patch), dim_(dim), net_(patch.control_points), moved_(std::size_t(patch.control_points.rows()), 0),
      q_(Eigen::VectorXd::Zero(patch.Phi.cols())), Phi_transposed_(patch.Phi.transpose()) {
  for (int d = 0; d < parameter_dim(); ++d) basis_[d] = SpanPolynomials(patch.knots[std::size_t(d)], patch.degrees[std::size_t(d)]);
  const Eigen::Index ncp = patch.control_points.rows();
  for (Eigen::Index i = 0; i < ncp; ++i) reference_center_.head(dim) += patch.control_points.row(i).transpose() / double(ncp);
  for (Eigen::Index i = 0; i < ncp; ++i) {
    reference_radius_ = std::max(reference_radius_, (patch.control_points.row(i).transpose() - reference_center_.head(dim)).norm());
    largest_row_norm_ = std::max(largest_row_norm_, Phi_transposed_.middleCols(i * dim, dim).norm());
  }
  std::vector<std::vector<double>> mids(2, std::vector<double>{0.0});
  for (int d = 0; d < parameter_dim(); ++d) {
    const std::vector<double> k = format::unique_knots(patch.knots[std::size_t(d)]);
    mids[std::size_t(d)].clear();
    for (std::size_t i = 0; i + 1 < k.size(); ++i) mids[std::size_t(d)].push_back(0.5 * (k[i] + k[i + 1]));
  }
  for (double v : mids[1])
    for (double u : mids[0]) midpoints_.emplace_back(u, v);
  // where they lie on the undeformed net (the net is the reference one until the first deform())
  Point point;
  for (const Eigen::Vector2d& m : midpoints_) {
    evaluate(m, point);
    midpoint_positions_.push_back(point.C);
  }
}

void DeformedPatch::deform(const Eigen::VectorXd& q) {
  q_ = q;
  ++stamp_;  // every control point is stale
}

Eigen::Vector3d DeformedPatch::control_point(int i) const {
  if (moved_[std::size_t(i)] != stamp_) {
    for (int a = 0; a < dim_; ++a) net_(i, a) = patch_.control_points(i, a) + Phi_transposed_.col(Eigen::Index(i) * dim_ + a).dot(q_);
    moved_[std::size_t(i)] = stamp_;
  }
  Eigen::Vector3d P = Eigen::Vector3d::Zero();
  P.head(dim_) = net_.row(i).transpose();
  return P;
}

void DeformedPatch::bounding_sphere(Eigen::Vector3d& center, double& radius) const {
  center = reference_center_;
  radius = reference_radius_ + largest_row_norm_ * q_.norm();
}

void DeformedPatch::evaluate(const Eigen::Vector2d& u, Point& out) const {
  // B-spline derivatives per direction, then the rational quotient rule for
  // C = A / W with A = sum N w P, W = sum N w (The NURBS Book, eq. 4.8 and A4.4)
  const int pd = parameter_dim();
  int span[2] = {0, 0}, p[2] = {0, 0};
  format::BasisDerivatives N[2] = {format::BasisDerivatives::Zero(3, 1), format::BasisDerivatives::Zero(3, 1)};
  N[1](0, 0) = 1;  // a curve: a constant second direction
  for (int d = 0; d < pd; ++d) {
    const auto& U = patch_.knots[std::size_t(d)];
    const double t = std::clamp(u(d), lower(d), upper(d));
    p[d] = patch_.degrees[std::size_t(d)];
    span[d] = format::find_span(U, p[d], t);
    out.span_lower(d) = U(span[d]), out.span_upper(d) = U(span[d] + 1);
    basis_[d].evaluate(span[d], t, N[d]);  // rows: value, first, second derivative
  }
  const int n_u = format::basis_count(patch_.knots[0], p[0]);
  // derivative index k: 0 value, 1 d/du, 2 d/dv, 3 uu, 4 uv, 5 vv (u-order, v-order)
  static constexpr int order_u[6] = {0, 1, 0, 2, 1, 0}, order_v[6] = {0, 0, 1, 0, 1, 2};
  Eigen::Vector3d A[6];
  double W[6] = {0, 0, 0, 0, 0, 0};
  for (auto& a : A) a.setZero();
  out.control_points.clear();
  // N w of each control point and its derivatives d/du, d/dv, for R and dR
  double Nw[(format::kMaxDegree + 1) * (format::kMaxDegree + 1)], dNw[2][(format::kMaxDegree + 1) * (format::kMaxDegree + 1)];
  int count = 0;
  for (int b = 0; b <= p[1]; ++b)
    for (int a = 0; a <= p[0]; ++a) {
      const int i = (span[0] - p[0] + a) + n_u * (pd > 1 ? span[1] - p[1] + b : 0);
      const double w = patch_.weights(i);
      const Eigen::Vector3d P = control_point(i);
      for (int k = 0; k < (pd > 1 ? 6 : 3); ++k) {
        const int ku = pd > 1 ? order_u[k] : k, kv = pd > 1 ? order_v[k] : 0;
        const double Nk = N[0](ku, a) * N[1](kv, b) * w;
        W[k] += Nk;
        A[k] += Nk * P;
      }
      out.control_points.push_back(i);
      Nw[count] = N[0](0, a) * N[1](0, b) * w;
      dNw[0][count] = N[0](1, a) * N[1](0, b) * w;
      dNw[1][count++] = pd > 1 ? N[0](0, a) * N[1](1, b) * w : 0.0;
    }
  const double W0 = W[0];
  out.C = A[0] / W0;
  out.R.resize(std::size_t(count));
  out.dR.resize(std::size_t(count));
  const double dW[2] = {W[1], pd > 1 ? W[2] : 0.0};  // W's derivatives d/du, d/dv
  for (int j = 0; j < count; ++j) {
    const double R = Nw[j] / W0;
    out.R[std::size_t(j)] = R;
    for (int d = 0; d < 2; ++d) out.dR[std::size_t(j)](d) = (dNw[d][j] - R * dW[d]) / W0;
  }
  if (pd == 1) {
    out.dC[0] = (A[1] - W[1] * out.C) / W0;
    out.ddC[0] = (A[2] - 2 * W[1] * out.dC[0] - W[2] * out.C) / W0;
    out.dC[1].setZero(), out.ddC[1].setZero(), out.ddC[2].setZero();
    return;
  }
  out.dC[0] = (A[1] - W[1] * out.C) / W0;
  out.dC[1] = (A[2] - W[2] * out.C) / W0;
  out.ddC[0] = (A[3] - 2 * W[1] * out.dC[0] - W[3] * out.C) / W0;
  out.ddC[1] = (A[4] - W[1] * out.dC[1] - W[2] * out.dC[0] - W[4] * out.C) / W0;
  out.ddC[2] = (A[5] - 2 * W[2] * out.dC[1] - W[5] * out.C) / W0;
}

void DeformedPatch::Point::advance(const Eigen::Vector2d& s) {
  C += s(0) * dC[0] + s(1) * dC[1] + 0.5 * (s(0) * s(0) * ddC[0] + 2 * s(0) * s(1) * ddC[1] + s(1) * s(1) * ddC[2]);
  dC[0] += s(0) * ddC[0] + s(1) * ddC[1];
  dC[1] += s(0) * ddC[1] + s(1) * ddC[2];
  for (std::size_t j = 0; j < R.size(); ++j) R[j] += dR[j].dot(s);
}

void DeformedPatch::shape_rows(const Point& point, Eigen::MatrixXd& Psi) const {
  // summed transposed, where each control point's modal rows are contiguous columns (a row of
  // Psi is strided), then turned once
  rows_transposed_.setZero(patch_.Phi.cols(), dim_);
  for (std::size_t j = 0; j < point.R.size(); ++j)
    rows_transposed_.noalias() += point.R[j] * Phi_transposed_.middleCols(Eigen::Index(point.control_points[j]) * dim_, dim_);
  Psi = rows_transposed_.transpose();
}

bool DeformedPatch::newton_projection(const Eigen::Vector3d& x, Eigen::Vector2d& u, Point& point) const {
  // minimizes 1/2 |C(u) - x|^2: gradient C_a . (C - x), Hessian C_a . C_b + C_ab . (C - x),
  // falling back to Gauss-Newton where the Hessian is not positive definite
  const int pd = parameter_dim();
  for (int iteration = 0; iteration < 30; ++iteration) {
    evaluate(u, point);
    const Eigen::Vector3d d = point.C - x;
    Eigen::Matrix2d H = Eigen::Matrix2d::Identity();
    Eigen::Vector2d g = Eigen::Vector2d::Zero();
    for (int a = 0; a < pd; ++a) {
      g(a) = point.dC[a].dot(d);
      for (int b = 0; b < pd; ++b) H(a, b) = point.dC[a].dot(point.dC[b]) + point.ddC[a + b].dot(d);
    }
    Eigen::Vector2d step = Eigen::Vector2d::Zero();
    bool newton = true;  // the step is Newton's (not Gauss-Newton's fallback)
    if (pd == 1) {
      const double gauss_newton = point.dC[0].squaredNorm();
      newton = H(0, 0) > 0.1 * gauss_newton;
      step(0) = -g(0) / (newton ? H(0, 0) : gauss_newton);
    } else {
      Eigen::LLT<Eigen::Matrix2d> llt(H);
      if (llt.info() != Eigen::Success) {
        newton = false;
        for (int a = 0; a < 2; ++a)
          for (int b = 0; b < 2; ++b) H(a, b) = point.dC[a].dot(point.dC[b]);
        H.diagonal().array() += 1e-14 * H.trace() + 1e-300;
      }
      step = -H.ldlt().solve(g);
    }
    // a degenerate point (a pole's collapsed edge, a far point's singular Hessian) can make the
    // step non-finite: a parameter that is no number must never reach the knot-span search
    if (!step.allFinite()) return false;
    const Eigen::Vector2d before = u;
    bool clamped = false;
    for (int a = 0; a < pd; ++a) {
      u(a) = std::clamp(u(a) + step(a), lower(a), upper(a));
      clamped = clamped || u(a) != before(a) + step(a);
    }
    Eigen::Vector2d moved = Eigen::Vector2d::Zero();
    moved.head(pd) = u.head(pd) - before.head(pd);
    // A step below 1e-9 of the parameter range ends the search (also on the patch's edge, where
    // the step is clamped to nothing), its tangents and basis values then 1e-9 off. A last
    // full Newton step below 3e-5 of its knot span, within that span, is taken by Taylor's
    // formula instead of another evaluation: the next Newton correction would be O(step^2),
    // 1e-9 of the span, and so are the errors of the expansion's tangents and basis values (the
    // gap's is the square of that: the closest point is stationary). A warm-started projection
    // then mostly costs one evaluation where it cost two. A clamped or Gauss-Newton step says
    // nothing of convergence, and across a knot the derivatives jump: evaluated again.
    bool taylor = newton && !clamped;
    for (int a = 0; a < pd; ++a)
      taylor = taylor && u(a) >= point.span_lower(a) && u(a) <= point.span_upper(a) &&
               std::abs(moved(a)) <= 3e-5 * (point.span_upper(a) - point.span_lower(a));
    if (taylor || moved.cwiseAbs().maxCoeff() <= 1e-9 * (upper(0) - lower(0))) {
      point.advance(moved);
      return true;
    }
  }
  evaluate(u, point);
  return false;
}

bool DeformedPatch::closest_point(const Eigen::Vector3d& x, Eigen::Vector2d& u, Point& point) const {
  if (!std::isnan(u(0)) && newton_projection(x, u, point)) return true;
  // no warm start, or Newton failed from it: start from the span midpoint nearest on the
  // undeformed patch (the displacements are far smaller than a span; evaluating every midpoint
  // on the deformed net cost a refined ball's first projections 1 505 evaluations each)
  double best = INFINITY;
  for (std::size_t i = 0; i < midpoints_.size(); ++i) {
    const double distance = (midpoint_positions_[i] - x).squaredNorm();
    if (distance < best) best = distance, u = midpoints_[i];
  }
  if (newton_projection(x, u, point)) return true;
  u.setConstant(NAN);
  return false;
}

std::vector<Eigen::Index> side_parameters(const format::ContactSurface& s, int parameter_dim) {
  if (s.patch.find(' ') != std::string::npos || s.points() == 0 || s.parameter.cols() != parameter_dim + 1) return {};
  const Eigen::VectorXd lo = s.parameter.colwise().minCoeff(), hi = s.parameter.colwise().maxCoeff();
  std::vector<Eigen::Index> free;
  for (Eigen::Index d = 0; d < s.parameter.cols(); ++d)
    if (hi(d) > lo(d)) free.push_back(d);
  if (int(free.size()) != parameter_dim) free.clear();
  return free;
}

}  // namespace isosid::run

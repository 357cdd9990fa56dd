// NURBS patch evaluation and sides; see nurbs_patch.hpp.
#include "geometry/nurbs_patch.hpp"

#include "geometry/multi_index.hpp"

#include "isosid/format/error.hpp"

#include <cmath>

namespace isosid::prep {

std::vector<int> NurbsPatch::counts() const {
  std::vector<int> n;
  for (std::size_t d = 0; d < degrees.size(); ++d) n.push_back(basis_count(knots[d], degrees[d]));
  return n;
}

int flat_index(const std::vector<int>& counts, const std::vector<int>& ijk) {
  int index = 0, stride = 1;
  for (std::size_t d = 0; d < counts.size(); ++d) {
    index += ijk[d] * stride;
    stride *= counts[d];
  }
  return index;
}

void NurbsPatch::evaluate(const Eigen::VectorXd& xi, Eigen::VectorXd& x, Eigen::MatrixXd* dx_dxi) const {
  const int pd = param_dim(), cols = phys_dim();
  const std::vector<int> n = counts();
  std::vector<Eigen::MatrixXd> ders(static_cast<std::size_t>(pd));
  std::vector<int> spans(static_cast<std::size_t>(pd));
  for (int d = 0; d < pd; ++d) {
    spans[std::size_t(d)] = find_span(knots[std::size_t(d)], degrees[std::size_t(d)], xi(d));
    ders[std::size_t(d)] = basis_derivatives(knots[std::size_t(d)], degrees[std::size_t(d)], spans[std::size_t(d)], xi(d), 1);
  }
  // homogeneous sums: A = sum N w P, W = sum N w, and their first derivatives
  Eigen::VectorXd A = Eigen::VectorXd::Zero(cols);
  Eigen::MatrixXd dA = Eigen::MatrixXd::Zero(cols, pd);
  double W = 0;
  Eigen::VectorXd dW = Eigen::VectorXd::Zero(pd);
  std::vector<int> local_count(static_cast<std::size_t>(pd)), ijk(static_cast<std::size_t>(pd));
  for (int d = 0; d < pd; ++d) local_count[std::size_t(d)] = degrees[std::size_t(d)] + 1;
  MultiIndex local(pd, local_count);
  do {
    double value = 1;
    Eigen::VectorXd grad = Eigen::VectorXd::Ones(pd);
    for (int d = 0; d < pd; ++d) {
      const auto dd = std::size_t(d);
      ijk[dd] = spans[dd] - degrees[dd] + local[d];
      value *= ders[dd](0, local[d]);
      for (int e = 0; e < pd; ++e) grad(e) *= ders[dd](e == d ? 1 : 0, local[d]);
    }
    const int i = flat_index(n, ijk);
    const double w = weights(i);
    A += value * w * points.row(i).transpose();
    dA += w * points.row(i).transpose() * grad.transpose();
    W += value * w;
    dW += w * grad;
  } while (local.next());
  x = A / W;
  if (dx_dxi) *dx_dxi = (dA - x * dW.transpose()) / W;
}

Eigen::VectorXd NurbsPatch::point(const Eigen::VectorXd& xi) const {
  Eigen::VectorXd x;
  evaluate(xi, x);
  return x;
}

std::optional<PatchSide> NurbsPatch::side(const std::string& name) const {
  if (auto s = side_from_name(name, param_dim())) return s;
  if (auto it = named_sides.find(name); it != named_sides.end()) return it->second;
  return std::nullopt;
}

Eigen::VectorXd basis_row(const KnotVector& U, int p, double u) {
  Eigen::VectorXd row = Eigen::VectorXd::Zero(basis_count(U, p));
  const int span = find_span(U, p, u);
  double N[format::kMaxDegree + 1];
  basis_functions(U, p, span, u, N);
  for (int j = 0; j <= p; ++j) row(span - p + j) = N[j];
  return row;
}

Eigen::VectorXd NurbsPatch::greville(int i) const {
  const std::vector<int> n = counts();
  Eigen::VectorXd g(param_dim());
  int rest = i;
  for (int d = 0; d < param_dim(); ++d) {
    const int k = rest % n[std::size_t(d)], p = degrees[std::size_t(d)];
    rest /= n[std::size_t(d)];
    g(d) = greville_abscissa(knots[std::size_t(d)], p, k);
  }
  return g;
}

std::vector<int> NurbsPatch::side_points(PatchSide side) const {
  const std::vector<int> n = counts();
  std::vector<int> out;
  MultiIndex ijk(param_dim(), n);
  for (int i = 0; i < count(); ++i, ijk.next())
    if (ijk[side.direction] == (side.end == 0 ? 0 : n[std::size_t(side.direction)] - 1)) out.push_back(i);
  return out;
}

std::vector<int> NurbsPatch::collapsed_directions(PatchSide side) const {
  const std::vector<int> n = counts();
  const double tol = 1e-10 * (points.colwise().maxCoeff() - points.colwise().minCoeff()).norm();
  std::vector<int> out;
  for (int d = 0; d < param_dim(); ++d) {
    if (d == side.direction) continue;
    bool collapsed = true;
    MultiIndex ijk(param_dim(), n);
    for (int i = 0; i < count() && collapsed; ++i, ijk.next()) {
      if (ijk[side.direction] != (side.end == 0 ? 0 : n[std::size_t(side.direction)] - 1) || ijk[d] == 0) continue;
      std::vector<int> first(n.size());
      for (int k = 0; k < param_dim(); ++k) first[std::size_t(k)] = k == d ? 0 : ijk[k];
      collapsed = (points.row(i) - points.row(flat_index(n, first))).norm() <= tol;
    }
    if (collapsed) out.push_back(d);
  }
  return out;
}

void validate_patch(const NurbsPatch& patch, const std::string& file, const std::string& field) {
  using format::InputError;
  const int pd = patch.param_dim();
  if (pd < 1 || pd > 3) throw InputError(file, field + ".degrees", "needs 1 to 3 parametric directions");
  if (int(patch.knots.size()) != pd) throw InputError(file, field + ".knots", "one knot vector per degree required");
  int expected = 1;
  for (int d = 0; d < pd; ++d) {
    validate_knot_vector(patch.knots[std::size_t(d)], patch.degrees[std::size_t(d)], file,
                         field + ".knots[" + std::to_string(d) + "]");
    expected *= basis_count(patch.knots[std::size_t(d)], patch.degrees[std::size_t(d)]);
  }
  if (patch.points.rows() != expected)
    throw InputError(file, field + ".control_points",
                     std::to_string(patch.points.rows()) + " control points, the knot vectors need " + std::to_string(expected));
  if (patch.weights.size() != expected)
    throw InputError(file, field + ".weights", std::to_string(patch.weights.size()) + " weights, expected " + std::to_string(expected));
  for (int i = 0; i < expected; ++i) {
    if (!std::isfinite(patch.weights(i)) || patch.weights(i) <= 0)
      throw InputError(file, field + ".weights", "weight " + std::to_string(i) + " must be positive and finite");
    if (!patch.points.row(i).allFinite())
      throw InputError(file, field + ".control_points", "non-finite coordinate in point " + std::to_string(i));
  }
}

}  // namespace isosid::prep

// Master patches of body sides; see master_patch.hpp.
#include "sid/master_patch.hpp"

#include "assemble/point_operator.hpp"
#include "isosid/common/dense_decompositions.hpp"
#include "refine/patch_refinement.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

namespace isosid::prep {
namespace {

/// Element boundaries along tangential direction d on the side that the patch's knots lack.
std::vector<double> missing_knots(const BodyModel& body, int patch, PatchSide side, int d) {
  const std::vector<double> have = unique_knots(body.refined[std::size_t(patch)].knots[std::size_t(d)]);
  const double tol = 1e-12 * (have.back() - have.front());
  std::vector<double> out;
  for (const Element& e : body.space.elements) {
    if (e.patch != patch || !body.space.on_side(e, side)) continue;
    for (double x : {e.lo(d), e.hi(d)}) {
      auto near = [&](double y) { return std::abs(x - y) <= tol; };
      if (std::none_of(have.begin(), have.end(), near) && std::none_of(out.begin(), out.end(), near)) out.push_back(x);
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

/// Applies (A_0 x A_1 x ...) or its inverse to V in place (first direction fastest in V's
/// rows), one direction at a time.
void tensor_apply(const std::vector<Eigen::MatrixXd>& A, Eigen::MatrixXd& V, bool inverse) {
  Eigen::Index stride = 1;
  for (const Eigen::MatrixXd& a : A) {
    const Eigen::PartialPivLU<Eigen::MatrixXd> lu = inverse ? Eigen::PartialPivLU<Eigen::MatrixXd>(a) : Eigen::PartialPivLU<Eigen::MatrixXd>();
    const Eigen::Index n = a.rows(), outer = V.rows() / (stride * n);
    Eigen::MatrixXd line(n, V.cols());
    for (Eigen::Index o = 0; o < outer; ++o)
      for (Eigen::Index s = 0; s < stride; ++s) {
        for (Eigen::Index i = 0; i < n; ++i) line.row(i) = V.row(s + stride * (i + n * o));
        line = inverse ? Eigen::MatrixXd(lu.solve(line)) : Eigen::MatrixXd(a * line);
        for (Eigen::Index i = 0; i < n; ++i) V.row(s + stride * (i + n * o)) = line.row(i);
      }
    stride *= n;
  }
}

}  // namespace

format::MasterPatch master_patch(const BodyModel& body, const std::string& name, int patch, PatchSide side,
                                 const Eigen::MatrixXd& Phi_nodal) {
  NurbsPatch p = body.refined[std::size_t(patch)];
  bool inserted = false;
  for (int d = 0; d < p.param_dim(); ++d)
    if (d != side.direction) {
      const std::vector<double> X = missing_knots(body, patch, side, d);
      inserted = inserted || !X.empty();
      insert_knots(p, d, X);
    }
  const int dim = body.dofs.dim();
  format::MasterPatch m;
  m.name = name;
  std::vector<int> tangential;
  for (int d = 0; d < p.param_dim(); ++d)
    if (d != side.direction) {
      tangential.push_back(d);
      m.degrees.push_back(p.degrees[std::size_t(d)]);
      m.knots.push_back(p.knots[std::size_t(d)]);
    }
  const std::vector<int> cps = p.side_points(side);  // first tangential direction fastest
  const auto n = Eigen::Index(cps.size());
  m.weights.resize(n);
  m.control_points.resize(n, dim);
  m.Phi.resize(n * dim, Phi_nodal.cols());
  for (Eigen::Index i = 0; i < n; ++i) {
    m.weights(i) = p.weights(cps[std::size_t(i)]);
    m.control_points.row(i) = p.points.row(cps[std::size_t(i)]);
  }
  if (!inserted) {  // the side's functions are the body's own: copy their rows
    for (Eigen::Index i = 0; i < n; ++i)
      m.Phi.middleRows(i * dim, dim) = Phi_nodal.middleRows(
          Eigen::Index(body.dofs.node_of(body.space.patch_first_function[std::size_t(patch)] + cps[std::size_t(i)])) * dim, dim);
    return m;
  }
  // collocation at the Greville points of the side's tensor space: w(g) u(g) = sum N_m(g) W_m D_m
  std::vector<Eigen::MatrixXd> A;
  std::vector<std::vector<double>> g;
  for (int d : tangential) {
    const KnotVector& U = p.knots[std::size_t(d)];
    const int deg = p.degrees[std::size_t(d)], count = basis_count(U, deg);
    std::vector<double> gd;
    for (int i = 0; i < count; ++i) gd.push_back(greville_abscissa(U, deg, i));
    Eigen::MatrixXd a(count, count);
    for (int k = 0; k < count; ++k) a.row(k) = basis_row(U, deg, gd[std::size_t(k)]).transpose();
    A.push_back(std::move(a));
    g.push_back(std::move(gd));
  }
  // mode shapes at the points from the body's own (THB) functions
  Eigen::MatrixXd V(n * dim, Phi_nodal.cols());
  Eigen::VectorXd xi(p.param_dim());
  xi(side.direction) = side.end ? p.upper(side.direction) : p.lower(side.direction);
  for (Eigen::Index k = 0; k < n; ++k) {
    Eigen::Index rest = k;
    for (std::size_t t = 0; t < tangential.size(); ++t) {
      const auto count = Eigen::Index(g[t].size());
      xi(tangential[t]) = g[t][std::size_t(rest % count)];
      rest /= count;
    }
    const PointOperator op = *point_operator_at(body.space, body.dofs, body.elasticity, patch, xi);  // xi lies on the side
    V.middleRows(k * dim, dim) = op.N * op.gather(Phi_nodal);
  }
  // w(g) u(g) = sum_m N_m(g) (W_m D_m): scale by the weight function, solve, unscale
  Eigen::MatrixXd w = m.weights;
  tensor_apply(A, w, false);
  for (Eigen::Index k = 0; k < n; ++k) V.middleRows(k * dim, dim) *= w(k);
  A.insert(A.begin(), Eigen::MatrixXd::Identity(dim, dim));  // components are the fastest index
  tensor_apply(A, V, true);
  for (Eigen::Index k = 0; k < n; ++k) m.Phi.middleRows(k * dim, dim) = V.middleRows(k * dim, dim) / m.weights(k);
  return m;
}

}  // namespace isosid::prep

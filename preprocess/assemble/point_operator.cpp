// Pointwise displacement and strain operators; see point_operator.hpp.
#include "assemble/point_operator.hpp"

#include "isosid/common/dense_decompositions.hpp"
#include "space/element_evaluator.hpp"

namespace isosid::prep {

PointOperator point_operator(const AnalysisSpace& space, const DofMap& dofs, const BodyElasticity& elasticity,
                             const Element& element, const double* t) {
  const ElementEvaluator ev(space);
  PointValues v;
  ev.evaluate(element, t, v);
  PointOperator op;
  op.x = v.x;
  op.det_J = v.J.determinant();
  const int nf = int(element.functions.size()), dim = dofs.dim();
  dofs.element_nodes(element, op.nodes);
  op.N = Eigen::MatrixXd::Zero(dim, nf * dim);
  for (int f = 0; f < nf; ++f)
    for (int a = 0; a < dim; ++a) op.N(a, f * dim + a) = v.R(f);
  op.R = v.R;
  op.dR_dx = v.dR_dxi * v.J.inverse();
  elasticity.of(element).strain_operator(v.R, op.dR_dx, v.x, op.B);
  return op;
}

bool locate(const AnalysisSpace& space, int patch, const Eigen::VectorXd& xi, int& element, double* t) {
  const int pd = space.param_dim();
  for (int e = 0; e < int(space.elements.size()); ++e) {
    const Element& el = space.elements[e];
    bool inside = el.patch == patch;
    for (int d = 0; d < pd && inside; ++d) inside = xi(d) >= el.lo(d) && xi(d) <= el.hi(d);
    if (!inside) continue;
    element = e;
    for (int d = 0; d < pd; ++d) t[d] = (xi(d) - el.lo(d)) / (el.hi(d) - el.lo(d));
    return true;
  }
  return false;
}

std::optional<PointOperator> point_operator_at(const AnalysisSpace& space, const DofMap& dofs, const BodyElasticity& elasticity,
                                               int patch, const Eigen::VectorXd& xi) {
  int e = 0;
  double t[3] = {0, 0, 0};
  if (!locate(space, patch, xi, e, t)) return std::nullopt;
  return point_operator(space, dofs, elasticity, space.elements[e], t);
}

Eigen::MatrixXd PointOperator::gather(const Eigen::MatrixXd& nodal) const {
  const Eigen::Index dim = N.rows();
  Eigen::MatrixXd local(N.cols(), nodal.cols());
  for (std::size_t f = 0; f < nodes.size(); ++f) local.middleRows(Eigen::Index(f) * dim, dim) = nodal.middleRows(nodes[f] * dim, dim);
  return local;
}

Eigen::VectorXd PointOperator::displacement(const Eigen::VectorXd& nodal) const { return N * gather(nodal); }
Eigen::VectorXd PointOperator::strain(const Eigen::VectorXd& nodal) const { return B * gather(nodal); }

Eigen::VectorXd expand_to_nodes(const DofMap& dofs, const Eigen::VectorXd& free_values, const Eigen::VectorXd* fixed_values) {
  Eigen::VectorXd nodal = fixed_values ? *fixed_values : Eigen::VectorXd::Zero(dofs.total_dofs());
  for (int n = 0; n < dofs.node_count(); ++n)
    for (int a = 0; a < dofs.dim(); ++a)
      if (const int i = dofs.free_index(n, a); i >= 0) nodal(n * dofs.dim() + a) = free_values(i);
  return nodal;
}

}  // namespace isosid::prep

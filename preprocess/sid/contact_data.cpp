// Contact Gauss points; see contact_data.hpp.
#include "sid/contact_data.hpp"

#include "assemble/boundary_quadrature.hpp"
#include "isosid/format/error.hpp"

namespace isosid::prep {
namespace {

std::vector<BoundaryPoint> selected_points(const BodyModel& body, const ContactSurfaceSpec& spec) {
  const auto side = body.refined[std::size_t(spec.patch)].side(spec.side);
  if (!side) throw format::InputError(body.spec.file, "contact_surface " + spec.name, "unknown side '" + spec.side + "'");
  std::vector<BoundaryPoint> out =
      boundary_points(body.space, body.elasticity, spec.patch, *side, spec.points_per_direction, spec.interval);
  if (out.empty())
    throw format::InputError(body.spec.file, "contact_surface " + spec.name, "no Gauss point lies in the interval");
  // a side that collapses (the axis of a body of revolution, a pole) or an interval narrower
  // than round-off has no area to carry pressure: say so here, not as bad weights in the SID
  for (const BoundaryPoint& p : out)
    if (!(p.weight > 0) || !p.normal.allFinite())
      throw format::InputError(body.spec.file, "contact_surface " + spec.name + (spec.interval.empty() ? ".side" : ".interval"),
                               spec.interval.empty() ? "side '" + spec.side + "' has no area (it collapses to a line or a point)"
                                                     : "has no area on side '" + spec.side +
                                                           "' (the side collapses there, or the interval is too narrow)");
  return out;
}

format::ContactSurface points_of(const BodyModel& body, const ContactSurfaceSpec& spec, const std::vector<BoundaryPoint>& pts) {
  const int dim = body.dofs.dim(), pd = body.space.param_dim();
  const auto n = Eigen::Index(pts.size());
  format::ContactSurface s;
  s.name = spec.name;
  s.side = side_name(*body.refined[std::size_t(spec.patch)].side(spec.side));
  s.master_patch = spec.name;
  s.parameter.resize(n, pd);
  s.element.resize(n);
  s.position.resize(n, dim);
  s.normal.resize(n, dim);
  s.weight.resize(n);
  for (Eigen::Index g = 0; g < n; ++g) {
    const BoundaryPoint& p = pts[std::size_t(g)];
    s.parameter.row(g) = p.xi.transpose();
    s.element(g) = p.element;
    s.position.row(g) = p.x.transpose();
    s.normal.row(g) = p.normal.transpose();
    s.weight(g) = p.weight;
  }
  return s;
}

Eigen::SparseMatrix<double> shape_rows_of(const BodyModel& body, const std::vector<BoundaryPoint>& pts) {
  const int dim = body.dofs.dim();
  std::vector<Eigen::Triplet<double>> t;
  for (std::size_t g = 0; g < pts.size(); ++g) {
    const Element& e = body.space.elements[std::size_t(pts[g].element)];
    for (std::size_t f = 0; f < e.functions.size(); ++f)
      for (int a = 0; a < dim; ++a)
        t.emplace_back(int(g) * dim + a, body.dofs.node_of(e.functions[f]) * dim + a, pts[g].R(Eigen::Index(f)));
  }
  Eigen::SparseMatrix<double> N(Eigen::Index(pts.size()) * dim, body.dofs.total_dofs());
  N.setFromTriplets(t.begin(), t.end());  // duplicates (merged nodes) are summed
  return N;
}

/// 1 for each point that only interface DOFs move: every free DOF in its rows of N is one of
/// them (fixed DOFs do not move it). On a side only the side's control points support a point;
/// the others' basis values there are round-off (a partition of unity: 1e-12 is relative).
Eigen::VectorXi interface_coverage(const Eigen::SparseMatrix<double>& N, const DofMap& dofs, const std::vector<int>& interface_dofs) {
  std::vector<char> in_interface(std::size_t(dofs.free_count()), 0);
  for (const int f : interface_dofs) in_interface[std::size_t(f)] = 1;
  const std::vector<int>& free = dofs.free_indices();
  Eigen::VectorXi covered = Eigen::VectorXi::Ones(N.rows() / dofs.dim());
  for (Eigen::Index dof = 0; dof < N.outerSize(); ++dof) {
    const int f = free[std::size_t(dof)];
    if (f < 0 || in_interface[std::size_t(f)]) continue;
    for (Eigen::SparseMatrix<double>::InnerIterator it(N, dof); it; ++it)
      if (std::abs(it.value()) > 1e-12) covered(it.row() / dofs.dim()) = 0;
  }
  return covered;
}

}  // namespace

format::ContactSurface contact_points(const BodyModel& body, const ContactSurfaceSpec& spec) {
  return points_of(body, spec, selected_points(body, spec));
}

Eigen::SparseMatrix<double> contact_shape_rows(const BodyModel& body, const ContactSurfaceSpec& spec) {
  return shape_rows_of(body, selected_points(body, spec));
}

format::ContactSurface contact_surface(const BodyModel& body, const ContactSurfaceSpec& spec, const Eigen::MatrixXd& Phi_nodal,
                                       const std::vector<int>* interface_dofs) {
  const std::vector<BoundaryPoint> pts = selected_points(body, spec);  // once for both
  format::ContactSurface s = points_of(body, spec, pts);
  const Eigen::SparseMatrix<double> N = shape_rows_of(body, pts);
  s.Psi = N * Phi_nodal;
  if (interface_dofs) s.in_interface = interface_coverage(N, body.dofs, *interface_dofs);
  return s;
}

}  // namespace isosid::prep

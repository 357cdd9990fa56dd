// Reduction of a body from its model file; see body_reduction.hpp.
#include "reduce/body_reduction.hpp"

#include "isosid/format/error.hpp"
#include "reduce/modal_analysis.hpp"
#include "sid/contact_data.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace isosid::prep {

std::vector<int> interface_dofs(const BodyModel& body, std::string& description) {
  const ReductionSpec& r = body.spec.reduction;
  const auto surface = std::find_if(body.spec.contact_surfaces.begin(), body.spec.contact_surfaces.end(),
                                    [&](const ContactSurfaceSpec& c) { return c.name == r.interface_surface; });
  const NurbsPatch& patch = body.refined[std::size_t(surface->patch)];
  const PatchSide side = *patch.side(surface->side);
  // the centre as a physical point of the side; nodes are ranked by their physical distance
  // to it (parameter distances mislead where the parametrization collapses, e.g. at a pole)
  Eigen::VectorXd centre;
  if (r.interface_point) {
    centre = *r.interface_point;
  } else {
    Eigen::VectorXd xi(body.space.param_dim());
    for (int d = 0, k = 0; d < body.space.param_dim(); ++d)
      xi(d) = d == side.direction ? (side.end ? patch.upper(d) : patch.lower(d)) : r.interface_center(k++);
    centre = patch.point(xi);
  }
  std::map<int, double> distance;
  std::vector<std::pair<int, std::string>> parts{{surface->patch, surface->side}};
  parts.insert(parts.end(), surface->continued.begin(), surface->continued.end());
  for (const auto& [part, name] : parts)
    for (int node : side_nodes(body, part, *body.refined[std::size_t(part)].side(name)))
      distance[node] = (body.dofs.node_points().row(node).transpose() - centre).norm();
  std::vector<std::pair<double, int>> ranked;
  for (auto [node, d] : distance) ranked.emplace_back(d, node);
  std::sort(ranked.begin(), ranked.end());
  if (int(ranked.size()) < r.interface_points)
    throw format::InputError(body.spec.file, "reduction.interface_points",
                             std::to_string(r.interface_points) + " requested, the side has " + std::to_string(ranked.size()) + " nodes");
  std::size_t count = std::size_t(r.interface_points);
  while (r.interface_radius > 0 && count < ranked.size() && ranked[count].first <= r.interface_radius) ++count;
  std::vector<int> dofs;
  for (std::size_t k = 0; k < count; ++k)
    for (int a = 0; a < body.dofs.dim(); ++a)
      if (const int i = body.dofs.free_index(ranked[k].second, a); i >= 0) dofs.push_back(i);
  if (dofs.empty())  // a model-file problem, found before the reduction would fail on it
    throw format::InputError(body.spec.file, "reduction.interface_points",
                             "the " + std::to_string(count) + " control points of '" + surface->name +
                                 "' nearest the interface centre are all held by [boundary]: no interface DOF is left (move or widen the interface)");
  std::sort(dofs.begin(), dofs.end());
  description = std::to_string(count) + " control points of '" + surface->name + "' nearest to (" +
                std::to_string(centre(0)) + ", " + std::to_string(centre(1)) + (centre.size() > 2 ? ", " + std::to_string(centre(2)) : "") +
                ") m (" + std::to_string(dofs.size()) + " DOFs)";
  return dofs;
}

std::vector<int> massless_boundary_dofs(const BodyModel& body, std::string& description) {
  const ReductionSpec& r = body.spec.reduction;
  const auto surface = std::find_if(body.spec.contact_surfaces.begin(), body.spec.contact_surfaces.end(),
                                    [&](const ContactSurfaceSpec& c) { return c.name == r.boundary_surface; });
  // every DOF that moves a contact point: then the points' displacements depend on the
  // boundary coordinates alone, and the contact problem is one of the massless boundary
  const Eigen::SparseMatrix<double> N = contact_shape_rows(body, *surface);
  std::vector<int> dofs;
  int points = 0;
  for (int n = 0; n < body.dofs.node_count(); ++n) {
    bool moves = false;
    for (int a = 0; a < body.dofs.dim(); ++a) {
      bool used = false;  // a function of the element that vanishes on the side stores a zero
      for (Eigen::SparseMatrix<double>::InnerIterator it(N, n * body.dofs.dim() + a); it; ++it) used = used || std::abs(it.value()) > 1e-14;
      moves = moves || used;
      if (const int i = body.dofs.free_index(n, a); used && i >= 0) dofs.push_back(i);
    }
    points += moves;
  }
  std::sort(dofs.begin(), dofs.end());
  description = "massless boundary: the " + std::to_string(points) + " control points under contact surface '" + surface->name +
                "' (" + std::to_string(dofs.size()) + " DOFs)";
  return dofs;
}

ReductionRequest reduction_request(const BodyModel& body) {
  ReductionRequest q;
  q.method = body.spec.reduction.method;
  q.normal_modes = body.spec.reduction.normal_modes;
  if (format::traits(q.method).interface_nodes) q.interface_dofs = interface_dofs(body, q.interface_description);
  if (format::traits(q.method).massless_boundary) q.interface_dofs = massless_boundary_dofs(body, q.interface_description);
  return q;
}

ReducedBasis reduce_body(const BodyModel& body, const SystemMatrices& system, const Eigen::MatrixXd& extra) {
  const Eigen::MatrixXd rigid = admissible_rigid_fields(rigid_nodal_fields(body.dofs.node_points(), body.spec.analysis),
                                                        body.dofs.free_indices());
  const format::Material& fastest = fastest_material(body.spec);
  const double scale = eigenvalue_scale(fastest.youngs_modulus, fastest.density, body_size(body));
  ReductionRequest request = reduction_request(body);
  request.extra_vectors = extra;
  // more modes than the refined model has: a model-file problem, not a failed computation
  const Eigen::Index free = system.K.rows();
  using format::ReductionMethod;
  const bool modal = request.method == ReductionMethod::Modal;
  const Eigen::Index needed = request.normal_modes + (modal ? rigid.cols() : Eigen::Index(request.interface_dofs.size())) +
                              (request.method == ReductionMethod::MacNeal ? rigid.cols() : 0);
  if (request.method != ReductionMethod::Full && needed > free)
    throw format::InputError(body.spec.file, "reduction.normal_modes",
                             std::to_string(request.normal_modes) + " modes need " + std::to_string(needed) +
                                 " free DOFs with the " + (modal ? "rigid-body modes" : "interface DOFs") +
                                 ", but the refined model has " + std::to_string(free));
  if (request.method == ReductionMethod::CraigBamptonMassless && rigid.cols() > 0)
    throw format::InputError(body.spec.file, "reduction.method",
                             "craig-bampton-massless needs a body that its [boundary] holds (this one has " + std::to_string(rigid.cols()) +
                                 " rigid-body motions); use macneal for a free body");
  return reduce(system.K, system.M, rigid, request, scale);
}

}  // namespace isosid::prep

// Composition of the SID; see sid_builder.hpp.
#include "sid/sid_builder.hpp"

#include "isosid/format/error.hpp"
#include "isosid/common/sha256.hpp"
#include "isosid/version.hpp"
#include "reduce/modal_analysis.hpp"
#include "sid/contact_data.hpp"
#include "sid/master_patch.hpp"
#include "sid/node_data.hpp"
#include "sid/sid_terms.hpp"
#include "sid/stress_rows.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <numeric>
#include <map>

namespace isosid::prep {

std::vector<int> interface_dofs(const BodyModel& body, std::string& description) {
  const ReductionSpec& r = body.spec.reduction;
  const auto surface = std::find_if(body.spec.contact_surfaces.begin(), body.spec.contact_surfaces.end(),
                                    [&](const ContactSurfaceSpec& c) { return c.name == r.interface_surface; });
  const PatchSide side = *body.refined.side(surface->side);
  // the centre as a physical point of the side; nodes are ranked by their physical distance
  // to it (parameter distances mislead where the parametrization collapses, e.g. at a pole)
  Eigen::VectorXd xi(body.space.param_dim());
  for (int d = 0, k = 0; d < body.space.param_dim(); ++d)
    xi(d) = d == side.direction ? (side.end ? body.refined.upper(d) : body.refined.lower(d)) : r.interface_center(k++);
  const Eigen::VectorXd centre = body.refined.point(xi);
  std::map<int, double> distance;
  for (int node : side_nodes(body, side)) distance[node] = (body.dofs.node_points().row(node).transpose() - centre).norm();
  std::vector<std::pair<double, int>> ranked;
  for (auto [node, d] : distance) ranked.emplace_back(d, node);
  std::sort(ranked.begin(), ranked.end());
  if (int(ranked.size()) < r.interface_points)
    throw format::InputError(body.spec.file, "reduction.interface_points",
                             std::to_string(r.interface_points) + " requested, the side has " + std::to_string(ranked.size()) + " nodes");
  std::vector<int> dofs;
  for (int k = 0; k < r.interface_points; ++k)
    for (int a = 0; a < body.dofs.dim(); ++a)
      if (const int i = body.dofs.free_index(ranked[std::size_t(k)].second, a); i >= 0) dofs.push_back(i);
  std::sort(dofs.begin(), dofs.end());
  description = std::to_string(r.interface_points) + " control points of '" + surface->name + "' nearest to (" +
                std::to_string(centre(0)) + ", " + std::to_string(centre(1)) + (centre.size() > 2 ? ", " + std::to_string(centre(2)) : "") +
                ") m (" + std::to_string(dofs.size()) + " DOFs)";
  return dofs;
}

ReductionRequest reduction_request(const BodyModel& body) {
  ReductionRequest q;
  q.method = body.spec.reduction.method;
  q.normal_modes = body.spec.reduction.normal_modes;
  if (q.method == "craig-bampton") q.interface_dofs = interface_dofs(body, q.interface_description);
  return q;
}

ReducedBasis reduce_body(const BodyModel& body, const SystemMatrices& system, const Eigen::MatrixXd& extra) {
  const Eigen::MatrixXd rigid = admissible_rigid_fields(rigid_nodal_fields(body.dofs.node_points(), body.spec.analysis),
                                                        body.dofs.free_indices());
  const double scale = eigenvalue_scale(body.spec.material.youngs_modulus, body.spec.material.density, body_size(body));
  ReductionRequest request = reduction_request(body);
  request.extra_vectors = extra;
  return reduce(system.K, system.M, rigid, request, scale);
}

Eigen::MatrixXd nodal_modes(const DofMap& dofs, const Eigen::MatrixXd& Phi_free) {
  Eigen::MatrixXd Phi = Eigen::MatrixXd::Zero(dofs.total_dofs(), Phi_free.cols());
  for (int n = 0; n < dofs.node_count(); ++n)
    for (int a = 0; a < dofs.dim(); ++a)
      if (const int i = dofs.free_index(n, a); i >= 0) Phi.row(n * dofs.dim() + a) = Phi_free.row(i);
  return Phi;
}

namespace {
std::string utc_now() {
  const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
  return buf;
}
}  // namespace

format::Sid build_sid(const BodyModel& body, const SystemMatrices& system, const SparseMatrix& scalar_mass,
                      const ReducedBasis& basis) {
  const ModelSpec& spec = body.spec;
  format::Sid sid;
  sid.body_name = spec.body_name;
  sid.analysis = spec.analysis;
  sid.material = spec.material;
  sid.thickness = spec.thickness;

  const Eigen::MatrixXd Phi = nodal_modes(body.dofs, basis.Phi);
  fill_inertia_terms(sid, scalar_mass, body.dofs.node_points(), Phi);
  auto symmetric = [](const Eigen::MatrixXd& A) { return Eigen::MatrixXd(0.5 * (A + A.transpose())); };
  sid.Me.M0 = symmetric(basis.Phi.transpose() * (system.M * basis.Phi));
  sid.Ke.M0 = symmetric(basis.Phi.transpose() * (system.K * basis.Phi));

  format::RefMod& r = sid.refmod;
  r.frequencies_hz = basis.omega2.cwiseMax(0.0).cwiseSqrt() / (2 * M_PI);
  r.n_low = basis.n_low;
  r.reduction_method = basis.method;
  r.interface_description = basis.interface;
  for (Eigen::Index k = 0; k < basis.Phi.cols(); ++k)
    r.mode_names.push_back((k < basis.n_low ? "low mode " : "high mode ") + std::to_string(k + 1) + ": " +
                           std::to_string(r.frequencies_hz(k)) + " Hz");
  const double f1 = spec.damping.f1_hz > 0 ? spec.damping.f1_hz : r.frequencies_hz(0);
  const double f2 = spec.damping.f2_hz > 0 ? spec.damping.f2_hz : r.frequencies_hz(std::max(0, basis.n_low - 1));
  sid.damping = rayleigh_damping(spec.damping.kappa, f1, std::max(f2, f1));
  sid.De.M0 = sid.damping.alpha1 * sid.Me.M0 + sid.damping.alpha2 * sid.Ke.M0;

  for (const ContactSurfaceSpec& c : spec.contact_surfaces) {
    sid.contact_surfaces.push_back(contact_surface(body, c, Phi));
    sid.master_patches.push_back(master_patch(body, c.name, *body.refined.side(c.side), Phi));
  }
  for (const NodeSpec& n : spec.nodes) sid.nodes.push_back(node_at(body, n, Phi));
  for (const StressLineSpec& l : spec.stress_lines) sid.stress_recovery.push_back(stress_rows(body, l, Phi));

  format::Discretization& mesh = sid.discretization.emplace();
  auto as_vector = [](const std::vector<int>& v) { return Eigen::VectorXi(Eigen::Map<const Eigen::VectorXi>(v.data(), Eigen::Index(v.size()))); };
  mesh.elements_per_level = body.hierarchy ? as_vector(body.hierarchy->elements_per_level) : Eigen::VectorXi::Constant(1, int(body.space.elements.size()));
  mesh.functions_per_level = body.hierarchy ? as_vector(body.hierarchy->functions_per_level) : Eigen::VectorXi::Constant(1, body.space.n_functions());
  mesh.free_dofs = body.dofs.free_count();

  sid.provenance.model_file = spec.file;
  sid.provenance.model_sha256 = std::filesystem::is_regular_file(spec.file) ? common::sha256_file(spec.file) : "";
  sid.provenance.program_version = kProgramVersion;
  sid.provenance.created_utc = utc_now();
  return sid;
}

}  // namespace isosid::prep

// Composition of the SID; see sid_builder.hpp.
#include "sid/sid_builder.hpp"

#include "isosid/format/error.hpp"
#include "isosid/common/invocation.hpp"
#include "isosid/common/sha256.hpp"
#include "isosid/version.hpp"
#include "reduce/sparse_products.hpp"
#include "sid/contact_data.hpp"
#include "sid/joined_surface.hpp"
#include "sid/master_patch.hpp"
#include "sid/node_data.hpp"
#include "sid/section_translation.hpp"
#include "sid/sid_terms.hpp"
#include "sid/stress_rows.hpp"
#include "sid/visual_mesh.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <filesystem>

namespace isosid::prep {

Eigen::MatrixXd nodal_modes(const DofMap& dofs, const Eigen::MatrixXd& Phi_free) {
  Eigen::MatrixXd Phi = Eigen::MatrixXd::Zero(dofs.total_dofs(), Phi_free.cols());
  for (int n = 0; n < dofs.node_count(); ++n)
    for (int a = 0; a < dofs.dim(); ++a)
      if (const int i = dofs.free_index(n, a); i >= 0) Phi.row(n * dofs.dim() + a) = Phi_free.row(i);
  return Phi;
}

namespace {
/// "boundary 7: control point 112 z": which physical DOF a massless coordinate is (its
/// column of the basis is the unit displacement of that DOF at the boundary).
std::string massless_coordinate_name(const BodyModel& body, const ReducedBasis& basis, Eigen::Index k) {
  const Eigen::Index first = basis.Phi.cols() - basis.massless();
  const int dof = basis.massless_dofs[std::size_t(k - first)];
  const char* axes = "xyz";
  for (int n = 0; n < body.dofs.node_count(); ++n)
    for (int a = 0; a < body.dofs.dim(); ++a)
      if (body.dofs.free_index(n, a) == dof)
        return "boundary " + std::to_string(k - first + 1) + ": control point " + std::to_string(n) + " " + axes[a];
  return "boundary " + std::to_string(k - first + 1);
}

}  // namespace

format::Sid build_sid(const BodyModel& body, const SystemMatrices& system, const SparseMatrix& scalar_mass,
                      const ReducedBasis& basis) {
  const ModelSpec& spec = body.spec;
  format::Sid sid;
  sid.body_name = spec.body_name;
  sid.analysis = spec.analysis;
  // one material per SID: a multi-patch body's is that of its (first) contact surface, which
  // the runtime's contact estimates use, else the one that sets the eigenvalue scale
  sid.material = spec.contact_surfaces.empty() ? fastest_material(spec)
                                               : spec.patches[std::size_t(spec.contact_surfaces.front().patch)].material;
  sid.thickness = spec.thickness;

  const Eigen::MatrixXd Phi = nodal_modes(body.dofs, basis.Phi);
  // the inertia terms from the field that carries the mass (MacNeal: the boundary carries none)
  const Eigen::MatrixXd& inertial = basis.mass_carrying();
  const Eigen::MatrixXd inertial_nodal = basis.massless() > 0 ? nodal_modes(body.dofs, inertial) : Eigen::MatrixXd();
  const Eigen::MatrixXd& moving = basis.massless() > 0 ? inertial_nodal : Phi;
  fill_inertia_terms(sid, scalar_mass, body.dofs.node_points(), moving);
  sid.Me.M0 = projected_leading(system.M, inertial);
  sid.Ke.M0 = basis.stiffness.size() ? basis.stiffness : projected(system.K, basis.Phi);

  format::RefMod& r = sid.refmod;
  r.frequencies_hz = basis.omega2.cwiseMax(0.0).cwiseSqrt() / (2 * M_PI);
  r.n_low = basis.n_low;
  r.reduction_method = format::name(basis.method);
  r.interface_description = basis.interface;
  const Eigen::Index first_massless = basis.Phi.cols() - basis.massless();
  for (Eigen::Index k = 0; k < first_massless; ++k)
    r.mode_names.push_back((k < basis.n_low ? "low mode " : "high mode ") + std::to_string(k + 1) + ": " +
                           std::to_string(r.frequencies_hz(k)) + " Hz");
  for (Eigen::Index k = first_massless; k < basis.Phi.cols(); ++k) r.mode_names.push_back(massless_coordinate_name(body, basis, k));
  SectionTranslation sections = section_translation(moving, body.dofs.node_points(), scalar_mass);
  r.section_translation = std::move(sections.shares);
  r.long_axis = sections.long_axis;
  const double f1 = spec.damping.f1_hz > 0 ? spec.damping.f1_hz : r.frequencies_hz(0);
  const double f2 = spec.damping.f2_hz > 0 ? spec.damping.f2_hz : r.frequencies_hz(std::max(0, basis.n_low - 1));
  sid.damping = rayleigh_damping(spec.damping.kappa, f1, std::max(f2, f1));
  sid.De.M0 = sid.damping.alpha1 * sid.Me.M0 + sid.damping.alpha2 * sid.Ke.M0;

  // a Craig-Bampton SID marks its points always (the runtime rebuilds one without the marks)
  const std::vector<int>* interface = format::traits(basis.method).interface_nodes ? &basis.interface_dofs : nullptr;
  for (const ContactSurfaceSpec& c : spec.contact_surfaces) {
    if (c.continued.empty()) {
      sid.contact_surfaces.push_back(contact_surface(body, c, Phi, interface));
      sid.master_patches.push_back(master_patch(body, c.name, c.patch, *body.refined[std::size_t(c.patch)].side(c.side), Phi));
    } else {  // over several patch sides
      JoinedSurface joined = joined_contact_surface(body, c, Phi, interface);
      sid.contact_surfaces.push_back(std::move(joined.surface));
      sid.master_patches.push_back(std::move(joined.master));
    }
  }
  for (const NodeSpec& n : spec.nodes) sid.nodes.push_back(node_at(body, n, Phi));
  for (const StressLineSpec& l : spec.stress_lines) sid.stress_recovery.push_back(stress_rows(body, l, Phi));
  if (spec.patches.size() > 1 && !spec.mesh) {  // the patches, their materials and interfaces; what lies on which (a meshed body: one material, elements)
    for (const PatchSpec& p : spec.patches) sid.patches.push_back({p.name, p.material, {}});
    for (const PatchInterface& i : body.interfaces) {
      sid.patches[std::size_t(i.a)].interfaces.push_back(side_name(i.side_a) + " " + spec.patches[std::size_t(i.b)].name + "." + side_name(i.side_b));
      sid.patches[std::size_t(i.b)].interfaces.push_back(side_name(i.side_b) + " " + spec.patches[std::size_t(i.a)].name + "." + side_name(i.side_a));
    }
    for (std::size_t k = 0; k < spec.contact_surfaces.size(); ++k) {
      const ContactSurfaceSpec& c = spec.contact_surfaces[k];
      sid.contact_surfaces[k].patch = spec.patches[std::size_t(c.patch)].name;
      for (const auto& [patch, side] : c.continued) sid.contact_surfaces[k].patch += " " + spec.patches[std::size_t(patch)].name;
    }
    for (std::size_t k = 0; k < spec.stress_lines.size(); ++k)
      sid.stress_recovery[k].patch = spec.patches[std::size_t(spec.stress_lines[k].patch)].name;
  }

  if (spec.visual) sid.visual = visual_mesh(body, *spec.visual, Phi);

  format::Discretization& mesh = sid.discretization.emplace();
  auto as_vector = [](const std::vector<int>& v) { return Eigen::VectorXi(Eigen::Map<const Eigen::VectorXi>(v.data(), Eigen::Index(v.size()))); };
  mesh.elements_per_level = body.hierarchy ? as_vector(body.hierarchy->elements_per_level) : Eigen::VectorXi::Constant(1, int(body.space.elements.size()));
  mesh.functions_per_level = body.hierarchy ? as_vector(body.hierarchy->functions_per_level) : Eigen::VectorXi::Constant(1, body.space.n_functions());
  mesh.free_dofs = body.dofs.free_count();
  if (spec.contact_resolution) mesh.contact_radius = spec.contact_resolution->contact_radius;

  sid.provenance.model_file = spec.file;
  sid.provenance.model_sha256 = std::filesystem::is_regular_file(spec.file) ? common::sha256_file(spec.file) : "";
  sid.provenance.program_version = kProgramVersion;
  sid.provenance.created_utc = common::utc_now();
  sid.provenance.command_line = common::command_line();
  return sid;
}

}  // namespace isosid::prep

// Test support for the preprocessor: bodies built in code (no model file) and their systems.
#pragma once
#include "assemble/assembly.hpp"
#include "model/body_model.hpp"
#include "reduce/modal_analysis.hpp"
#include "reduce/mode_basis.hpp"

namespace isosid::test {

inline prep::ModelSpec spec_for(prep::NurbsPatch patch, format::AnalysisType type, double E, double nu, double rho,
                                prep::RefinementSpec refinement = {}) {
  prep::ModelSpec s;
  s.file = "test";
  s.body_name = "test";
  s.analysis = type;
  s.patches.push_back({"", {E, nu, rho}, std::move(patch), std::move(refinement)});
  return s;
}

/// Elevation to `degrees`, then every span split into `parts` (per direction).
inline prep::RefinementSpec uniform(std::vector<int> degrees, std::vector<int> parts) {
  prep::RefinementSpec r;
  r.degrees = std::move(degrees);
  r.subdivisions = std::move(parts);
  return r;
}

/// Nodes on any side of any patch of the body (interfaces included).
inline std::vector<int> boundary_nodes(const prep::BodyModel& b) {
  std::vector<int> all;
  for (int k = 0; k < b.space.patch_count(); ++k)
    for (int d = 0; d < b.space.param_dim(); ++d)
      for (int e = 0; e < 2; ++e) {
        const auto n = prep::side_nodes(b, k, {d, e});
        all.insert(all.end(), n.begin(), n.end());
      }
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  return all;
}

/// A body with its stiffness and mass on the free DOFs, its admissible rigid-body fields and its
/// eigenvalue scale: where the reduction tests start.
struct AssembledBody {
  prep::BodyModel body;
  prep::SystemMatrices sys;
  Eigen::MatrixXd rigid;
  double scale = 0;
};

inline AssembledBody assembled(const prep::ModelSpec& spec) {
  AssembledBody f{prep::build_body(spec), {}, {}, 0};
  f.sys = prep::assemble_system(f.body.space, f.body.dofs, f.body.elasticity);
  f.rigid = prep::admissible_rigid_fields(prep::rigid_nodal_fields(f.body.dofs.node_points(), spec.analysis),
                                         f.body.dofs.free_indices());
  const format::Material& m = prep::fastest_material(spec);
  f.scale = prep::eigenvalue_scale(m.youngs_modulus, m.density, prep::body_size(f.body));
  return f;
}

/// Free DOF indices (ascending) of the nodes on a side of a patch.
inline std::vector<int> side_free_dofs(const prep::BodyModel& b, int patch, prep::PatchSide side) {
  std::vector<int> dofs;
  for (int node : prep::side_nodes(b, patch, side))
    for (int a = 0; a < b.dofs.dim(); ++a)
      if (const int i = b.dofs.free_index(node, a); i >= 0) dofs.push_back(i);
  std::sort(dofs.begin(), dofs.end());
  return dofs;
}

}  // namespace isosid::test

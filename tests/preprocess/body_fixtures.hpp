// Test support for the preprocessor: bodies built in code (no model file) and their systems.
#pragma once
#include "assemble/assembly.hpp"
#include "model/body_model.hpp"

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

}  // namespace isosid::test

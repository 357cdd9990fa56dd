// Model files (*.model.toml): body, analysis type, material, geometry, refinement, boundary
// conditions. Parsed strictly; see models/README.md for the keys.
#pragma once
#include "geometry/nurbs_patch.hpp"
#include "isosid/format/sid.hpp"
#include "refine/graded_knots.hpp"

#include <string>
#include <vector>

namespace isosid::prep {

struct FixedComponents {
  std::string side;                 ///< canonical or primitive side name
  std::vector<int> components;      ///< 0 = x, 1 = y, 2 = z
};

struct RefinementSpec {
  std::vector<int> degrees;         ///< target degree per direction (elevation first)
  std::vector<int> subdivisions;    ///< uniform split of every span per direction
  std::vector<GradingRequest> graded;
};

struct ModelSpec {
  std::string file;                 ///< path of the model file
  std::string body_name;
  format::AnalysisType analysis = format::AnalysisType::Solid;
  format::Material material;
  double thickness = 1.0;
  NurbsPatch patch;                 ///< the coarse, exact geometry
  RefinementSpec refinement;
  std::vector<FixedComponents> fixed;
  int extra_quadrature_points = 0;
};

/// Reads and validates a model file; throws InputError(file, field, problem).
ModelSpec read_model_file(const std::string& path);

}  // namespace isosid::prep

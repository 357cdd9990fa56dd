// Names of the analysis types as they appear in model, scene and SID files.
#include "isosid/format/analysis_type.hpp"

namespace isosid::format {

std::string to_string(AnalysisType type) {
  switch (type) {
    case AnalysisType::PlaneStrain: return "plane_strain";
    case AnalysisType::PlaneStress: return "plane_stress";
    case AnalysisType::Axisymmetric: return "axisymmetric";
    case AnalysisType::Solid: return "solid";
  }
  return "unknown";
}

std::optional<AnalysisType> analysis_type_from_string(std::string_view name) {
  for (AnalysisType t : {AnalysisType::PlaneStrain, AnalysisType::PlaneStress, AnalysisType::Axisymmetric,
                         AnalysisType::Solid})
    if (to_string(t) == name) return t;
  return std::nullopt;
}

}  // namespace isosid::format

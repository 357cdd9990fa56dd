// The kinematic model of a body: 2D (plane strain, plane stress, axisymmetric) or 3D solid.
#pragma once
#include <optional>
#include <string>
#include <string_view>

namespace isosid::format {

enum class AnalysisType { PlaneStrain, PlaneStress, Axisymmetric, Solid };

std::string to_string(AnalysisType type);
std::optional<AnalysisType> analysis_type_from_string(std::string_view name);

/// Number of displacement components of the analysis (2 for the 2D types, 3 for solids).
inline int spatial_dim(AnalysisType type) { return type == AnalysisType::Solid ? 3 : 2; }

}  // namespace isosid::format

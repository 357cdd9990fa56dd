// Gauss points on a side of the body with outward normals and measure-weighted quadrature
// weights (length x thickness, length x 2 pi r, or area): for tractions and contact surfaces.
#pragma once
#include "space/analysis_space.hpp"
#include "assemble/body_elasticity.hpp"

#include <array>
#include <vector>

namespace isosid::prep {

struct BoundaryPoint {
  int element = 0;
  Eigen::Vector3d t = Eigen::Vector3d::Zero();  ///< reference coordinates in the element
  Eigen::VectorXd xi, x, normal;                ///< patch parameter, position, outward unit normal
  double weight = 0;                            ///< quadrature weight incl. measure, m^2 (m in planar per thickness)
  Eigen::VectorXd R;                            ///< functions of the element at the point
};

/// Parametric interval per tangential direction (in the order of the directions).
using SideInterval = std::vector<std::array<double, 2>>;

/// `points_per_direction` Gauss points in each tangential direction of every element on the
/// side of the patch (p+1 of that direction when 0). With an interval, each element's tangential range is
/// clipped to it and the rule mapped onto the intersection, so the points integrate exactly
/// over the interval.
std::vector<BoundaryPoint> boundary_points(const AnalysisSpace& space, const BodyElasticity& elasticity, int patch, PatchSide side,
                                           int points_per_direction = 0, const SideInterval& interval = {});

}  // namespace isosid::prep

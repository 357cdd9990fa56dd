// Placing the named points of a model (nodes, stress lines) on its body: by patch parameter,
// or by a physical point taken to the nearest point of the exact NURBS geometry.
#pragma once
#include "geometry/nurbs_patch.hpp"

#include <Eigen/Dense>
#include <vector>

namespace isosid::prep {

/// A point as a model file gives it: a patch parameter, or a physical point in metres.
struct GivenPoint {
  Eigen::VectorXd value;
  bool physical = false;
};

struct BodyPoint {
  Eigen::VectorXd parameter;  ///< patch parameter
  Eigen::VectorXd x;          ///< the physical point there (m)
  double distance = 0;        ///< from a given physical point to it (0 inside the body, to round-off)
};

/// The point of the body (the whole patch, a solid) nearest to `x`: the best of a coarse
/// sample of the parameter box, then Gauss-Newton steps kept inside the box (a direction at
/// a bound that the gradient pushes outward stays there).
BodyPoint nearest_point(const NurbsPatch& patch, const Eigen::VectorXd& x);

/// The body point a given point names: the parameter itself, or the nearest body point.
BodyPoint place(const NurbsPatch& patch, const GivenPoint& given);

/// How far outside the body a physical point may lie and still be placed on it: 1e-6 of the
/// body's size (control-net diagonal), far above the round-off of coordinates written to
/// seven digits and far below any element.
double placement_tolerance(const NurbsPatch& patch);

/// The `points` points of a line between two ends of one kind, evenly spaced in patch
/// parameter, or for physical ends on the straight segment, each placed by nearest_point
/// (its `distance` says how far the segment runs outside the body there).
std::vector<BodyPoint> line_points(const NurbsPatch& patch, const GivenPoint& from, const GivenPoint& to, int points);

}  // namespace isosid::prep

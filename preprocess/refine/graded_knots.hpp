// Knots graded geometrically toward a parametric location, sized in metres: the element at
// the location is `smallest` long in physical space and each neighbour `growth` times longer,
// until the spans reach the size they already have.
#pragma once
#include "geometry/nurbs_patch.hpp"

#include <vector>

namespace isosid::prep {

struct GradingRequest {
  int direction = 0;
  double toward = 0;       ///< parameter value the grading is centred on
  double smallest = 0;     ///< m, physical length of the element(s) at `toward`
  double growth = 1.3;     ///< ratio of neighbouring element lengths (> 1)
};

/// Knots to insert. Physical lengths are measured with the largest speed |dx/dxi_dir| over
/// the other directions (so no element at the location is longer than `smallest`).
std::vector<double> graded_knots(const NurbsPatch& patch, const GradingRequest& request);

/// How many knots graded_knots would insert at most, without marching them: each side of
/// `toward` grows its elements from `smallest` by `growth` until they span the rest of the
/// direction or reach its largest existing span, log(1 + L (growth - 1) / smallest) /
/// log(growth) elements for a physical length L (speeds sampled as graded_knots does).
double graded_knot_count_bound(const NurbsPatch& patch, const GradingRequest& request);

}  // namespace isosid::prep

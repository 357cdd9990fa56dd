// Gauss points of an element: reference coordinates and parametric weights (det J and the
// measure factor are applied by the caller at the evaluated point).
#pragma once
#include "space/analysis_space.hpp"

#include <vector>

namespace isosid::prep {

struct QuadPoint {
  double t[3] = {0, 0, 0};  ///< reference coordinates in [0,1]^d
  double weight = 0;        ///< Gauss weight times the element's parametric size
};

/// (p+1+extra) points per direction.
std::vector<QuadPoint> element_quadrature(const AnalysisSpace& space, const Element& e, int extra = 0);

}  // namespace isosid::prep

// Analysis spaces; see analysis_space.hpp.
#include "space/analysis_space.hpp"

#include "thb/hierarchical_space.hpp"

namespace isosid::prep {

int AnalysisSpace::bernstein_count() const {
  int n = 1;
  for (int p : degrees) n *= p + 1;
  return n;
}

double AnalysisSpace::parametric_size(const Element& e) const {
  double size = 1;
  for (int d = 0; d < param_dim(); ++d) size *= e.hi(d) - e.lo(d);
  return size;
}

bool AnalysisSpace::on_side(const Element& e, PatchSide side) const {
  const auto d = side.direction;
  return side.end == 0 ? e.lo(d) == param_lo(d) : e.hi(d) == param_hi(d);
}

AnalysisSpace tensor_space(const NurbsPatch& patch) {
  AnalysisSpace space = hierarchical_space(patch, HierarchicalMesh::single_level(patch)).space;
  // one level reproduces the patch; keep its control points and weights bit for bit
  space.control_points = patch.points;
  space.weights = patch.weights;
  return space;
}

}  // namespace isosid::prep

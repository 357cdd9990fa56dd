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
  const PatchRange& box = patch_boxes[std::size_t(e.patch)];
  return side.end == 0 ? e.lo(d) == box.lo(d) : e.hi(d) == box.hi(d);
}

AnalysisSpace tensor_space(const NurbsPatch& patch) {
  AnalysisSpace space = hierarchical_space(patch, HierarchicalMesh::single_level(patch)).space;
  // one level reproduces the patch; keep its control points and weights bit for bit
  space.control_points = patch.points;
  space.weights = patch.weights;
  return space;
}

AnalysisSpace join_spaces(std::vector<AnalysisSpace> spaces) {
  AnalysisSpace joined = std::move(spaces.front());
  for (std::size_t k = 1; k < spaces.size(); ++k) {
    AnalysisSpace& s = spaces[k];
    const int offset = joined.n_functions(), patch_offset = joined.patch_count();
    for (Element& e : s.elements) {
      for (int& f : e.functions) f += offset;
      e.patch += patch_offset;
      joined.elements.push_back(std::move(e));
    }
    joined.control_points.conservativeResize(offset + s.n_functions(), Eigen::NoChange);
    joined.control_points.bottomRows(s.n_functions()) = s.control_points;
    joined.weights.conservativeResize(offset + s.n_functions());
    joined.weights.tail(s.n_functions()) = s.weights;
    const std::vector<int> levels = s.function_level.empty() ? std::vector<int>(std::size_t(s.n_functions()), 0) : s.function_level;
    if (joined.function_level.empty()) joined.function_level.assign(std::size_t(offset), 0);
    joined.function_level.insert(joined.function_level.end(), levels.begin(), levels.end());
    joined.patch_boxes.insert(joined.patch_boxes.end(), s.patch_boxes.begin(), s.patch_boxes.end());
    for (int first : s.patch_first_function) joined.patch_first_function.push_back(offset + first);
  }
  return joined;
}

}  // namespace isosid::prep

// Edge elements of a contact surface; see surface_edge.hpp.
#include "contact/surface_edge.hpp"

#include "isosid/format/patch_side.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

namespace isosid::run {

namespace {
struct Range {
  double lo = INFINITY, hi = -INFINITY;
  void add(double x) { lo = std::min(lo, x), hi = std::max(hi, x); }
  double width() const { return hi - lo; }
};

/// Largest distance between two of the points, m.
double spread(const format::ContactSurface& s, const std::vector<Eigen::Index>& points) {
  double d = 0;
  for (const Eigen::Index a : points)
    for (const Eigen::Index b : points) d = std::max(d, (s.position.row(a) - s.position.row(b)).norm());
  return d;
}
/// The parameter range of the whole patch side along surface direction d, if the surface lies on
/// one patch of a one-patch body and `side_patch` describes its side.
std::optional<Range> side_range(const format::ContactSurface& surface, const format::MasterPatch* side_patch, Eigen::Index d) {
  if (!side_patch || !surface.patch.empty()) return std::nullopt;
  const auto side = format::side_from_name(surface.side, int(surface.parameter.cols()));
  if (!side || d == side->direction) return std::nullopt;
  const std::size_t k = std::size_t(d - (d > side->direction ? 1 : 0));  // the side's directions skip the fixed one
  if (k >= side_patch->knots.size() || side_patch->knots[k].size() == 0) return std::nullopt;
  const Eigen::VectorXd& knots = side_patch->knots[k];
  return Range{knots(0), knots(knots.size() - 1)};
}
}  // namespace

std::vector<char> edge_points(const format::ContactSurface& surface, format::AnalysisType analysis,
                              const format::MasterPatch* side_patch) {
  const Eigen::Index n = surface.points();
  std::vector<char> edge(std::size_t(n), 0);
  for (Eigen::Index d = 0; d < surface.parameter.cols(); ++d) {
    Range all;
    std::map<int, Range> element;  // the span of each element's Gauss points along d
    std::map<int, std::vector<Eigen::Index>> members;
    for (Eigen::Index g = 0; g < n; ++g) {
      all.add(surface.parameter(g, d));
      element[surface.element(g)].add(surface.parameter(g, d));
      members[surface.element(g)].push_back(g);
    }
    if (all.width() <= 0) continue;  // the side's fixed direction
    // an element's Gauss points stop short of its ends by a small fraction of it (0.05 of its
    // length for 5 points, 0.2 for 2), so the first element's start lies within half its
    // points' span of the surface's first point; its neighbour's lies a whole element further.
    // Per end: its elements, and their points nearest the end (the end's "front")
    std::map<int, std::vector<int>> end_elements;
    std::map<int, std::vector<Eigen::Index>> front;
    std::map<int, double> size;      // the spread of each end element's points, m
    double element_size = INFINITY;  // the smallest of them
    std::map<int, bool> corner;      // per end: the end of the body's side
    const std::optional<Range> whole_side = side_range(surface, side_patch, d);
    for (const auto& [e, r] : element) {
      int end = 0;
      if (r.lo - all.lo <= 0.5 * r.width()) end = -1;
      else if (all.hi - r.hi <= 0.5 * r.width()) end = +1;
      if (end == 0) continue;
      if (whole_side) corner[end] = end < 0 ? r.lo - whole_side->lo <= 0.5 * r.width() : whole_side->hi - r.hi <= 0.5 * r.width();
      end_elements[end].push_back(e);
      size[e] = spread(surface, members[e]);
      element_size = std::min(element_size, size[e]);
      const double extreme = end < 0 ? r.lo : r.hi;
      for (const Eigen::Index g : members[e])
        if (std::abs(surface.parameter(g, d) - extreme) <= 1e-9 * all.width()) front[end].push_back(g);
    }
    // across a seam a front point's partner lies a small fraction of its element away
    auto near_any = [&](Eigen::Index g, const std::vector<Eigen::Index>& others) {
      for (const Eigen::Index o : others)
        if ((surface.position.row(g) - surface.position.row(o)).norm() < 0.5 * size[surface.element(g)]) return true;
      return false;
    };
    for (const int end : {-1, +1}) {
      const std::vector<Eigen::Index>& f = front[end];
      if (f.empty()) continue;
      // a pole: the front shrinks to a point (3D), or reaches the axis (axisymmetric curve)
      const bool pole = surface.position.cols() == 3
                            ? spread(surface, f) < 0.5 * element_size
                            : analysis == format::AnalysisType::Axisymmetric &&
                                  std::all_of(f.begin(), f.end(), [&](Eigen::Index g) { return std::abs(surface.position(g, 0)) < 0.5 * element_size; });
      // a seam: every point of this front lies next to one of the other end's
      const bool seam = std::all_of(f.begin(), f.end(), [&](Eigen::Index g) { return near_any(g, front[-end]); });
      if (pole || seam || corner[end]) continue;
      for (const int e : end_elements[end])
        for (const Eigen::Index g : members[e]) edge[std::size_t(g)] = 1;
    }
  }
  return edge;
}

}  // namespace isosid::run

// Coincident-point merging and free-DOF numbering; see dof_map.hpp.
#include "space/dof_map.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace isosid::prep {

DofMap::DofMap(const AnalysisSpace& space, int dim, double tolerance, const std::vector<std::pair<int, PatchSide>>& point_sides)
    : dim_(dim) {
  const Eigen::MatrixXd& P = space.control_points;
  const int n = int(P.rows());
  std::vector<bool> on_point_side(std::size_t(n), false);
  for (const Element& e : space.elements)
    for (const auto& [patch, side] : point_sides)
      if (e.patch == patch && space.on_side(e, side))
        for (int f : e.functions) on_point_side[f] = true;
  auto level = [&](int f) { return space.function_level.empty() ? 0 : space.function_level[f]; };
  auto mergeable = [&](int f, int g) {
    return level(f) == level(g) || (on_point_side[f] && on_point_side[g]);
  };
  // sort by the first coordinate, then compare points whose first coordinates are close
  std::vector<int> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return P(a, 0) < P(b, 0); });
  node_of_function_.assign(std::size_t(n), -1);
  std::vector<int> representative;
  for (std::size_t i = 0; i < order.size(); ++i) {
    const int f = order[i];
    if (node_of_function_[f] >= 0) continue;
    const int node = int(representative.size());
    representative.push_back(f);
    node_of_function_[f] = node;
    for (std::size_t j = i + 1; j < order.size() && P(order[j], 0) - P(f, 0) <= tolerance; ++j) {
      const int g = order[j];
      if (node_of_function_[g] < 0 && (P.row(g) - P.row(f)).norm() <= tolerance && mergeable(f, g))
        node_of_function_[g] = node;
    }
  }
  // number nodes in the order of their first function, so numbering follows the patch layout
  std::vector<int> first_function(representative.size(), n);
  for (int f = 0; f < n; ++f) first_function[node_of_function_[f]] =
      std::min(first_function[node_of_function_[f]], f);
  std::vector<int> node_order(representative.size());
  std::iota(node_order.begin(), node_order.end(), 0);
  std::sort(node_order.begin(), node_order.end(), [&](int a, int b) { return first_function[a] < first_function[b]; });
  std::vector<int> renamed(representative.size());
  for (std::size_t k = 0; k < node_order.size(); ++k) renamed[node_order[k]] = int(k);
  node_points_.resize(Eigen::Index(representative.size()), P.cols());
  for (int f = 0; f < n; ++f) {
    int& node = node_of_function_[f];
    node = renamed[node];
    node_points_.row(node) = P.row(f);
  }
  fixed_.assign(std::size_t(node_count() * dim_), false);
  renumber();
}

void DofMap::fix(int node, int component) {
  fixed_[node * dim_ + component] = true;
  renumber();
}

void DofMap::element_nodes(const Element& element, std::vector<int>& nodes) const {
  nodes.clear();
  for (int f : element.functions) nodes.push_back(node_of(f));
}

void DofMap::element_free_dofs(const Element& element, std::vector<int>& free) const {
  free.clear();
  for (int f : element.functions)
    for (int a = 0; a < dim_; ++a) free.push_back(free_index(node_of(f), a));
}

void DofMap::renumber() {
  free_.assign(fixed_.size(), -1);
  n_free_ = 0;
  for (std::size_t i = 0; i < fixed_.size(); ++i)
    if (!fixed_[i]) free_[i] = n_free_++;
}

}  // namespace isosid::prep

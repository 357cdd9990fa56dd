// Node-graph sparsity and in-place element scatter; see element_pattern.hpp.
#include "assemble/element_pattern.hpp"

#include <algorithm>

namespace isosid::prep {

ElementPattern::ElementPattern(const AnalysisSpace& space, const DofMap& dofs, Unknowns unknowns, Coupling coupling)
    : dofs_(dofs), unknowns_(unknowns), coupling_(coupling) {
  components_ = unknowns == Unknowns::FreeDofs ? dofs.dim() : 1;
  size_ = unknowns == Unknowns::FreeDofs ? dofs.free_count() : dofs.node_count();
  // nodes coupled with each node through a shared element
  std::vector<std::vector<int>> coupled(std::size_t(dofs.node_count()));
  std::vector<int> nodes;
  for (const Element& e : space.elements) {
    dofs.element_nodes(e, nodes);
    for (int g : nodes) coupled[g].insert(coupled[g].end(), nodes.begin(), nodes.end());
  }
  auto unknown = [&](int node, int a) { return unknowns == Unknowns::FreeDofs ? dofs.free_index(node, a) : node; };
  // columns in increasing unknown order: free indices grow with (node, component)
  column_start_.reserve(std::size_t(size_) + 1);
  column_start_.push_back(0);
  for (int g = 0; g < dofs.node_count(); ++g) {
    std::vector<int>& around = coupled[g];
    std::sort(around.begin(), around.end());
    around.erase(std::unique(around.begin(), around.end()), around.end());
    for (int b = 0; b < components_; ++b) {
      if (unknown(g, b) < 0) continue;
      for (int node : around)
        for (int a = 0; a < components_; ++a) {
          const int row = unknown(node, a);
          if (row >= 0 && (coupling == Coupling::AllComponents || a == b)) rows_.push_back(row);
        }
      column_start_.push_back(int(rows_.size()));
    }
  }
}

void ElementPattern::element_unknowns(const Element& element, std::vector<int>& index) const {
  if (unknowns_ == Unknowns::FreeDofs)
    dofs_.element_free_dofs(element, index);
  else
    dofs_.element_nodes(element, index);
}

SparseMatrix ElementPattern::zero_matrix() const {
  SparseMatrix m(size_, size_);
  m.resizeNonZeros(non_zeros());
  std::copy(column_start_.begin(), column_start_.end(), m.outerIndexPtr());
  std::copy(rows_.begin(), rows_.end(), m.innerIndexPtr());
  std::fill_n(m.valuePtr(), non_zeros(), 0.0);
  return m;
}

void PatternAccumulator::add_into_and_release(double* values) {
  const std::size_t n = std::size_t(pattern_.non_zeros());
  for (std::size_t i = 0; i < n; ++i) values[i] += values_[i];
  own_.clear();
  own_.shrink_to_fit();
  values_ = nullptr;
}

void PatternAccumulator::add(const Element& element, const Eigen::MatrixXd& local) {
  const ElementPattern& p = pattern_;
  p.element_unknowns(element, index_);
  by_row_.clear();
  for (int i = 0; i < int(index_.size()); ++i)
    if (index_[i] >= 0) by_row_.emplace_back(index_[i], i);
  std::sort(by_row_.begin(), by_row_.end());
  const bool same_component_only = p.coupling_ == Coupling::SameComponent;
  for (int j = 0; j < int(index_.size()); ++j) {
    const int column = index_[j];
    if (column < 0) continue;
    // walk the column's sorted rows alongside the element's sorted rows
    const int* row = p.rows_.data() + p.column_start_[column];
    for (const auto& [global, i] : by_row_) {
      if (same_component_only && i % p.components_ != j % p.components_) continue;
      while (*row < global) ++row;
      values_[std::size_t(row - p.rows_.data())] += local(i, j);
    }
  }
}

}  // namespace isosid::prep

// Sparsity of a global matrix that couples the unknowns of every element with each other,
// built once from the node graph, so that element matrices are added in place into its
// values (no triplet lists, no sort of duplicates).
#pragma once
#include "space/analysis_space.hpp"
#include "space/dof_map.hpp"

#include <Eigen/Sparse>
#include <vector>

namespace isosid::prep {

using SparseMatrix = Eigen::SparseMatrix<double>;

/// What the rows and columns of a global matrix are.
enum class Unknowns {
  FreeDofs,  ///< free index of (node, component); fixed components dropped
  Nodes,     ///< one per node (scalar matrices over all nodes)
};

/// Which components of two coupled nodes a matrix connects (FreeDofs only).
enum class Coupling {
  AllComponents,  ///< stiffness
  SameComponent,  ///< mass: u_a couples with u_a only
};

class ElementPattern {
public:
  ElementPattern(const AnalysisSpace& space, const DofMap& dofs, Unknowns unknowns, Coupling coupling);

  Unknowns unknowns() const { return unknowns_; }
  Eigen::Index non_zeros() const { return Eigen::Index(rows_.size()); }
  /// Global unknown of each local row of an element matrix (f*components + a), -1 where dropped.
  void element_unknowns(const Element& element, std::vector<int>& index) const;
  /// The matrix with this pattern, its values zero (an accumulator may then sum into them).
  SparseMatrix zero_matrix() const;

private:
  const DofMap& dofs_;
  Unknowns unknowns_;
  Coupling coupling_;
  int components_ = 1;              ///< unknowns per node
  int size_ = 0;                    ///< rows = columns
  std::vector<int> column_start_;   ///< size_ + 1 offsets into rows_
  std::vector<int> rows_;           ///< sorted row indices of each column
  friend class PatternAccumulator;
};

/// One thread's sum of element matrices in the values of a pattern: its own, or those of a
/// matrix with the pattern (ElementPattern::zero_matrix), which then needs no copy.
class PatternAccumulator {
public:
  /// Sums into values of its own.
  explicit PatternAccumulator(const ElementPattern& pattern)
      : pattern_(pattern), own_(std::size_t(pattern.non_zeros()), 0.0), values_(own_.data()) {}
  /// Sums into `values` (non_zeros long, zero at first), which must outlive it.
  PatternAccumulator(const ElementPattern& pattern, double* values) : pattern_(pattern), values_(values) {}
  PatternAccumulator(const PatternAccumulator&) = delete;
  PatternAccumulator& operator=(const PatternAccumulator&) = delete;
  PatternAccumulator(PatternAccumulator&&) = default;
  /// Adds the element matrix `local`, whose rows and columns are `element`'s local unknowns.
  void add(const Element& element, const Eigen::MatrixXd& local);
  /// Adds its sum into `values` (non_zeros long) and frees values of its own.
  void add_into_and_release(double* values);

private:
  const ElementPattern& pattern_;
  std::vector<double> own_;                    ///< empty when it sums into a matrix's values
  double* values_;
  std::vector<int> index_;                     ///< global unknown of each local row
  std::vector<std::pair<int, int>> by_row_;    ///< (global row, local row), sorted
};

}  // namespace isosid::prep

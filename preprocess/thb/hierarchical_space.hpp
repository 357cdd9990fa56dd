// Truncated hierarchical B-splines (THB, Giannelli, Juettler & Speleers, CAGD 29 (2012) 485)
// on a NURBS patch, as an AnalysisSpace: per-level tensor bases, the active functions of each
// level (support inside Omega^l, not inside Omega^{l+1}), truncation (a coarse function drops
// its finer components whose support lies in the finer domain) and element extraction
// operators for the active elements of every level. NURBS weights are carried by the THB
// coefficients of the patch's weight function, so the geometry map stays the patch's exactly.
// A one-level hierarchy is the patch's tensor-product space.
#pragma once
#include "space/analysis_space.hpp"
#include "thb/hierarchical_mesh.hpp"

#include <Eigen/Sparse>

namespace isosid::prep {

struct HierarchicalSpace {
  AnalysisSpace space;
  /// n_functions x n_patch_functions: the coefficients (control point values) in this space of
  /// any field given by coefficients on the patch's functions (exact: the patch space is nested).
  Eigen::SparseMatrix<double> prolongation;
  std::vector<int> functions_per_level, elements_per_level;
};

HierarchicalSpace hierarchical_space(const NurbsPatch& patch, const HierarchicalMesh& mesh);

}  // namespace isosid::prep

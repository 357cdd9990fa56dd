// Model reduction as chosen in the model file: modal truncation, Craig-Bampton or the full
// modal basis; every result is a Buckens-frame, M-orthonormal, K-diagonal basis.
#pragma once
#include "reduce/mode_basis.hpp"

#include <Eigen/Sparse>
#include <string>
#include <vector>

namespace isosid::prep {

struct ReductionRequest {
  std::string method = "modal";      ///< modal | craig-bampton | full
  int normal_modes = 10;             ///< modal: elastic modes kept; craig-bampton: fixed-interface modes
  std::vector<int> interface_dofs;   ///< free DOF indices (craig-bampton)
  std::string interface_description;
  Eigen::MatrixXd extra_vectors;     ///< free DOFs x k, added to the basis (e.g. a coarse model's modes)
};

/// `rigid` holds the admissible rigid-body fields on the free DOFs (columns).
ReducedBasis reduce(const Eigen::SparseMatrix<double>& K, const Eigen::SparseMatrix<double>& M, const Eigen::MatrixXd& rigid,
                    const ReductionRequest& request, double lambda_scale);

}  // namespace isosid::prep

// Model reduction as chosen in the model file: modal truncation, Craig-Bampton, the full
// modal basis, or a massless boundary (MacNeal, massless Craig-Bampton). Every result is a Buckens-frame basis;
// all but the massless-boundary ones are M-orthonormal and K-diagonal.
#pragma once
#include "isosid/format/reduction_method.hpp"
#include "reduce/mode_basis.hpp"

#include <Eigen/Sparse>
#include <string>
#include <vector>

namespace isosid::prep {

struct ReductionRequest {
  format::ReductionMethod method = format::ReductionMethod::Modal;
  int normal_modes = 10;             ///< modal, macneal: elastic modes kept; craig-bampton(-massless): fixed-interface modes
  std::vector<int> interface_dofs;   ///< free DOF indices (craig-bampton: interface; massless methods: the boundary)
  std::string interface_description;
  Eigen::MatrixXd extra_vectors;     ///< free DOFs x k, added to the basis (e.g. a coarse model's modes)
};

/// `rigid` holds the admissible rigid-body fields on the free DOFs (columns).
ReducedBasis reduce(const Eigen::SparseMatrix<double>& K, const Eigen::SparseMatrix<double>& M, const Eigen::MatrixXd& rigid,
                    const ReductionRequest& request, double lambda_scale);

}  // namespace isosid::prep

// Sparse times dense by rows; see sparse_products.hpp.
#include "reduce/sparse_products.hpp"

namespace isosid::prep {

Eigen::MatrixXd sparse_times(const Eigen::SparseMatrix<double>& A, const Eigen::Ref<const Eigen::MatrixXd>& X) {
  using RowMajorMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  const RowMajorMatrix rows = X;
  RowMajorMatrix product(A.rows(), X.cols());
  product.noalias() = A * rows;
  return product;
}

Eigen::MatrixXd projected(const Eigen::SparseMatrix<double>& A, const Eigen::Ref<const Eigen::MatrixXd>& X) {
  const Eigen::MatrixXd P = X.transpose() * sparse_times(A, X);
  return 0.5 * (P + P.transpose());
}

}  // namespace isosid::prep

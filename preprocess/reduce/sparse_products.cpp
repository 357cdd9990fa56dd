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

Eigen::Index leading_columns(const Eigen::Ref<const Eigen::MatrixXd>& X) {
  Eigen::Index used = X.cols();
  while (used > 0 && X.col(used - 1).isZero(0.0)) --used;
  return used;
}

Eigen::MatrixXd projected_leading(const Eigen::SparseMatrix<double>& A, const Eigen::Ref<const Eigen::MatrixXd>& X) {
  const Eigen::Index used = leading_columns(X);
  Eigen::MatrixXd P = Eigen::MatrixXd::Zero(X.cols(), X.cols());
  P.topLeftCorner(used, used) = projected(A, X.leftCols(used));
  return P;
}

}  // namespace isosid::prep

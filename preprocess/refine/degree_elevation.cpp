// Order elevation by collocation; see degree_elevation.hpp.
#include "refine/degree_elevation.hpp"

#include "isosid/common/dense_decompositions.hpp"

#include <Eigen/LU>

namespace isosid::prep {

KnotVector elevated_knots(const KnotVector& U, int p, int t) {
  (void)p;
  std::vector<double> out;
  for (Eigen::Index i = 0; i < U.size(); ++i) {
    out.push_back(U(i));
    if (i + 1 == U.size() || U(i + 1) != U(i))
      for (int k = 0; k < t; ++k) out.push_back(U(i));
  }
  return Eigen::Map<Eigen::VectorXd>(out.data(), Eigen::Index(out.size()));
}

Eigen::MatrixXd degree_elevation_matrix(const KnotVector& U, int p, int t) {
  const KnotVector Un = elevated_knots(U, p, t);
  const int q = p + t, nn = basis_count(Un, q), no = basis_count(U, p);
  Eigen::MatrixXd A(nn, nn), B(nn, no);
  for (int j = 0; j < nn; ++j) {
    const double g = greville_abscissa(Un, q, j);
    A.row(j) = basis_row(Un, q, g).transpose();
    B.row(j) = basis_row(U, p, g).transpose();
  }
  return Eigen::PartialPivLU<Eigen::MatrixXd>(A).solve(B);
}

}  // namespace isosid::prep

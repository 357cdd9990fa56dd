// Ke or De in the SID's normal form; see modal_matrix.hpp.
#include "body/modal_matrix.hpp"

#include <cmath>

namespace isosid::run {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;

ModalMatrix::ModalMatrix(const MatrixXd& M) {
  // The SID's normal form is diagonal by construction; what its reduction leaves off the
  // diagonal is round-off of the orthogonalization, measured up to 2.4e-9 of sqrt(M_ii M_jj)
  // (a Craig-Bampton beam, its interface modes at 1e16 beside normal modes at 1e9; measured
  // against the largest entry instead, that round-off is 1.4e-12 of it, and a bound there
  // would have to grow with the spread of the diagonal). Dropping entries below
  // kRoundoff sqrt(M_ii M_jj) changes the scaled matrix D^-1/2 M D^-1/2 by at most
  // n kRoundoff in norm (Gershgorin: 3e-6 at n = 300) and its eigenvalues only at second order.
  constexpr double kRoundoff = 1e-8;
  const Index n = M.rows();
  if (n == 0) return;  // a rigid body's
  const VectorXd root = M.diagonal().cwiseAbs().cwiseSqrt();
  auto coupled = [&](Index i) {
    for (Index j = 0; j < n; ++j)
      if (j != i && (std::abs(M(i, j)) > kRoundoff * root(i) * root(j) || std::abs(M(j, i)) > kRoundoff * root(i) * root(j))) return true;
    return false;
  };
  // the leading coordinates whose row and column hold nothing beside the diagonal
  Index d = 0;
  while (d < n && !coupled(d)) ++d;
  diagonal_ = M.diagonal().head(d);
  if (d < n) trailing_ = M.bottomRightCorner(n - d, n - d);
}

}  // namespace isosid::run

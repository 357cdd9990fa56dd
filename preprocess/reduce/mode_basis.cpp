// Buckens projection and orthonormalization; see mode_basis.hpp.
#include "reduce/mode_basis.hpp"

#include "isosid/common/dense_decompositions.hpp"
#include "reduce/sparse_products.hpp"

namespace isosid::prep {

Eigen::MatrixXd rigid_nodal_fields(const Eigen::MatrixXd& P, format::AnalysisType analysis) {
  const Eigen::Index n = P.rows();
  using format::AnalysisType;
  if (analysis == AnalysisType::Axisymmetric) {
    Eigen::MatrixXd R = Eigen::MatrixXd::Zero(2 * n, 1);
    for (Eigen::Index i = 0; i < n; ++i) R(2 * i + 1, 0) = 1;
    return R;
  }
  if (analysis != AnalysisType::Solid) {
    Eigen::MatrixXd R = Eigen::MatrixXd::Zero(2 * n, 3);
    for (Eigen::Index i = 0; i < n; ++i) {
      R(2 * i, 0) = 1;
      R(2 * i + 1, 1) = 1;
      R(2 * i, 2) = -P(i, 1);
      R(2 * i + 1, 2) = P(i, 0);
    }
    return R;
  }
  Eigen::MatrixXd R = Eigen::MatrixXd::Zero(3 * n, 6);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Vector3d x = P.row(i).transpose();
    for (int a = 0; a < 3; ++a) {
      R(3 * i + a, a) = 1;
      const Eigen::Vector3d rotation = Eigen::Vector3d::Unit(a).cross(x);  // e_a x x
      R.block(3 * i, 3 + a, 3, 1) = rotation;
    }
  }
  return R;
}

Eigen::MatrixXd admissible_rigid_fields(const Eigen::MatrixXd& rigid_nodal, const std::vector<int>& free_of_dof) {
  // a rigid field is admissible if it does not move any fixed DOF
  std::vector<Eigen::Index> keep;
  int n_free = 0;
  for (int f : free_of_dof) n_free = std::max(n_free, f + 1);
  for (Eigen::Index c = 0; c < rigid_nodal.cols(); ++c) {
    const double scale = rigid_nodal.col(c).cwiseAbs().maxCoeff();
    bool ok = scale > 0;
    for (std::size_t d = 0; d < free_of_dof.size() && ok; ++d)
      if (free_of_dof[d] < 0 && std::abs(rigid_nodal(Eigen::Index(d), c)) > 1e-12 * scale) ok = false;
    if (ok) keep.push_back(c);
  }
  Eigen::MatrixXd R = Eigen::MatrixXd::Zero(n_free, Eigen::Index(keep.size()));
  for (std::size_t k = 0; k < keep.size(); ++k)
    for (std::size_t d = 0; d < free_of_dof.size(); ++d)
      if (free_of_dof[d] >= 0) R(free_of_dof[d], Eigen::Index(k)) = rigid_nodal(Eigen::Index(d), keep[k]);
  return R;
}

void remove_rigid_content(Eigen::MatrixXd& Phi, const Eigen::SparseMatrix<double>& M, const Eigen::MatrixXd& R) {
  if (R.cols() == 0) return;
  const Eigen::MatrixXd MR = sparse_times(M, R);
  const Eigen::MatrixXd G = R.transpose() * MR;
  // two passes of the projection: the second removes what round-off left of the first
  for (int pass = 0; pass < 2; ++pass) Phi -= R * G.ldlt().solve(MR.transpose() * Phi);
}

Eigen::VectorXd orthonormalize(Eigen::MatrixXd& Phi, const Eigen::SparseMatrix<double>& K,
                               const Eigen::SparseMatrix<double>& M, double rank_tolerance) {
  // 1) M-orthonormal basis of span(Phi), dropping (numerically) dependent directions; columns
  //    are scaled to unit M-norm first so that the rank test compares directions, not scales
  //    (constraint modes and mass-normalized normal modes differ in M-norm by orders of magnitude)
  Eigen::MatrixXd G = projected(M, Phi);
  const Eigen::VectorXd norms = G.diagonal().cwiseMax(0.0).cwiseSqrt();
  const Eigen::VectorXd scale = (norms.array() > 0).select(norms.cwiseInverse(), 1.0);
  Phi *= scale.asDiagonal();
  G = scale.asDiagonal() * G * scale.asDiagonal();
  const common::SymmetricEigen g = common::symmetric_eigen(G);
  const double largest = g.values.maxCoeff();
  Eigen::Index first = 0;
  while (first < g.values.size() && g.values(first) <= rank_tolerance * largest) ++first;
  const Eigen::Index rank = g.values.size() - first;
  Eigen::MatrixXd B = Phi * g.vectors.rightCols(rank) * g.values.tail(rank).cwiseSqrt().cwiseInverse().asDiagonal();
  // 2) diagonalize K in that basis (a standard symmetric eigenproblem now), ascending
  const common::SymmetricEigen k = common::symmetric_eigen(projected(K, B));
  Phi = B * k.vectors;
  // 3) one re-orthonormalization pass against round-off growth in the products above
  Eigen::LLT<Eigen::MatrixXd> llt(projected(M, Phi));
  Phi = llt.matrixU().solve(Phi.transpose()).transpose();
  canonicalize_modes(Phi, k.values);
  return k.values;
}

void canonicalize_modes(Eigen::MatrixXd& Phi, const Eigen::VectorXd& omega2) {
  // fixed, generic directions of the DOF space: a mode's sign (or a repeated frequency's
  // basis) is whatever the eigensolver's start made of it, and differs from run to run
  const auto generic = [&](Eigen::Index columns) {
    Eigen::MatrixXd G(Phi.rows(), columns);
    for (Eigen::Index j = 0; j < columns; ++j)
      for (Eigen::Index i = 0; i < Phi.rows(); ++i) G(i, j) = std::sin(0.7 + 1.37 * double(i) + 2.11 * double(j));
    return G;
  };
  const double scale = omega2.size() ? omega2.cwiseAbs().maxCoeff() : 0.0;
  for (Eigen::Index first = 0; first < Phi.cols();) {
    Eigen::Index last = first + 1;  // a cluster: frequencies equal to round-off
    while (last < Phi.cols() && std::abs(omega2(last) - omega2(first)) <= 1e-9 * std::max(std::abs(omega2(first)), 1e-12 * scale)) ++last;
    const Eigen::Index k = last - first;
    // Q with (Phi Q)^T G upper triangular, positive diagonal: unique for any basis of the cluster
    const Eigen::MatrixXd A = Phi.middleCols(first, k).transpose() * generic(k);
    Eigen::MatrixXd Q = common::qr_orthogonal_factor(A);
    const Eigen::MatrixXd R = Q.transpose() * A;
    for (Eigen::Index j = 0; j < k; ++j)
      if (R(j, j) < 0) Q.col(j) *= -1;
    Phi.middleCols(first, k) = (Phi.middleCols(first, k) * Q).eval();
    first = last;
  }
}

}  // namespace isosid::prep

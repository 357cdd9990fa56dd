// The dense decompositions compiled once for all callers: each returns what its Eigen class
// computes, checked against closed forms and the defining equations. Tolerances are a few
// hundred machine epsilons: the matrices are 2x2 to 4x4 with entries of order one.
#include "isosid/common/dense_decompositions.hpp"

#include <catch2/catch.hpp>
#include <cmath>

using namespace isosid::common;
using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {
constexpr double tol = 1e-13;

MatrixXd second_difference() {  // eigenvalues 2 - sqrt 2, 2, 2 + sqrt 2
  MatrixXd A(3, 3);
  A << 2, -1, 0, -1, 2, -1, 0, -1, 2;
  return A;
}
}  // namespace

TEST_CASE("symmetric eigen: ascending closed-form values, orthonormal vectors", "[common][dense]") {
  const MatrixXd A = second_difference();
  const SymmetricEigen e = symmetric_eigen(A);
  REQUIRE(e.converged);
  const VectorXd expected = (VectorXd(3) << 2 - std::sqrt(2.0), 2, 2 + std::sqrt(2.0)).finished();
  CHECK((e.values - expected).cwiseAbs().maxCoeff() < tol);
  CHECK((A * e.vectors - e.vectors * e.values.asDiagonal()).cwiseAbs().maxCoeff() < tol);
  CHECK((e.vectors.transpose() * e.vectors - MatrixXd::Identity(3, 3)).cwiseAbs().maxCoeff() < tol);
  CHECK((symmetric_eigenvalues(A) - expected).cwiseAbs().maxCoeff() < tol);
}

TEST_CASE("generalized symmetric eigen: A x = lambda B x with B-orthonormal vectors", "[common][dense]") {
  const MatrixXd A = second_difference();
  const MatrixXd B = VectorXd::LinSpaced(3, 1.0, 3.0).asDiagonal();
  const SymmetricEigen e = generalized_symmetric_eigen(A, B);
  REQUIRE(e.converged);
  CHECK(e.values(0) < e.values(1));
  CHECK(e.values(1) < e.values(2));
  CHECK((A * e.vectors - B * e.vectors * e.values.asDiagonal()).cwiseAbs().maxCoeff() < tol);
  CHECK((e.vectors.transpose() * B * e.vectors - MatrixXd::Identity(3, 3)).cwiseAbs().maxCoeff() < tol);
}

TEST_CASE("minimum-norm solve: the shortest solution of a singular system, least squares of a tall one", "[common][dense]") {
  MatrixXd singular(2, 2);
  singular << 1, 1, 1, 1;
  CHECK((minimum_norm_solve(singular, VectorXd::Constant(2, 2.0)) - VectorXd::Ones(2)).cwiseAbs().maxCoeff() < tol);

  MatrixXd tall(4, 2);
  tall << 1, 0, 1, 1, 1, 2, 1, 3;
  const VectorXd b = (VectorXd(4) << 1, 2, 2, 4).finished();
  const VectorXd normal_equations = (tall.transpose() * tall).llt().solve(tall.transpose() * b);
  CHECK((minimum_norm_solve(tall, b) - normal_equations).cwiseAbs().maxCoeff() < tol);
}

TEST_CASE("QR's orthogonal factor: Q orthogonal and Q^T A upper triangular", "[common][dense]") {
  MatrixXd A(3, 3);
  A << 4, 1, 2, 1, 3, 0, 2, 0, 5;
  const MatrixXd Q = qr_orthogonal_factor(A);
  REQUIRE(Q.rows() == 3);
  REQUIRE(Q.cols() == 3);
  CHECK((Q.transpose() * Q - MatrixXd::Identity(3, 3)).cwiseAbs().maxCoeff() < tol);
  const MatrixXd R = Q.transpose() * A;
  CHECK(std::abs(R(1, 0)) + std::abs(R(2, 0)) + std::abs(R(2, 1)) < tol);
}

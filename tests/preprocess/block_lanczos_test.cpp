// Block Lanczos against a dense eigen solver: spectra with clusters and repeated eigenvalues,
// restarts forced by a small room, an operator whose Krylov space closes early, and requests
// it cannot serve.
#include "isosid/format/error.hpp"
#include "reduce/block_lanczos.hpp"

#include <Eigen/Eigenvalues>
#include <catch2/catch.hpp>
#include <random>

using namespace isosid;
using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

/// A symmetric matrix Q diag(values) Q^T with a random orthogonal Q.
MatrixXd with_spectrum(const VectorXd& values, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal;
  MatrixXd G(values.size(), values.size());
  for (Eigen::Index i = 0; i < G.size(); ++i) G.data()[i] = normal(rng);
  const MatrixXd Q = Eigen::HouseholderQR<MatrixXd>(G).householderQ();
  return Q * values.asDiagonal() * Q.transpose();
}

prep::BlockOperator product(const MatrixXd& A) {
  return [&A](const MatrixXd& X, MatrixXd& Y) { Y = A * X; };
}

/// The largest principal-angle sine between the column spaces of orthonormal U and W.
double largest_angle_sine(const MatrixXd& U, const MatrixXd& W) {
  const MatrixXd residual = W - U * (U.transpose() * W);
  return Eigen::JacobiSVD<MatrixXd>(residual).singularValues()(0);
}

/// The computed pairs against the exact ones: values to 1e-12 relative (the residual tolerance
/// 1e-12 bounds a value's error by its square over the gap, far below); each group of values
/// within 1e-4 of the largest (repeated ones, close pairs) spans the exact eigenspace of the
/// group to 1e-9 (the residual over the gap to the next group, above 5e-3 of the largest here).
void check_against_dense(const MatrixXd& A, const prep::BlockLanczosResult& r, int n) {
  const Eigen::SelfAdjointEigenSolver<MatrixXd> dense(A);
  const VectorXd exact = dense.eigenvalues().reverse();
  const MatrixXd vectors = dense.eigenvectors().rowwise().reverse();
  REQUIRE(r.values.size() == n);
  REQUIRE(r.vectors.cols() == n);
  for (int i = 0; i < n; ++i) CHECK(r.values(i) == Approx(exact(i)).epsilon(1e-12));
  CHECK((r.vectors.transpose() * r.vectors - MatrixXd::Identity(n, n)).cwiseAbs().maxCoeff() < 1e-12);
  for (int i = 0; i < n;) {
    int j = i + 1;
    while (j < n && std::abs(exact(j) - exact(i)) < 1e-4 * exact(0)) ++j;
    INFO("eigenvalues " << i << " to " << j - 1);
    CHECK(largest_angle_sine(vectors.middleCols(i, j - i), r.vectors.middleCols(i, j - i)) < 1e-9);
    i = j;
  }
}

}  // namespace

TEST_CASE("block Lanczos finds the largest eigenpairs of a spectrum with clusters and repeated values", "[lanczos]") {
  // like a shift-inverted solid: mu = 1 / lambda over a spread of lambda, with triple values
  // (a symmetric body's repeated frequencies) and a close pair
  VectorXd lambda(300);
  for (int i = 0; i < lambda.size(); ++i) lambda(i) = 1.0 + 0.2 * i + 1e-3 * i * i;
  lambda.segment(4, 3).setConstant(lambda(4));
  lambda(12) = lambda(11) * (1 + 1e-6);
  const MatrixXd A = with_spectrum(lambda.cwiseInverse(), 7);
  SECTION("with the default room") {
    const auto r = prep::block_lanczos_largest(product(A), A.rows(), 20);
    check_against_dense(A, r, 20);
  }
  SECTION("with room for few vectors, so that it restarts") {
    prep::BlockLanczosOptions options;
    options.block = 3;
    options.room = 32;
    const auto r = prep::block_lanczos_largest(product(A), A.rows(), 20, options);
    CHECK(r.restarts > 0);
    check_against_dense(A, r, 20);
  }
  SECTION("one vector per block, on the spectrum without its repeated values") {
    // a single Krylov vector sees one direction of a repeated eigenvalue only (in exact
    // arithmetic); the blocks are there for repeated values
    VectorXd simple(300);
    for (int i = 0; i < simple.size(); ++i) simple(i) = 1.0 + 0.2 * i + 1e-3 * i * i;
    const MatrixXd B = with_spectrum(simple.cwiseInverse(), 5);
    prep::BlockLanczosOptions options;
    options.block = 1;
    const auto r = prep::block_lanczos_largest(product(B), B.rows(), 10, options);
    check_against_dense(B, r, 10);
  }
}

TEST_CASE("block Lanczos completes a Krylov space that closes before its room is full", "[lanczos]") {
  // rank 6 with two triple values: the first blocks span the whole range, and the vanished
  // directions are replaced by random ones orthogonal to it (eigenvalue 0)
  VectorXd values = VectorXd::Zero(80);
  values.head(3).setConstant(2.0);
  values.segment(3, 3).setConstant(1.0);
  const MatrixXd A = with_spectrum(values, 11);
  prep::BlockLanczosOptions options;
  options.block = 4;
  const auto r = prep::block_lanczos_largest(product(A), A.rows(), 6, options);
  check_against_dense(A, r, 6);
}

TEST_CASE("block Lanczos serves operators barely larger than the request", "[lanczos]") {
  // small bodies: the blocks shrink so that a full basis still leaves a block of new directions
  for (const Eigen::Index size : {6, 9, 20, 36}) {
    VectorXd values(size);
    for (Eigen::Index i = 0; i < size; ++i) values(i) = 1.0 / (1.0 + 0.5 * double(i));
    const MatrixXd A = with_spectrum(values, unsigned(size));
    INFO("size " << size);
    check_against_dense(A, prep::block_lanczos_largest(product(A), size, 4), 4);
  }
}

TEST_CASE("block Lanczos refuses requests it cannot serve", "[lanczos]") {
  const MatrixXd A = MatrixXd::Identity(10, 10);
  CHECK_THROWS_AS(prep::block_lanczos_largest(product(A), 10, 10), format::ComputationError);
  CHECK_THROWS_AS(prep::block_lanczos_largest(product(A), 10, 0), format::ComputationError);
  VectorXd slow(200);  // a spectrum that barely decays, in a room that cannot hold it: no convergence
  for (int i = 0; i < slow.size(); ++i) slow(i) = 1.0 - 1e-6 * i;
  const MatrixXd B = with_spectrum(slow, 3);
  prep::BlockLanczosOptions options;
  options.block = 2;
  options.room = 20;
  options.max_restarts = 3;
  CHECK_THROWS_AS(prep::block_lanczos_largest(product(B), B.rows(), 8, options), format::ComputationError);
}

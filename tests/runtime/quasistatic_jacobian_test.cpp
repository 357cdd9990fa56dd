// QuasistaticJacobian against dense solves of K + U V^T: Woodbury and the direct path, a
// diagonal and a dense K, and its kept factorizations reused and replaced correctly.
#include "condensation/quasistatic_jacobian.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace isosid;

namespace {
/// A well-conditioned symmetric positive definite n x n matrix.
Eigen::MatrixXd spd(Eigen::Index n, unsigned seed) {
  std::srand(seed);
  const Eigen::MatrixXd A = Eigen::MatrixXd::Random(n, n);
  return A * A.transpose() + double(n) * Eigen::MatrixXd::Identity(n, n);
}

/// The relative error of the solver's x against a dense LU solve (`weights`: U = V diag(weights), as solve() takes them;
/// the solver is then given NaN for U, which it must not read).
double solve_error(const run::QuasistaticJacobian& J, const Eigen::MatrixXd& K, const Eigen::MatrixXd& U, const Eigen::MatrixXd& V,
                   Eigen::Index r, const Eigen::VectorXd& b, const Eigen::VectorXd* weights = nullptr) {
  Eigen::VectorXd x;
  const Eigen::MatrixXd unread = Eigen::MatrixXd::Constant(U.rows(), U.cols(), NAN);
  J.solve(weights ? unread : U, V, r, b, x, weights);
  const Eigen::MatrixXd full = K + U.leftCols(r) * V.leftCols(r).transpose();
  const Eigen::VectorXd expected = full.partialPivLu().solve(b);
  return (x - expected).norm() / expected.norm();
}
}  // namespace

TEST_CASE("QuasistaticJacobian solves K + U V^T as a dense solve does", "[runtime][unit]") {
  const Eigen::Index n = 10;
  const Eigen::MatrixXd K_dense = spd(n, 3);
  const Eigen::VectorXd k_diagonal = Eigen::VectorXd::LinSpaced(n, 1.0, 50.0);
  const Eigen::MatrixXd K_diagonal = k_diagonal.asDiagonal();
  for (const bool diagonal : {true, false}) {
    const Eigen::MatrixXd& K = diagonal ? K_diagonal : K_dense;
    const run::QuasistaticJacobian J({K}, diagonal);
    std::srand(7);
    // U = c V (+ a skew part: friction makes the terms unsymmetric); r = 0, Woodbury (r <= n,
    // or r <= n / 4 for dense K) and the n x n Jacobian (r > n); the capacity exceeds r
    for (const Eigen::Index r : {0L, 2L, 6L, 14L}) {
      const Eigen::MatrixXd V = Eigen::MatrixXd::Random(n, 16), U = 3.0 * V + 0.2 * Eigen::MatrixXd::Random(n, 16);
      const Eigen::VectorXd b = Eigen::VectorXd::Random(n);
      INFO("diagonal K " << diagonal << ", rank " << r);
      // the dense reference and the solver differ by the round-off of a condition number near 1e3
      CHECK(solve_error(J, K, U, V, r, b) < 1e-11);
      // without friction U = V diag(c_p w): Cholesky's factors of the Jacobian (r > n, or a
      // dense K's r > n / 4) or of the symmetric capacitance (diagonal K), weights spread over
      // six decades as penalties times Gauss weights are
      const Eigen::VectorXd weights = Eigen::VectorXd::LinSpaced(16, 0.0, 6.0).unaryExpr([](double e) { return std::pow(10.0, e); });
      const Eigen::MatrixXd U_symmetric = V * weights.asDiagonal();
      const run::QuasistaticJacobian fresh({K}, diagonal);  // no kept factorization of these terms
      CHECK(solve_error(fresh, K, U_symmetric, V, r, b, &weights) < 1e-11);
    }
  }
  // an indefinite K (a quasistatic block of no physical body, but the LU fallbacks' case): no
  // Cholesky factors, so the weighted terms' U = V diag(weights) is formed by the solver itself
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(K_dense, Eigen::EigenvaluesOnly);
  const Eigen::MatrixXd K_indefinite = K_dense - 1.5 * eigen.eigenvalues()(0) * Eigen::MatrixXd::Identity(n, n);
  const Eigen::VectorXd weights = Eigen::VectorXd::LinSpaced(16, 1.0, 4.0);
  std::srand(9);
  for (const Eigen::Index r : {0L, 2L, 6L, 14L}) {
    const Eigen::MatrixXd V = Eigen::MatrixXd::Random(n, 16);
    const Eigen::VectorXd b = Eigen::VectorXd::Random(n);
    const run::QuasistaticJacobian J({K_indefinite}, false);
    INFO("indefinite K, rank " << r);
    // its condition stays near that of the definite K above (the shift leaves the smallest
    // eigenvalue at half its size): the same round-off bound
    CHECK(solve_error(J, K_indefinite, V * weights.asDiagonal(), V, r, b, &weights) < 1e-11);
  }
}

TEST_CASE("QuasistaticJacobian with two bodies' dense blocks works as with the whole matrix", "[runtime][unit]") {
  // a sphere's and a beam's massless boundaries: K_h = diag(K_1, K_2), each block dense; the
  // products and Woodbury's K^-1 U run per block, so terms with rows in one body, in the other
  // and in both (a point and its target point) must all come out as the whole K's
  const Eigen::Index n1 = 7, n2 = 5, n = n1 + n2;
  const Eigen::MatrixXd K1 = spd(n1, 11), K2 = spd(n2, 12);
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n);
  K.topLeftCorner(n1, n1) = K1;
  K.bottomRightCorner(n2, n2) = K2;
  const run::QuasistaticJacobian J({K1, K2}, false);
  std::srand(13);
  const Eigen::VectorXd z = Eigen::VectorXd::Random(n), w = Eigen::VectorXd::Random(n);
  Eigen::VectorXd Kz;
  J.multiply(z, Kz);
  CHECK((Kz - K * z).norm() < 1e-14 * (K * z).norm());
  CHECK(J.product(z, w) == Approx(z.dot(K * w)).epsilon(1e-14));
  // the direct Jacobian (r > n / 4) and Woodbury (r <= n / 4), one solver throughout: a block
  // without terms must clear its rows of the buffers an earlier factorization filled
  const run::QuasistaticJacobian reused({K1, K2}, false);
  for (const Eigen::Index r : {8L, 3L, 2L, 1L}) {
    Eigen::MatrixXd V = Eigen::MatrixXd::Zero(n, 8);
    V.col(0).head(n1) = Eigen::VectorXd::Random(n1);  // a point of the first body
    V.col(1).tail(n2) = Eigen::VectorXd::Random(n2);  // of the second
    V.rightCols(6) = Eigen::MatrixXd::Random(n, 6);   // of both
    V.row(2).setZero();                               // a coordinate no point moves
    const Eigen::MatrixXd U = 3.0 * V + 0.2 * Eigen::MatrixXd::Random(n, 8).cwiseProduct((V.array() != 0).cast<double>().matrix());
    const Eigen::VectorXd b = Eigen::VectorXd::Random(n);
    INFO("rank " << r);
    // the round-off of a condition number near 1e3, as above
    CHECK(solve_error(reused, K, U, V, r, b) < 1e-11);
  }
  // K^-1 B for sparse gradients (the gap-space condensation's W = K^-1 V): columns on one body,
  // on the other and on both
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(n, 4);
  B.col(0).head(n1) = Eigen::VectorXd::Random(n1);
  B.col(1).tail(n2) = Eigen::VectorXd::Random(n2);
  B.col(2) = Eigen::VectorXd::Random(n);
  B(n1 - 1, 3) = 2.0, B(n1, 3) = -1.0;  // the last row of one block and the first of the next
  Eigen::MatrixXd X;
  J.solve_stiffness(Eigen::SparseMatrix<double>(B.sparseView()), X);
  const Eigen::MatrixXd expected = K.llt().solve(B);
  CHECK((X - expected).norm() < 1e-12 * expected.norm());
}

TEST_CASE("QuasistaticJacobian reuses a kept factorization only for the same terms", "[runtime][unit]") {
  const Eigen::Index n = 8;
  const Eigen::VectorXd k = Eigen::VectorXd::LinSpaced(n, 2.0, 20.0);
  const Eigen::MatrixXd K = k.asDiagonal();
  const run::QuasistaticJacobian J({K}, true);
  // more term sets than are kept, cycled twice: every solve must be that of its own terms,
  // whether its factorization was kept, replaced or made anew; sets of equal rank differ in
  // one entry only, which the reuse must notice
  std::vector<Eigen::MatrixXd> Us, Vs;
  std::srand(11);
  const Eigen::MatrixXd base = Eigen::MatrixXd::Random(n, 4);
  for (std::size_t set = 0; set < run::QuasistaticJacobian::kKeptFactorizations + 3; ++set) {
    Eigen::MatrixXd V = base;
    V(Eigen::Index(set) % n, 1) += 0.1 * double(set);
    Vs.push_back(V);
    Us.push_back(5.0 * V);
  }
  const Eigen::VectorXd b = Eigen::VectorXd::Random(n);
  for (int pass = 0; pass < 2; ++pass)
    for (std::size_t set = 0; set < Us.size(); ++set) {
      INFO("pass " << pass << ", set " << set);
      CHECK(solve_error(J, K, Us[set], Vs[set], 3, b) < 1e-11);
      CHECK(solve_error(J, K, Us[set], Vs[set], 2, b) < 1e-11);  // same columns, fewer of them
    }
  // without friction the weights and V name the terms: sets of one V whose weights differ in
  // one entry, and one V with the weights of another set
  std::vector<Eigen::VectorXd> weights;
  for (std::size_t set = 0; set < run::QuasistaticJacobian::kKeptFactorizations + 3; ++set) {
    weights.push_back(Eigen::VectorXd::Constant(4, 5.0));
    weights.back()(Eigen::Index(set) % 3) += 0.5 * double(set);
  }
  for (int pass = 0; pass < 2; ++pass)
    for (std::size_t set = 0; set < weights.size(); ++set)
      for (const Eigen::MatrixXd* V : {&Vs[0], &Vs[1]}) {
        INFO("weighted, pass " << pass << ", set " << set << ", V of set " << (V == &Vs[0] ? 0 : 1));
        const Eigen::MatrixXd U = *V * weights[set].asDiagonal();
        CHECK(solve_error(J, K, U, *V, 3, b, &weights[set]) < 1e-11);
      }
}

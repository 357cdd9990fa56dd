// A sparse factorization's progress: the BLAS calls of CHOLMOD's supernodal factorization,
// counted on their way to the BLAS library, add up to the analysis's count of its flops, and the
// work step shows each tenth done. The matrix: a 3D Laplacian, whose supernodes are large
// enough for every kind of call (dpotrf, dtrsm, dsyrk, dgemm).
#include "isosid/common/progress_line.hpp"
#include "reduce/factorization_progress.hpp"
#include "reduce/sparse_cholesky.hpp"

#include <Eigen/CholmodSupport>
#include <catch2/catch.hpp>
#include <string>
#include <vector>

using namespace isosid;

namespace {

/// The 7-point Laplacian of an n x n x n grid, shifted to be well conditioned.
Eigen::SparseMatrix<double> laplacian_3d(int n) {
  const auto index = [n](int i, int j, int k) { return (i * n + j) * n + k; };
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const int row = index(i, j, k);
        entries.emplace_back(row, row, 6.5);
        if (i > 0) entries.emplace_back(row, index(i - 1, j, k), -1.0), entries.emplace_back(index(i - 1, j, k), row, -1.0);
        if (j > 0) entries.emplace_back(row, index(i, j - 1, k), -1.0), entries.emplace_back(index(i, j - 1, k), row, -1.0);
        if (k > 0) entries.emplace_back(row, index(i, j, k - 1), -1.0), entries.emplace_back(index(i, j, k - 1), row, -1.0);
      }
  Eigen::SparseMatrix<double> A(n * n * n, n * n * n);
  A.setFromTriplets(entries.begin(), entries.end());
  return A;
}

}  // namespace

TEST_CASE("FactorizationProgress: the counted BLAS work is the analysis's count of the factorization's flops", "[reduction]") {
  const Eigen::SparseMatrix<double> A = laplacian_3d(16);
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> llt;
  llt.analyzePattern(A);
  const double expected = llt.cholmod().fl;
  REQUIRE(expected > 1e7);
  double counted = 0;
  {
    const prep::FactorizationProgress progress(expected, "factorizing the test's matrix");
    llt.factorize(A);
    counted = progress.counted_flops();
    CHECK(common::work_fraction() > 0.5);
  }
  REQUIRE(llt.info() == Eigen::Success);
  // the calls' work (dsyrk's n (n + 1) k, dgemm's 2 m n k, dtrsm's, dpotrf's n^3 / 3) and the
  // analysis's sum of squared column counts are two counts of the same work, which differ in the
  // terms of lower order: measured 1.10 times the analysis's count on this matrix
  CHECK(counted == Approx(expected).epsilon(0.15));
  CHECK(common::work_fraction() == -1);  // unknown again once the factorization is done
  // no meter alive: the BLAS calls pass through and leave the fraction unknown
  llt.factorize(A);
  REQUIRE(llt.info() == Eigen::Success);
  CHECK(common::work_fraction() == -1);
}

TEST_CASE("SparseCholesky: its factorization shows each tenth done in the work step", "[reduction]") {
  const Eigen::SparseMatrix<double> A = laplacian_3d(16);
  std::vector<std::string> steps;
  common::set_work_step("factorizing the test's matrix");
  common::set_work_step_listener([&](const std::string& step) { steps.push_back(step); });
  const prep::SparseCholesky factor(A);
  common::set_work_step_listener(nullptr);
  CHECK(common::work_step() == "factorizing the test's matrix");  // the share gone with the factorization
  steps.pop_back();
  // first the ordering of the node graph, as a step of its own
  REQUIRE(steps.size() >= 2);
  CHECK(steps[0] == "factorizing the test's matrix: ordering its node graph");
  CHECK(steps[1] == "factorizing the test's matrix");
  steps.erase(steps.begin(), steps.begin() + 2);
  // a tenth at a time, in order; one large call (a separator's dpotrf) may pass more than one
  REQUIRE(steps.size() >= 5);
  for (std::size_t i = 0; i < steps.size(); ++i) {
    CHECK_THAT(steps[i], Catch::Matchers::StartsWith("factorizing the test's matrix, ") && Catch::Matchers::EndsWith(" % of its 6e+07 flops"));
    if (i > 0) CHECK(std::stoi(steps[i].substr(31)) > std::stoi(steps[i - 1].substr(31)));
  }
  CHECK_THAT(steps.front(), Catch::Matchers::StartsWith("factorizing the test's matrix, 10 % of its "));
  CHECK_THAT(steps.back(), Catch::Matchers::StartsWith("factorizing the test's matrix, 90 % of its "));
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(A.rows());
  CHECK((A * factor.solve(ones) - ones).norm() < 1e-10);  // the calls reached the BLAS library
}

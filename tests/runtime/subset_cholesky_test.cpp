// The Cholesky factor of a principal block kept across index-set changes
// (condensation/subset_cholesky.hpp) against a factorization from scratch of the same block.
#include "condensation/subset_cholesky.hpp"

#include <catch2/catch.hpp>
#include <algorithm>
#include <random>

using namespace isosid;

TEST_CASE("subset Cholesky: the block's solution after removals and appends equals a factorization from scratch",
          "[runtime][unit][gap-space]") {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(-1, 1);
  const Eigen::Index n = 120;
  // a compliance of low rank plus a small diagonal, as the pressed points' block of gap space:
  // condition about 1e6
  Eigen::MatrixXd shapes(n, 12);
  for (Eigen::Index i = 0; i < shapes.size(); ++i) shapes.data()[i] = unit(random);
  const Eigen::MatrixXd A = shapes * shapes.transpose();
  const Eigen::VectorXd d = Eigen::VectorXd::Constant(n, 1e-5 * A.diagonal().maxCoeff());
  Eigen::VectorXd b(n);
  for (Eigen::Index i = 0; i < n; ++i) b(i) = unit(random);
  run::SubsetCholesky factor;
  factor.reset(A, d);
  std::vector<char> is_member(std::size_t(n), 0);
  std::vector<Eigen::Index> members;
  double worst = 0;
  for (int step = 0; step < 400; ++step) {
    // a set that drifts: a few indices leave or enter per step, now and then many at once
    const int changes = step % 50 == 0 ? 40 : 1 + step % 3;
    for (int c = 0; c < changes; ++c) {
      const Eigen::Index i = Eigen::Index(random() % std::uint32_t(n));
      is_member[std::size_t(i)] = !is_member[std::size_t(i)];
    }
    members.clear();
    for (Eigen::Index i = 0; i < n; ++i)
      if (is_member[std::size_t(i)]) members.push_back(i);
    std::shuffle(members.begin(), members.end(), random);
    REQUIRE(factor.follow(members, is_member));
    Eigen::VectorXd x = Eigen::VectorXd::Constant(n, 7.0);
    factor.solve(b, x);
    // the block from scratch
    const Eigen::Index r = Eigen::Index(members.size());
    Eigen::MatrixXd block(r, r);
    Eigen::VectorXd rhs(r);
    for (Eigen::Index a = 0; a < r; ++a) {
      rhs(a) = b(members[std::size_t(a)]);
      for (Eigen::Index c = 0; c < r; ++c)
        block(a, c) = A(members[std::size_t(a)], members[std::size_t(c)]) + (a == c ? d(members[std::size_t(a)]) : 0.0);
    }
    const Eigen::VectorXd expected = block.llt().solve(rhs);
    for (Eigen::Index a = 0; a < r; ++a)
      worst = std::max(worst, std::abs(x(members[std::size_t(a)]) - expected(a)) / expected.cwiseAbs().maxCoeff());
    // entries outside the set are left alone
    for (Eigen::Index i = 0; i < n; ++i)
      if (!is_member[std::size_t(i)]) REQUIRE(x(i) == 7.0);
  }
  // both solves are backward stable: they differ by the condition (1e6) times round-off
  CHECK(worst < 1e-8);
  INFO(factor.factorizations() << " factorizations, " << factor.updates() << " single updates");
  // most changes were updates, and the set was factored anew now and then
  CHECK(factor.updates() > 300);
  CHECK(factor.factorizations() > 8);
}

TEST_CASE("subset Cholesky: a block that is not positive definite is reported, and the next follow recovers", "[runtime][unit][gap-space]") {
  Eigen::MatrixXd A = Eigen::MatrixXd::Identity(3, 3);
  A(0, 1) = A(1, 0) = 2.0;  // indices 0 and 1 together: eigenvalues -1 and 3
  const Eigen::VectorXd d = Eigen::VectorXd::Zero(3);
  run::SubsetCholesky factor;
  factor.reset(A, d);
  std::vector<char> is_member{1, 0, 1};
  REQUIRE(factor.follow({0, 2}, is_member));
  is_member = {1, 1, 1};
  CHECK_FALSE(factor.follow({0, 2, 1}, is_member));
  is_member = {0, 1, 1};
  REQUIRE(factor.follow({1, 2}, is_member));
  Eigen::VectorXd x = Eigen::VectorXd::Zero(3);
  factor.solve(Eigen::Vector3d(5.0, 2.0, 3.0), x);
  CHECK(x(1) == Approx(2.0));
  CHECK(x(2) == Approx(3.0));
}

TEST_CASE("subset Cholesky: an index whose append makes the block indefinite is reported, within a set large enough for updates",
          "[runtime][unit][gap-space]") {
  // the identity, except that indices 20 and 21 together make the block indefinite (eigenvalue -1)
  const Eigen::Index n = 30;
  Eigen::MatrixXd A = Eigen::MatrixXd::Identity(n, n);
  A(20, 21) = A(21, 20) = 2.0;
  const Eigen::VectorXd d = Eigen::VectorXd::Zero(n);
  run::SubsetCholesky factor;
  factor.reset(A, d);
  auto set_of = [&](const std::vector<Eigen::Index>& members) {
    std::vector<char> flags(std::size_t(n), 0);
    for (const Eigen::Index i : members) flags[std::size_t(i)] = 1;
    return flags;
  };
  std::vector<Eigen::Index> members;
  for (Eigen::Index i = 0; i <= 20; ++i) members.push_back(i);
  REQUIRE(factor.follow(members, set_of(members)));
  // two changes in 21: an update (one removal, one append), whose append finds no pivot
  members.erase(members.begin());
  members.push_back(21);
  CHECK_FALSE(factor.follow(members, set_of(members)));
  // without index 20 the block is the identity again
  members.erase(std::find(members.begin(), members.end(), Eigen::Index(20)));
  REQUIRE(factor.follow(members, set_of(members)));
  Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, 1.0, 30.0), x = Eigen::VectorXd::Zero(n);
  factor.solve(b, x);
  for (const Eigen::Index i : members) CHECK(x(i) == Approx(b(i)));
  CHECK(x(0) == 0.0);
  CHECK(x(20) == 0.0);
}

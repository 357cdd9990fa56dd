// The fill-reducing ordering on the node graph: the columns of one node (equal patterns) form
// one supervariable whichever way the DOFs are numbered, the ordering is a permutation that
// keeps each node's DOFs together, its factor fills no more than CHOLMOD's ordering of the DOF
// graph (within 10 %: both are heuristics; the natural order fills 2.6 times more), and the
// factorization analysed with it solves. The matrix: a 3D vector Laplacian, a 3 x 3 coupling
// block per pair of neighbouring nodes, as an elasticity stiffness has.
#include "reduce/node_ordering.hpp"
#include "reduce/sparse_cholesky.hpp"

#include <Eigen/CholmodSupport>
#include <catch2/catch.hpp>
#include <vector>

using namespace isosid;

namespace {

/// The vector Laplacian of an n^3 grid of nodes with three DOFs each; DOF (node, k) is numbered
/// node * 3 + k (interleaved) or k * nodes + node (blocked). With `drop_first`, the first DOF is
/// removed (held), leaving its node two.
Eigen::SparseMatrix<double> vector_laplacian(int n, bool interleaved, bool drop_first) {
  const int nodes = n * n * n;
  const auto dof = [&](int node, int k) { return interleaved ? node * 3 + k : k * nodes + node; };
  Eigen::Matrix3d block;
  block << 2.0, 0.5, 0.2, 0.5, 2.0, 0.3, 0.2, 0.3, 2.0;
  std::vector<Eigen::Triplet<double>> entries;
  const auto couple = [&](int a, int b, double weight) {
    for (int k = 0; k < 3; ++k)
      for (int l = 0; l < 3; ++l) entries.emplace_back(dof(a, k), dof(b, l), weight * block(k, l));
  };
  const auto index = [n](int i, int j, int k) { return (i * n + j) * n + k; };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const int a = index(i, j, k);
        couple(a, a, 6.5);
        for (int b : {i > 0 ? index(i - 1, j, k) : -1, j > 0 ? index(i, j - 1, k) : -1, k > 0 ? index(i, j, k - 1) : -1})
          if (b >= 0) couple(a, b, -1.0), couple(b, a, -1.0);
      }
  Eigen::SparseMatrix<double> A(3 * nodes, 3 * nodes);
  A.setFromTriplets(entries.begin(), entries.end());
  if (!drop_first) return A;
  const int first = dof(0, 0);
  std::vector<Eigen::Triplet<double>> kept;
  for (int c = 0; c < A.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, c); it; ++it)
      if (it.row() != first && c != first) kept.emplace_back(int(it.row()) - (it.row() > first), c - (c > first), it.value());
  Eigen::SparseMatrix<double> held(A.rows() - 1, A.cols() - 1);
  held.setFromTriplets(kept.begin(), kept.end());
  return held;
}

}  // namespace

TEST_CASE("node_graph_ordering: one supervariable per node, its DOFs together, fill as CHOLMOD's own", "[reduction]") {
  const int n = 10, nodes = n * n * n;
  for (const bool interleaved : {true, false})
    for (const bool drop_first : {false, true}) {
      CAPTURE(interleaved, drop_first);
      const Eigen::SparseMatrix<double> A = vector_laplacian(n, interleaved, drop_first);
      CHECK(prep::supervariable_count(A) == nodes);

      Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> own;
      own.analyzePattern(A);
      const double own_entries = own.cholmod().lnz;
      const std::vector<int> perm = prep::node_graph_ordering(A, own.cholmod());
      REQUIRE(perm.size() == std::size_t(A.rows()));
      std::vector<int> seen(perm.size(), 0);
      for (int c : perm) ++seen.at(std::size_t(c));
      CHECK(std::count(seen.begin(), seen.end(), 1) == A.rows());
      // each node's DOFs stand next to each other (its first held DOF aside)
      const auto node_of = [&](int c) {
        const int full = drop_first ? c + 1 : c;  // the DOF's number before the first was removed
        return interleaved ? full / 3 : full % nodes;
      };
      int runs = 1;
      for (std::size_t k = 1; k < perm.size(); ++k) runs += node_of(perm[k]) != node_of(perm[k - 1]);
      CHECK(runs == nodes);

      const prep::SparseCholesky factor(A);
      const double entries = factor.solve_flops(1) / 4.0;
      CHECK(entries <= 1.10 * own_entries);
      const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(A.rows(), -1.0, 2.0);
      const Eigen::VectorXd x = factor.solve(b);
      CHECK((A * x - b).norm() <= 1e-12 * b.norm());
    }
}

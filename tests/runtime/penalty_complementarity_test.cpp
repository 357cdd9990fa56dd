// The points' penalty contact problem of gap space (condensation/penalty_complementarity.hpp)
// against its own conditions: every force pushes, every pressed point's gap is its force over
// its stiffness, every free point's gap is open. The problems are those of a flat face pressed
// on a plane: gaps that close together over many points, under a compliance of low rank (a
// few smooth modes) with a small penalty flexibility on its diagonal, where semismooth Newton
// alone can cycle.
#include "condensation/penalty_complementarity.hpp"

#include <catch2/catch.hpp>
#include <random>

using namespace isosid;

namespace {
struct Problem {
  Eigen::MatrixXd compliance;
  Eigen::VectorXd stiffness, free_gaps;
};

/// m points on a square face; the compliance of `rank` smooth displacement shapes over it
/// (1, x, y, x^2, xy, ...); penalty flexibilities 1e-6..1e-1 of the compliance's largest
/// entry; free gaps of a face pressed in, tilted at random, 1e-3..1 deep.
Problem flat_face(std::mt19937& random, Eigen::Index m, int rank) {
  std::uniform_real_distribution<double> unit(-1, 1), scale(0.5, 2);
  Eigen::MatrixXd x(m, 2);
  for (Eigen::Index i = 0; i < m; ++i) x(i, 0) = unit(random), x(i, 1) = unit(random);
  Eigen::MatrixXd shapes(m, rank);
  int column = 0;
  for (int degree = 0; column < rank; ++degree)
    for (int i = degree; i >= 0 && column < rank; --i, ++column)
      shapes.col(column) = scale(random) * (x.col(0).array().pow(i) * x.col(1).array().pow(degree - i)).matrix();
  Problem p;
  p.compliance = shapes * shapes.transpose();
  const double flexibility = std::pow(10.0, -6 + 5 * (unit(random) + 1) / 2) * p.compliance.cwiseAbs().maxCoeff();
  p.stiffness = Eigen::VectorXd::Constant(m, 1 / flexibility);
  const double depth = std::pow(10.0, -3 + 3 * (unit(random) + 1) / 2), tilt_x = unit(random), tilt_y = unit(random);
  p.free_gaps = -depth * (1 + tilt_x * x.col(0).array() + tilt_y * x.col(1).array()).matrix();
  return p;
}
}  // namespace

TEST_CASE("penalty complementarity: forces push, pressed gaps follow the penalty law, free gaps are open, also where Newton cycles",
          "[runtime][unit][gap-space]") {
  std::mt19937 random(2026);
  int by_active_set = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const Eigen::Index m = 72;
    const Problem p = flat_face(random, m, 3 + trial % 9);
    run::PenaltyComplementarity points;
    points.set(p.compliance, p.stiffness);
    int iterations = 0;
    REQUIRE(points.solve(p.free_gaps, iterations) == run::PenaltyComplementarity::Outcome::Solved);
    by_active_set += points.by_active_set();
    const Eigen::VectorXd& f = points.forces();
    const Eigen::VectorXd gaps = p.free_gaps + p.compliance * f;
    // the conditions to the round-off of the pressed points' Cholesky solve: their matrix's
    // condition (up to 1e6 here) times eps, relative to the free gaps
    const double tolerance = 1e-8 * p.free_gaps.cwiseAbs().maxCoeff();
    double worst = 0;
    for (Eigen::Index i = 0; i < m; ++i) {
      CHECK(f(i) >= 0);
      worst = std::max(worst, f(i) > 0 ? std::abs(gaps(i) + f(i) / p.stiffness(i)) : -gaps(i));
    }
    INFO("trial " << trial << ": " << points.pressed().size() << " of " << m << " points pressed, " << iterations << " iterations");
    CHECK(worst <= tolerance);
    CHECK(Eigen::Index(points.pressed().size()) == (f.array() > 0).count());
  }
  // Newton cycled on some of them (measured: 52 of 200), and the active-set method solved those
  INFO(by_active_set << " of 200 by the active-set method");
  CHECK(by_active_set >= 10);
}

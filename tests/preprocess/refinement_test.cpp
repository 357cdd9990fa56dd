// Knot insertion and order elevation leave geometry and fields unchanged (case G,
// docs/references.md).
#include "geometry/primitives.hpp"
#include "refine/degree_elevation.hpp"
#include "refine/knot_insertion.hpp"
#include "refine/patch_refinement.hpp"

#include <catch2/catch.hpp>
#include <random>

using namespace isosid::prep;

namespace {
/// A patch carrying a smooth displacement field in extra point columns (x, y, ux, uy).
NurbsPatch disk_with_field() {
  NurbsPatch p = primitives::disk(0.1);
  p.points.conservativeResize(Eigen::NoChange, 4);
  for (int i = 0; i < p.count(); ++i) {
    p.points(i, 2) = std::sin(30 * p.points(i, 0)) * 1e-3;
    p.points(i, 3) = p.points(i, 0) * p.points(i, 1);
  }
  return p;
}
}  // namespace

TEST_CASE("A5.4 knot insertion equals the collocation refinement matrix", "[refine]") {
  KnotVector U(8);
  U << 0, 0, 0, 0.3, 0.6, 1, 1, 1;
  const std::vector<double> X = {0.1, 0.3, 0.45, 0.8, 0.8};
  const Eigen::MatrixXd T = knot_insertion_matrix(U, 2, X);
  CHECK(T.rows() == 10);
  CHECK(T.cols() == 5);
  // every row of T is a convex combination (partition of unity is preserved)
  CHECK((T.rowwise().sum().array() - 1.0).abs().maxCoeff() < 1e-14);
  // check against basis values: N_old(u) = T^T N_new(u) at random u
  const RefinedCurve r = insert_knots(U, 2, Eigen::MatrixXd::Identity(5, 5), X);
  std::mt19937 gen(2);
  std::uniform_real_distribution<double> u01(0, 1);
  for (int k = 0; k < 30; ++k) {
    const double u = u01(gen);
    CHECK((basis_row(U, 2, u) - T.transpose() * basis_row(r.knots, 2, u)).norm() < 1e-14);
  }
}

TEST_CASE("knot insertion and order elevation leave the geometry and a field unchanged", "[refine]") {
  const NurbsPatch coarse = disk_with_field();
  NurbsPatch fine = coarse;
  elevate_degree(fine, 0, 4);
  elevate_degree(fine, 1, 3);
  insert_knots(fine, 0, {0.1, 0.25, 0.25, 0.7});
  subdivide_uniformly(fine, 1, 5);
  CHECK(fine.degrees == std::vector<int>{4, 3});
  std::mt19937 gen(9);
  std::uniform_real_distribution<double> u01(0, 1);
  double worst = 0;
  for (int k = 0; k < 200; ++k) {
    const Eigen::Vector2d xi(u01(gen), u01(gen));
    const Eigen::VectorXd a = coarse.point(xi), b = fine.point(xi);
    worst = std::max(worst, (a - b).cwiseAbs().maxCoeff() / a.cwiseAbs().maxCoeff());
  }
  // case G: <= 1e-12 relative (round-off of the homogeneous maps and the banded solve)
  CHECK(worst <= 1e-12);
}

// NURBS geometry: basis properties and the exactness of the primitives (case G, docs/references.md).
#include "geometry/nurbs_patch.hpp"
#include "geometry/primitives.hpp"

#include <catch2/catch.hpp>
#include <random>

using namespace isosid::prep;

TEST_CASE("B-spline basis functions form a partition of unity and their derivatives sum to zero", "[geometry]") {
  KnotVector U(11);
  U << 0, 0, 0, 0, 0.2, 0.2, 0.5, 0.7, 1, 1, 1;
  U.conservativeResize(12);
  U(11) = 1;  // degree 3, interior knot 0.2 of multiplicity 2
  const int p = 3;
  std::mt19937 gen(3);
  std::uniform_real_distribution<double> u01(0, 1);
  for (int k = 0; k < 50; ++k) {
    const double u = u01(gen);
    const int span = find_span(U, p, u);
    REQUIRE(U(span) <= u);
    REQUIRE(u < U(span + 1));
    const Eigen::MatrixXd d = basis_derivatives(U, p, span, u, 2);
    CHECK(d.row(0).sum() == Approx(1.0).epsilon(1e-14));
    CHECK(d.row(1).sum() == Approx(0.0).margin(1e-12));
    CHECK(d.row(2).sum() == Approx(0.0).margin(1e-10));
    CHECK(d.row(0).minCoeff() >= 0.0);
    double N[16];
    basis_functions(U, p, span, u, N);
    for (int j = 0; j <= p; ++j) CHECK(N[j] == Approx(d(0, j)).margin(1e-15));
  }
  // derivative by central difference (second-order accurate, h = 1e-6: error ~ 1e-10)
  const double u = 0.43, h = 1e-6;
  const int span = find_span(U, p, u);
  const Eigen::MatrixXd d = basis_derivatives(U, p, span, u, 1);
  double Np[16], Nm[16];
  basis_functions(U, p, span, u + h, Np);
  basis_functions(U, p, span, u - h, Nm);
  for (int j = 0; j <= p; ++j) CHECK(d(1, j) == Approx((Np[j] - Nm[j]) / (2 * h)).margin(1e-8));
}

TEST_CASE("the seed primitives represent circles exactly", "[geometry]") {
  // case G: radius error <= 1e-13 r (round-off of the rational evaluation)
  const double r = 0.01;
  std::mt19937 gen(5);
  std::uniform_real_distribution<double> u01(0, 1);
  const NurbsPatch hd = primitives::half_disk(r);
  const NurbsPatch disk = primitives::disk(r);
  const NurbsPatch rod = primitives::rod_with_spherical_end(r, 1.0);
  const NurbsPatch ball = primitives::ball(r);
  const NurbsPatch spherical = primitives::ball_spherical(r);
  for (int k = 0; k < 100; ++k) {
    const double s = u01(gen), t = u01(gen);
    CHECK(std::abs(hd.point(Eigen::Vector2d(s, 0)).norm() - r) <= 1e-13 * r);  // lower arc
    CHECK(std::abs(hd.point(Eigen::Vector2d(s, 1)).norm() - r) <= 1e-13 * r);  // upper arc
    CHECK(std::abs(disk.point(Eigen::Vector2d(1, s)).norm() - r) <= 1e-13 * r);
    CHECK(std::abs(disk.point(Eigen::Vector2d(s, 0)).norm() - r) <= 1e-13 * r);
    const Eigen::Vector2d cap = rod.point(Eigen::Vector2d(s, 0));
    CHECK(std::abs((cap - Eigen::Vector2d(0, r)).norm() - r) <= 1e-13 * r);
    CHECK(std::abs(ball.point(Eigen::Vector3d(s, 0, t)).norm() - r) <= 1e-13 * r);
    CHECK(std::abs(ball.point(Eigen::Vector3d(s, 1, t)).norm() - r) <= 1e-13 * r);
    CHECK(std::abs(spherical.point(Eigen::Vector3d(s, 1, t)).norm() - r) <= 1e-13 * r);
    // eta is the radius: the map is eta times the surface point
    CHECK((spherical.point(Eigen::Vector3d(s, t, 0.3)) - t * spherical.point(Eigen::Vector3d(s, 1, 0.3))).norm() <= 1e-13 * r);
  }
  // spherical coordinates: xi = 0.5 is the equator, zeta = 0.25 its point on +z, xi = 0 the pole -y
  CHECK((spherical.point(Eigen::Vector3d(0.5, 1, 0.25)) - Eigen::Vector3d(0, 0, r)).norm() < 1e-16);
  CHECK((spherical.point(Eigen::Vector3d(0, 1, 0.6)) - Eigen::Vector3d(0, -r, 0)).norm() < 1e-16);
  // the contact pole of the half-disk is its corner xi = eta = 0
  CHECK((hd.point(Eigen::Vector2d(0, 0)) - Eigen::Vector2d(0, -r)).norm() < 1e-16);
  CHECK((disk.point(Eigen::Vector2d(1, 0.5)) - Eigen::Vector2d(0, -r)).norm() < 1e-16);
}

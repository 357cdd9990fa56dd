// Mass and inertia of the refined primitives against closed forms (case G, docs/references.md):
// mass = rho V (2 pi int r dA for axisymmetric) to 1e-10, inertia tensors of disk and ball.
#include "geometry/primitives.hpp"
#include "sid/body_integrals.hpp"
#include "preprocess/body_fixtures.hpp"

#include <catch2/catch.hpp>

using namespace isosid;
using format::AnalysisType;

namespace {
prep::RigidIntegrals integrals(const prep::BodyModel& b, int extra = 0) {
  const auto Ms = prep::assemble_scalar_mass(b.space, b.dofs, b.elasticity, extra);
  return prep::rigid_integrals(Ms, b.dofs.node_points(), b.spec.analysis);
}
prep::ModelSpec model(const std::string& name) { return prep::read_model_file(std::string(ISOSID_MODELS_DIR) + "/" + name); }
}  // namespace

// The integrands are rational (NURBS weights), so (p+1)-point Gauss quadrature is not exact;
// on the refined validation models the elements are small enough that its error stays below 1e-10.
TEST_CASE("seed models: mass equals rho times the exact volume", "[mass]") {
  const double r = 0.01;
  SECTION("sphere (axisymmetric)") {
    const auto b = prep::build_body(model("sphere_axisym.model.toml"));
    const auto I = integrals(b);
    const double m = 2789.0 * 4.0 / 3.0 * M_PI * r * r * r;
    CHECK(I.mass == Approx(m).epsilon(1e-10));
    CHECK(std::abs(I.first_moment(1)) < 1e-10 * m * r);  // centred at the origin
    // solid sphere: 2/5 m r^2 about every axis; r^2-weighted, the rational integrand is
    // integrated less exactly on the graded mesh's largest elements (measured 4.6e-10)
    CHECK(I.inertia()(0, 0) == Approx(0.4 * m * r * r).epsilon(1e-9));
    CHECK(I.inertia()(1, 1) == Approx(0.4 * m * r * r).epsilon(1e-9));
  }
  SECTION("rod with spherical end (axisymmetric)") {
    const auto b = prep::build_body(model("rod_axisym.model.toml"));
    const double l = 1.0;
    CHECK(integrals(b).mass == Approx(2789.0 * (M_PI * r * r * (l - r) + 2.0 / 3.0 * M_PI * r * r * r)).epsilon(1e-10));
  }
  SECTION("disk (plane strain, thickness 1 m)") {
    const auto b = prep::build_body(model("disk_plane_strain.model.toml"));
    const auto I = integrals(b);
    const double R = 0.1, m = 7850.0 * M_PI * R * R;
    CHECK(I.mass == Approx(m).epsilon(1e-10));
    CHECK(I.inertia()(2, 2) == Approx(0.5 * m * R * R).epsilon(1e-10));
  }
  SECTION("beam (box)") {
    const auto b = prep::build_body(model("beam_free_free.model.toml"));
    const auto I = integrals(b);
    const double m = 7800.0 * 0.21 * 0.01 * 0.015;
    CHECK(I.mass == Approx(m).epsilon(1e-12));  // polynomial geometry: quadrature is exact
    CHECK(I.first_moment(0) / m == Approx(0.105).epsilon(1e-12));
  }
}

TEST_CASE("3D ball: mass and inertia tensor", "[mass]") {
  const double r = 0.01, rho = 7850;
  prep::RefinementSpec ref;
  ref.degrees = {3, 3, 3};
  ref.subdivisions = {4, 4, 4};
  // both parametrizations: the revolved half-disk and spherical coordinates (a singular centre)
  for (const bool spherical : {false, true}) {
    INFO((spherical ? "ball_spherical" : "ball"));
    const auto b = prep::build_body(test::spec_for(spherical ? prep::primitives::ball_spherical(r) : prep::primitives::ball(r),
                                                   AnalysisType::Solid, 2.1e11, 0.3, rho, ref));
    // a coarse revolved mesh with a singular axis: 4 extra Gauss points bring the rational
    // quadrature error below 1e-10
    const auto I = integrals(b, 4);
    const double m = rho * 4.0 / 3.0 * M_PI * r * r * r;
    CHECK(I.mass == Approx(m).epsilon(1e-10));
    CHECK(I.first_moment.norm() < 1e-10 * m * r);
    const Eigen::Matrix3d expected = 0.4 * m * r * r * Eigen::Matrix3d::Identity();
    CHECK((I.inertia() - expected).norm() < 1e-10 * expected.norm());
  }
}

TEST_CASE("hierarchical models keep the mass and inertia of their coarse models", "[mass][thb]") {
  // the geometry map is the coarse NURBS exactly, so every body integral is the same up to
  // quadrature (rational integrands on different elements: 1e-10 with 4 extra points)
  for (const char* name : {"sphere_axisym_thb.model.toml", "ball_3d_thb.model.toml"}) {
    INFO(name);
    const auto spec = model(name);
    const auto fine = prep::build_body(spec);
    const auto coarse = prep::build_body(prep::coarse_model_spec(spec));
    REQUIRE(fine.hierarchy);
    const auto a = integrals(coarse, 4), b = integrals(fine, 4);
    CHECK(b.mass == Approx(a.mass).epsilon(1e-10));
    CHECK((b.first_moment - a.first_moment).norm() < 1e-10 * a.mass * prep::body_size(coarse));
    CHECK((b.inertia() - a.inertia()).norm() < 1e-10 * a.inertia().norm());
  }
}

// In-process test of QuasistaticModes: one static solve of the high modes under penalty
// contact against a dense direct solve of the same equilibrium.
#include "contact/quasistatic_modes.hpp"
#include "contact/shape_target.hpp"
#include "support/lumped_sid.hpp"

#include <catch2/catch.hpp>

using namespace isosid;

TEST_CASE("QuasistaticModes: one static solve equals a dense direct solve", "[runtime][unit]") {
  format::Sid sid = test::lumped_sid(test::random_lumped_body(12, 6, 11));
  sid.refmod.n_low = 2;  // modes 3..6 are the quasistatic ones
  const format::ContactSurface& s = sid.contact_surfaces.front();
  run::ShapeSpec plane;
  plane.kind = run::ShapeSpec::Kind::Plane;
  plane.name = "ground";
  plane.normal = {0, 1, 0};
  plane.point = {0, s.position.col(1).maxCoeff() + 0.1, 0};
  const double penalty = 1e10;
  const run::ContactSpec contact_spec{"impact", "body", s.name, "ground", "", penalty, 0.0, 1e-6};
  run::BodySpec spec;
  spec.name = "body";
  spec.high_modes = "quasistatic";

  std::vector<std::unique_ptr<run::FloatingBody>> bodies;
  bodies.push_back(std::make_unique<run::FloatingBody>(spec, sid, run::Dimension::Solid));
  const run::FloatingBody& body = *bodies.front();
  const run::ShapeTarget ground(plane);
  std::vector<run::SurfaceContact> contacts;
  contacts.emplace_back(contact_spec, body, ground);
  const run::QuasistaticModes modes(bodies, contacts);
  REQUIRE(modes.size() == 4);
  Eigen::VectorXd y(body.state_size());
  body.initial_state(y.data());
  CHECK(modes.solve(y.data()) > 0);
  const Eigen::VectorXd z = body.quasistatic_modes();

  // With every point penetrating, the equilibrium K_h z = -c_p sum w n (g0 + n^T Psi_h z) Psi_h^T
  // is linear: (K_h + c_p sum w Psi_h^T n n^T Psi_h) z = -c_p sum w g0 Psi_h^T n.
  const Eigen::Index nh = 4;
  Eigen::MatrixXd A = sid.Ke.M0.bottomRightCorner(nh, nh);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(nh);
  for (Eigen::Index g = 0; g < s.points(); ++g) {
    const Eigen::VectorXd normal_rows = s.Psi.middleRows(3 * g, 3).rightCols(nh).transpose() * plane.normal;
    const double g0 = s.position(g, 1) - plane.point.y();
    A += penalty * s.weight(g) * normal_rows * normal_rows.transpose();
    b -= penalty * s.weight(g) * g0 * normal_rows;
    // the active set of the linear solution: every point still penetrates
    REQUIRE(g0 + normal_rows.dot(z) < 0);
  }
  const Eigen::VectorXd expected = A.ldlt().solve(b);
  REQUIRE(expected.norm() > 0);
  // Newton stops at a relative residual near round-off of the stiffness (about 1e-10)
  CHECK((z - expected).norm() < 1e-8 * expected.norm());
}

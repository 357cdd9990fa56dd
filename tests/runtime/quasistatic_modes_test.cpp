// In-process tests of QuasistaticModes: one static solve of the high modes under penalty
// contact against a dense direct solve of the same equilibrium, and a partial contact against
// the optimality conditions.
#include "condensation/quasistatic_modes.hpp"
#include "contact/penalty_decision.hpp"
#include "contact/shape_target.hpp"
#include "support/lumped_sid.hpp"

#include <catch2/catch.hpp>

#include <algorithm>

using namespace isosid;

namespace {
/// The body of `sid` with quasistatic high modes against the fixed plane `plane` at `penalty`:
/// what QuasistaticModes solves (the body's frame is the world's at its initial state).
struct PlaneContact {
  PlaneContact(const format::Sid& sid, const run::ShapeSpec& plane, double penalty) : ground(plane) {
    run::BodySpec spec;
    spec.name = "body";
    spec.high_modes = "quasistatic";
    bodies.push_back(std::make_unique<run::FloatingBody>(spec, sid, run::Dimension::Solid));
    const run::ContactSpec contact{"impact", "body", sid.contact_surfaces.front().name, plane.name, "", penalty, 0.0, 1e-6};
    contacts.emplace_back(contact, body(), ground);
    contacts.back().set_penalty(run::decide_penalty(contacts.back(), std::nullopt, 0));
    modes = std::make_unique<run::QuasistaticModes>(bodies, contacts, Eigen::Vector3d::Zero());
  }
  PlaneContact(const PlaneContact&) = delete;  // the contacts refer to the members
  const run::FloatingBody& body() const { return *bodies.front(); }

  std::vector<std::unique_ptr<run::FloatingBody>> bodies;
  const run::ShapeTarget ground;
  std::vector<run::SurfaceContact> contacts;
  std::unique_ptr<run::QuasistaticModes> modes;
};
}  // namespace

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
  const PlaneContact setup(sid, plane, penalty);
  const run::FloatingBody& body = setup.body();
  const run::QuasistaticModes& modes = *setup.modes;
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

TEST_CASE("QuasistaticModes: a tilted plane that presses part of the surface meets the optimality conditions",
          "[runtime][unit]") {
  // Part of the points touch, and which ones depends on the deformation: the solution is
  // checked by the conditions that define it, from the SID alone (not the runtime's terms):
  // the energy's gradient K_h z - sum over penetrating points of c_p w (-g) Psi_h^T n is zero.
  const test::LumpedBody lumped = test::random_lumped_body(40, 8, 5);
  format::Sid sid = test::lumped_sid(lumped);
  sid.refmod.n_low = 2;  // modes 3..8 are quasistatic
  // every point of the cloud a contact point (the lumped SID's surface has four)
  format::ContactSurface& s = sid.contact_surfaces.front();
  const Eigen::Index np = lumped.points.rows();
  s.position = lumped.points;
  s.Psi = lumped.Phi;
  s.weight = Eigen::VectorXd::Constant(np, 1e-5);
  s.normal = Eigen::MatrixXd::Zero(np, 3);
  s.normal.col(1).setConstant(-1);
  s.parameter = Eigen::MatrixXd::Zero(np, 3);
  s.element = Eigen::VectorXi::LinSpaced(np, 0, int(np) - 1);
  const Eigen::Vector3d normal = Eigen::Vector3d(0.3, 1.0, -0.2).normalized();
  Eigen::VectorXd height(s.points());
  for (Eigen::Index g = 0; g < s.points(); ++g) height(g) = normal.dot(s.position.row(g).transpose());
  std::vector<double> sorted(height.data(), height.data() + height.size());
  std::sort(sorted.begin(), sorted.end());
  run::ShapeSpec plane;
  plane.kind = run::ShapeSpec::Kind::Plane;
  plane.name = "ground";
  plane.normal = -normal;  // the target lies on the side of large heights: points above the median penetrate
  plane.point = sorted[sorted.size() / 2] * normal;
  const Eigen::Index nh = 6;
  const Eigen::MatrixXd K = sid.Ke.M0.bottomRightCorner(nh, nh);
  // a penalty whose contact stiffness matches the modes' (c_p w |Psi|^2 ~ K): the deformation
  // then moves points across the plane, so the active set is not the one of the rigid body
  const double penalty = K.diagonal().mean() / (s.weight.mean() * s.Psi.rightCols(nh).squaredNorm() / double(s.points()));
  const PlaneContact setup(sid, plane, penalty);
  const run::FloatingBody& body = setup.body();
  const run::QuasistaticModes& modes = *setup.modes;
  Eigen::VectorXd y(body.state_size());
  body.initial_state(y.data());
  // gaps from the SID: signed distance to the plane of X + Psi_h z shifted by `lift` along the
  // plane's normal (world = body frame here, the body's position along it)
  auto gap = [&](Eigen::Index g, const Eigen::VectorXd& zz, double lift) {
    const Eigen::Vector3d x = s.position.row(g).transpose() + s.Psi.middleRows(3 * g, 3).rightCols(nh) * zz;
    return plane.normal.dot(x - plane.point) + lift;
  };
  // the optimality conditions at the modes' solution for the body lifted by `lift`
  auto check_optimality = [&](double lift) {
    const Eigen::VectorXd z = body.quasistatic_modes();
    Eigen::VectorXd gradient = K * z, contact_force = Eigen::VectorXd::Zero(nh);
    int pressed = 0, pressed_rigid = 0, changed = 0;
    for (Eigen::Index g = 0; g < s.points(); ++g) {
      const double g_z = gap(g, z, lift), g_0 = gap(g, Eigen::VectorXd::Zero(nh), lift);
      pressed += g_z < 0;
      pressed_rigid += g_0 < 0;
      changed += (g_z < 0) != (g_0 < 0);
      if (g_z < 0) contact_force += penalty * s.weight(g) * (-g_z) * s.Psi.middleRows(3 * g, 3).rightCols(nh).transpose() * plane.normal;
    }
    gradient -= contact_force;
    INFO("lift " << lift << ": pressed " << pressed << " of " << s.points() << " (undeformed " << pressed_rigid << "), changed " << changed);
    REQUIRE(pressed > 0);
    REQUIRE(pressed < s.points());
    CHECK(changed > 0);  // the case exercises a change of the active set
    // Newton stops at an update of 1e-11 |z|; the gradient then vanishes to the round-off of
    // the forces it balances (1e-8 of them leaves a thousandfold margin)
    CHECK(gradient.norm() < 1e-8 * contact_force.norm());
  };
  // from the undeformed body: the linear model is exact against a plane, so one step solves
  // it and a second at most confirms
  CHECK(modes.solve(y.data()) <= 2);
  check_optimality(0);
  // from that solution, the body moved by a tenth of its modes' largest displacement along
  // the normal: a move the recorded points bound, so the model's solution is taken without
  // another pass over the points, and it must still be the solution
  const double shift = 0.1 * (s.Psi.rightCols(nh) * body.quasistatic_modes()).cwiseAbs().maxCoeff();
  y.segment(body.offset(), 3) += shift * plane.normal;
  CHECK(modes.solve(y.data()) == 1);
  check_optimality(shift);
}

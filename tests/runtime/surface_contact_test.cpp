// In-process tests of SurfaceContact: the force of a prescribed penetration against the
// penalty law, point by point, the direction and size of the friction force, and the
// default penalty rule.
#include "contact/default_penalty.hpp"
#include "contact/penalty_decision.hpp"
#include "contact/shape_target.hpp"
#include "contact/surface_contact.hpp"
#include "support/lumped_sid.hpp"

#include <catch2/catch.hpp>
#include <algorithm>

using namespace isosid;

namespace {

/// A 3D lumped body moving at `velocity` and a plane (normal +y) 0.1 m + `plane_shift` above
/// the highest of its four contact points.
struct PenetratingBody {
  format::Sid sid = test::lumped_sid(test::random_lumped_body(12, 5, 7));
  run::ShapeSpec plane;
  run::BodySpec spec;
  PenetratingBody(const Eigen::Vector3d& velocity, double plane_shift = 0) {
    const format::ContactSurface& s = sid.contact_surfaces.front();
    plane.kind = run::ShapeSpec::Kind::Plane;
    plane.name = "ground";
    plane.normal = {0, 1, 0};
    plane.point = {0, s.position.col(1).maxCoeff() + 0.1 + plane_shift, 0};
    spec.name = "body";
    spec.velocity = velocity;
  }
  const format::ContactSurface& surface() const { return sid.contact_surfaces.front(); }
};

/// The body, the plane and their contact at the initial state, evaluated once.
struct EvaluatedContact {
  run::FloatingBody body;
  run::ShapeTarget ground;
  run::SurfaceContact contact;
  Eigen::VectorXd y;
  run::GeneralizedForce force;
  run::ContactState state;
  EvaluatedContact(const PenetratingBody& setup, double penalty, double friction)
      : body(setup.spec, setup.sid, run::Dimension::Solid),
        ground(setup.plane),
        contact({"impact", "body", setup.surface().name, "ground", "", penalty, friction, 1e-6}, body, ground),
        y(body.state_size()) {
    contact.set_penalty(run::decide_penalty(contact, std::nullopt, 0));
    body.initial_state(y.data());
    force.reset(body.nq());
    state = contact.apply(y.data(), force, nullptr);
  }
};

}  // namespace

TEST_CASE("SurfaceContact: a prescribed penetration gives the penalty force of every point", "[runtime][unit]") {
  const double penalty = 1e10, mu = 0.3;
  const PenetratingBody setup({0.2, 0.0, 0.1});  // sliding along the plane
  const EvaluatedContact evaluated(setup, penalty, mu);
  const run::ContactState& state = evaluated.state;
  const run::GeneralizedForce& force = evaluated.force;

  // the penalty law, point by point: c_p |g| w along the plane normal, plus regularized
  // Coulomb friction -mu v_t / sqrt(|v_t|^2 + eps^2) per unit normal force
  const format::ContactSurface& s = setup.surface();
  const Eigen::Vector3d v_t = setup.spec.velocity;
  const Eigen::Vector3d friction = -mu * v_t / std::sqrt(v_t.squaredNorm() + 1e-12);
  Eigen::Vector3d total = Eigen::Vector3d::Zero();
  Eigen::VectorXd elastic = Eigen::VectorXd::Zero(evaluated.body.nq());
  double energy = 0;
  for (Eigen::Index g = 0; g < s.points(); ++g) {
    const double gap = s.position(g, 1) - setup.plane.point.y();
    REQUIRE(gap < 0);
    const double normal_force = penalty * -gap * s.weight(g);
    const Eigen::Vector3d F = normal_force * (setup.plane.normal + friction);
    total += F;
    elastic += s.Psi.middleRows(3 * g, 3).transpose() * F;
    energy += 0.5 * penalty * gap * gap * s.weight(g);
  }
  // round-off of sums of a few terms
  CHECK(state.active_points == s.points());
  CHECK((state.force - total).norm() < 1e-12 * total.norm());
  CHECK((force.force - total).norm() < 1e-12 * total.norm());
  CHECK((force.elastic - elastic).norm() < 1e-12 * elastic.norm());
  CHECK(state.penalty_energy == Approx(energy).epsilon(1e-12));
  // friction opposes the sliding, at mu times the normal force
  const Eigen::Vector3d tangential = state.force - state.force.dot(setup.plane.normal) * setup.plane.normal;
  CHECK(tangential.normalized().dot(-v_t.normalized()) == Approx(1.0).epsilon(1e-12));
  CHECK(tangential.norm() == Approx(mu * state.force.dot(setup.plane.normal)).epsilon(1e-9));
  CHECK(state.friction_power == Approx(-tangential.dot(v_t)).epsilon(1e-12));
}

TEST_CASE("SurfaceContact: a surface clear of the target carries no force", "[runtime][unit]") {
  const PenetratingBody setup(Eigen::Vector3d::Zero(), -0.5);  // the plane 0.3 m and more below every point
  const EvaluatedContact evaluated(setup, 1e10, 0.3);
  CHECK(evaluated.state.active_points == 0);
  CHECK(evaluated.state.force.norm() == 0);
  CHECK(evaluated.contact.min_gap(evaluated.y.data()) > 0.25);
}

TEST_CASE("the penalty decision: one given for the run, else the scene's, else 1000 E*/max(a, h)", "[runtime][unit]") {
  const PenetratingBody setup(Eigen::Vector3d::Zero());
  const EvaluatedContact evaluated(setup, 0.0, 0.0);  // no penalty in the scene
  const run::SurfaceContact& contact = evaluated.contact;
  // every point of the lumped surface is its own element of area 1e-5 .. 4e-5 m^2: h = sqrt(1e-5);
  // a fixed plane is rigid: E* = E / (1 - nu^2)
  const format::Material& m = setup.sid.material;
  const double expected = 1000 * m.youngs_modulus / (1 - m.poisson_ratio * m.poisson_ratio) / std::sqrt(1e-5);
  CHECK(contact.penalty_source() == "derived: 1000 E*/h");  // as the fixture decided it, without an estimate
  CHECK(contact.penalty() == Approx(expected).epsilon(1e-12));
  // an expected contact radius below the element size changes nothing; above it, it rules
  const run::ContactPenalty small = run::decide_penalty(contact, std::nullopt, 0.5 * std::sqrt(1e-5));
  CHECK(small.source == "derived: 1000 E*/h");
  CHECK(small.value == Approx(expected).epsilon(1e-12));
  const run::ContactPenalty large = run::decide_penalty(contact, std::nullopt, 4 * std::sqrt(1e-5));
  CHECK(large.source == "derived: 1000 E*/a");
  CHECK(large.value == Approx(expected / 4).epsilon(1e-12));

  // a penalty the scene gives stays, whatever the contact radius
  const EvaluatedContact given(setup, 1e10, 0.0);
  const run::ContactPenalty scene = run::decide_penalty(given.contact, std::nullopt, 1.0);
  CHECK(scene.source == "scene");
  CHECK(scene.value == 1e10);
  // and one given for the run (the adaptive loop's penalty search) rules over both
  const run::ContactPenalty search{3e11, "penalty search: found by trial"};
  for (const run::SurfaceContact* c : {&contact, &given.contact}) {
    const run::ContactPenalty decided = run::decide_penalty(*c, search, 1.0);
    CHECK(decided.value == search.value);
    CHECK(decided.source == search.source);
  }

  // two elastic bodies add their compliances
  format::Sid aluminium = setup.sid;
  aluminium.material = {70e9, 0.33, 2700};
  run::BodySpec other = setup.spec;
  other.name = "other";
  const run::FloatingBody master(other, aluminium, run::Dimension::Solid);
  CHECK(run::combined_modulus(evaluated.body, &master) ==
        Approx(1 / ((1 - 0.09) / m.youngs_modulus + (1 - 0.33 * 0.33) / 70e9)).epsilon(1e-12));
}

TEST_CASE("SurfaceContact: a deformed body's pressed points and least gap on a plane are those of every point placed", "[runtime][unit]") {
  // The plane's gaps leave out the points whose undeformed gap, less |Psi_g|_F |q|, is beyond
  // what the caller needs; the rest are placed each by its rows or all in one product. Against
  // every point placed by hand, for planes between the deformed points' heights (one to four
  // pressed) and halfway between a point's undeformed and deformed height (the deformation
  // alone decides whether it presses).
  const double penalty = 1e10;
  PenetratingBody setup(Eigen::Vector3d::Zero());
  const format::ContactSurface& s = setup.surface();
  run::FloatingBody probe(setup.spec, setup.sid, run::Dimension::Solid);
  Eigen::VectorXd y(probe.state_size());
  probe.initial_state(y.data());
  // a deformation that moves the points by a tenth of the least height between two of them
  std::vector<double> heights;
  for (Eigen::Index g = 0; g < s.points(); ++g) heights.push_back(s.position(g, 1));
  std::sort(heights.begin(), heights.end());
  double spacing = INFINITY;
  for (std::size_t k = 1; k < heights.size(); ++k) spacing = std::min(spacing, heights[k] - heights[k - 1]);
  Eigen::VectorXd q = Eigen::VectorXd::LinSpaced(probe.nq(), 1.0, -0.6);
  double largest_move = 0;
  for (Eigen::Index g = 0; g < s.points(); ++g) largest_move = std::max(largest_move, s.Psi.middleRows(3 * g, 3).norm() * q.norm());
  q *= 0.1 * spacing / largest_move;
  Eigen::Map<Eigen::VectorXd>(y.data() + 7, probe.nq()) = q;
  Eigen::VectorXd deformed(s.points());
  for (Eigen::Index g = 0; g < s.points(); ++g) deformed(g) = s.position(g, 1) + s.Psi.row(3 * g + 1).dot(q);
  REQUIRE((deformed - s.position.col(1)).cwiseAbs().minCoeff() > 0);

  std::vector<double> planes;
  std::vector<double> sorted(deformed.data(), deformed.data() + deformed.size());
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t k = 0; k + 1 < sorted.size(); ++k) planes.push_back(0.5 * (sorted[k] + sorted[k + 1]));
  planes.push_back(sorted.back() + spacing);
  for (Eigen::Index g = 0; g < s.points(); ++g) planes.push_back(0.5 * (s.position(g, 1) + deformed(g)));
  for (double level : planes) {
    setup.plane.point = {0, level, 0};
    const run::FloatingBody body(setup.spec, setup.sid, run::Dimension::Solid);
    const run::ShapeTarget ground(setup.plane);
    run::SurfaceContact contact({"impact", "body", s.name, "ground", "", penalty, 0.0, 1e-6}, body, ground);
    contact.set_penalty(run::decide_penalty(contact, std::nullopt, 0));
    run::GeneralizedForce force;
    force.reset(body.nq());
    const run::ContactState state = contact.apply(y.data(), force, nullptr);
    int pressed = 0;
    Eigen::Vector3d total = Eigen::Vector3d::Zero();
    for (Eigen::Index g = 0; g < s.points(); ++g) {
      const double gap = deformed(g) - level;
      if (gap >= 0) continue;
      ++pressed;
      total += penalty * -gap * s.weight(g) * Eigen::Vector3d::UnitY();
    }
    INFO("plane at " << level << ": " << pressed << " pressed");
    CHECK(state.active_points == pressed);
    // round-off of sums of a few terms
    CHECK((state.force - total).norm() <= 1e-12 * total.norm());
    CHECK(contact.min_gap(y.data()) == Approx((deformed.array() - level).minCoeff()).epsilon(1e-12));
  }
}

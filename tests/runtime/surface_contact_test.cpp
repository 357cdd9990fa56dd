// In-process tests of SurfaceContact: the force of a prescribed penetration against the
// penalty law, point by point, the direction and size of the friction force, and the
// default penalty rule.
#include "contact/default_penalty.hpp"
#include "contact/shape_target.hpp"
#include "contact/surface_contact.hpp"
#include "support/lumped_sid.hpp"

#include <catch2/catch.hpp>

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

TEST_CASE("SurfaceContact: without a penalty in the scene it takes 1000 E*/max(a, h)", "[runtime][unit]") {
  const PenetratingBody setup(Eigen::Vector3d::Zero());
  EvaluatedContact evaluated(setup, 0.0, 0.0);  // no penalty given
  run::SurfaceContact& contact = evaluated.contact;
  // every point of the lumped surface is its own element of area 1e-5 .. 4e-5 m^2: h = sqrt(1e-5);
  // a fixed plane is rigid: E* = E / (1 - nu^2)
  const format::Material& m = setup.sid.material;
  const double expected = 1000 * m.youngs_modulus / (1 - m.poisson_ratio * m.poisson_ratio) / std::sqrt(1e-5);
  CHECK(contact.penalty_source() == "derived: 1000 E*/h");
  CHECK(contact.penalty() == Approx(expected).epsilon(1e-12));
  // an expected contact radius below the element size changes nothing; above it, it rules
  contact.fit_penalty_to_contact_radius(0.5 * std::sqrt(1e-5));
  CHECK(contact.penalty() == Approx(expected).epsilon(1e-12));
  contact.fit_penalty_to_contact_radius(4 * std::sqrt(1e-5));
  CHECK(contact.penalty_source() == "derived: 1000 E*/a");
  CHECK(contact.penalty() == Approx(expected / 4).epsilon(1e-12));

  // a penalty the scene gives stays
  EvaluatedContact given(setup, 1e10, 0.0);
  given.contact.fit_penalty_to_contact_radius(1.0);
  CHECK(given.contact.penalty_source() == "scene");
  CHECK(given.contact.penalty() == 1e10);
  // and so does one the adaptive loop gives, whatever its source says: its penalty search
  // starts from a derived value and probes ten times it
  run::ContactSpec spec{"impact", "body", setup.surface().name, "ground", "", 1e10, 0.0, 1e-6};
  spec.penalty_source = "derived: 1000 E*/a (the penalty search's start)";
  run::SurfaceContact probed(spec, given.body, given.ground);
  probed.fit_penalty_to_contact_radius(1.0);
  CHECK(probed.penalty() == 1e10);
  CHECK(probed.penalty_source() == spec.penalty_source);

  // two elastic bodies add their compliances
  format::Sid aluminium = setup.sid;
  aluminium.material = {70e9, 0.33, 2700};
  run::BodySpec other = setup.spec;
  other.name = "other";
  const run::FloatingBody master(other, aluminium, run::Dimension::Solid);
  CHECK(run::combined_modulus(evaluated.body, &master) ==
        Approx(1 / ((1 - 0.09) / m.youngs_modulus + (1 - 0.33 * 0.33) / 70e9)).epsilon(1e-12));
}

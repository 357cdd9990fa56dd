// In-process tests of FloatingBody and Simulation: free flight against the closed form, the
// invariants of torque-free rotation, the rotation loads on quasistatic modes and when they are
// left out, the modal matrices' block forms, the kinetic energy, and what a run reports to its
// observer.
#include "body/floating_body.hpp"
#include "body/rigid_body_sid.hpp"
#include "isosid/format/sid_io.hpp"
#include "isosid/format/skew.hpp"
#include "solve/simulation.hpp"
#include "solve/time_integrator.hpp"

#include <algorithm>
#include <cmath>

#include <catch2/catch.hpp>

using namespace isosid;

namespace {

run::Scene free_flight_scene(double end_time) {
  run::Scene scene;
  scene.file = "in-process";
  scene.simulation.dimension = run::Dimension::Solid;
  scene.simulation.end_time = end_time;
  scene.simulation.rtol = 1e-10;
  scene.simulation.atol = 1e-14;
  scene.simulation.output_interval = end_time / 20;
  return scene;
}

/// Counts what a run reports.
struct CountingObserver : run::SimulationObserver {
  int samples = 0, steps = 0, events = 0;
  double last_sample = -1;
  void sample(double t, const double*) override { ++samples, last_sample = t; }
  void step(double, const double*) override { ++steps; }
  void contact_event(int, bool, double) override { ++events; }
};

}  // namespace

TEST_CASE("FloatingBody: a flexible body in free flight under gravity follows the parabola", "[runtime][unit]") {
  run::Scene scene = free_flight_scene(0.02);
  scene.gravity = {0, -9.81, 0};
  run::BodySpec beam;
  beam.name = "beam";
  beam.position = {0, 1, 0};
  beam.velocity = {1, 2, -0.5};
  scene.bodies.push_back(beam);
  run::Simulation simulation(scene, {format::read_sid(std::string(ISOSID_GOLDEN_DIR) + "/beam_small.sid.h5")});
  const run::FloatingBody& body = simulation.system().body("beam");

  // at rest in its reference shape the body falls freely: v' = g, omega' = 0, q'' = 0 (the
  // Buckens frame keeps gravity out of the modes: Ct = 0)
  Eigen::VectorXd y = simulation.state(), ydot(y.size());
  run::GeneralizedForce none;
  none.reset(body.nq());
  body.derivatives(y.data(), none, scene.gravity, ydot.data());
  const Eigen::Index velocity_rates = body.offset() + 7 + body.n_dynamic();
  CHECK((ydot.segment<3>(velocity_rates) - scene.gravity).norm() < 1e-12);
  CHECK(ydot.segment<3>(velocity_rates + 3).norm() < 1e-12);
  CHECK(ydot.segment(velocity_rates + 6, body.n_dynamic()).norm() < 1e-9);

  CountingObserver observer;
  const run::RunOutcome outcome = simulation.run(observer);
  REQUIRE(outcome.completed());
  const double t = 0.02;
  const Eigen::Vector3d r = body.r(simulation.state().data()), v = body.v(simulation.state().data());
  // tolerance: rtol 1e-10 over ~1e3 steps of a polynomial solution (DP5 integrates it exactly)
  CHECK(r.x() == Approx(1.0 * t).epsilon(1e-9));
  CHECK(r.y() == Approx(1.0 + 2.0 * t - 0.5 * 9.81 * t * t).epsilon(1e-9));
  CHECK(r.z() == Approx(-0.5 * t).epsilon(1e-9));
  CHECK(v.y() == Approx(2.0 - 9.81 * t).epsilon(1e-9));
  // the observer saw the start, every output time and every accepted step
  CHECK(observer.samples == 21);
  CHECK(observer.last_sample == Approx(t));
  CHECK(observer.steps == simulation.stats().steps);
  CHECK(observer.events == 0);
}

TEST_CASE("TimeIntegrator: every kind the scene can name carries a free flight along its parabola", "[runtime][unit]") {
  // The integrator interface: make_integrator gives each kind, advance() reaches the time
  // asked, stats() counts the steps the step callback saw. A parabola is a polynomial of
  // degree 2: Dormand-Prince and the ESDIRK integrate it exactly but for their tolerance
  // (rtol 1e-10 over some hundred steps: 1e-9), the leapfrog's kicks and drift exactly (1e-12).
  for (const run::IntegratorKind kind : {run::IntegratorKind::DormandPrince, run::IntegratorKind::Implicit, run::IntegratorKind::Leapfrog}) {
    run::Scene scene = free_flight_scene(0.02);
    scene.gravity = {0, -9.81, 0};
    scene.simulation.integrator = kind;
    scene.simulation.step = 1e-5;  // the leapfrog is stable below 2 / omega_max: 1.6e-4 s here
    run::BodySpec beam;
    beam.name = "beam";
    beam.position = {0, 1, 0};
    beam.velocity = {1, 2, -0.5};
    beam.high_modes = "quasistatic";
    beam.quasistatic_above_hz = 2000.0;  // 2 integrated modes
    scene.bodies.push_back(beam);
    const run::MultibodySystem system(scene, {format::read_sid(std::string(ISOSID_GOLDEN_DIR) + "/beam_small.sid.h5")});
    Eigen::VectorXd y0(system.size());
    system.initial_state(y0.data());
    const std::unique_ptr<run::TimeIntegrator> integrator = run::make_integrator(system, scene.simulation, y0);
    long seen = 0;
    integrator->on_step([&](double, const double*) { ++seen; });
    double t = 0;
    CHECK(integrator->advance(0.02, t).empty());  // no contact: no gap changes
    const double tolerance = kind == run::IntegratorKind::Leapfrog ? 1e-12 : 1e-9;
    const run::FloatingBody& body = system.body("beam");
    INFO("integrator kind " << int(kind));
    CHECK(t == Approx(0.02).epsilon(1e-12));
    CHECK(body.r(integrator->y().data()).y() == Approx(1.0 + 2.0 * t - 0.5 * 9.81 * t * t).epsilon(tolerance));
    CHECK(body.v(integrator->y().data()).y() == Approx(2.0 - 9.81 * t).epsilon(tolerance));
    CHECK(integrator->stats().steps == seen);
    CHECK(seen > 0);
  }
}

TEST_CASE("FloatingBody: a torque-free rigid box keeps its world angular momentum and its energy", "[runtime][unit]") {
  run::Scene scene = free_flight_scene(0.5);
  run::BodySpec box;
  box.name = "box";
  box.rigid = run::RigidShape{run::RigidShape::Kind::Box, 0, {0.1, 0.05, 0.02}, 2.0, {}};
  const Eigen::Vector3d s2 = (2 * box.rigid->half_extents).cwiseAbs2();
  box.rigid->principal_inertia = 2.0 / 12 * Eigen::Vector3d(s2.y() + s2.z(), s2.x() + s2.z(), s2.x() + s2.y());
  box.velocity = {0.3, -0.2, 0.1};
  box.angular_velocity = {3, 0.2, -1};  // near the intermediate axis: a tumbling motion
  box.tait_bryan = {0.3, -0.2, 0.5};
  scene.bodies.push_back(box);
  run::Simulation simulation(scene, {});
  const run::FloatingBody& body = simulation.system().body("box");
  const Eigen::Matrix3d J = box.rigid->principal_inertia.asDiagonal();
  auto momentum = [&](const double* y) -> Eigen::Vector3d { return body.orientation(y).toRotationMatrix() * J * body.omega(y); };
  const Eigen::Vector3d L0 = momentum(simulation.state().data());
  const double E0 = body.kinetic_energy(simulation.state().data());

  CountingObserver observer;
  REQUIRE(simulation.run(observer).completed());
  const double* y = simulation.state().data();
  // rtol 1e-10 over ~1e3 steps: the invariants drift by less than 1e-8
  CHECK((momentum(y) - L0).norm() < 1e-8 * L0.norm());
  CHECK(body.kinetic_energy(y) == Approx(E0).epsilon(1e-8));
  CHECK((body.r(y) - 0.5 * box.velocity).norm() < 1e-9);
  CHECK((body.omega(y) - box.angular_velocity).norm() > 1e-2);  // it did tumble
}

TEST_CASE("FloatingBody: the rotation loads on the quasistatic modes are the SID's -Ge(qdot) w - Oe(q) w^2 there",
          "[runtime][unit]") {
  // The loads are formed by rows (the integrated modes' in derivatives(), the quasistatic
  // modes' here) from a side-by-side copy of Oe's first-order terms; the reference sums the
  // SID's Taylor terms directly. The beam's SID carries first-order terms (Oe1).
  const format::Sid sid = format::read_sid(std::string(ISOSID_GOLDEN_DIR) + "/beam_small.sid.h5");
  REQUIRE(sid.Oe.order() == 1);
  const Eigen::Index nq = sid.nq();
  // a general spin, and one about z alone (as in a plane: only one component of w^2 is not zero)
  for (const Eigen::Vector3d& w : {Eigen::Vector3d(0.5, 3.0, 40.0), Eigen::Vector3d(0.0, 0.0, 40.0)})
  for (double split_hz : {2000.0, 1.0}) {  // 2 integrated modes, or none (every row quasistatic)
    run::BodySpec spec;
    spec.name = "beam";
    spec.high_modes = "quasistatic";
    spec.quasistatic_above_hz = split_hz;
    const run::FloatingBody body(spec, sid, run::Dimension::Solid);
    const Eigen::Index nd = body.n_dynamic();
    REQUIRE(body.n_quasistatic() > 0);
    Eigen::VectorXd y = Eigen::VectorXd::Zero(body.state_size());
    body.initial_state(y.data());
    y.segment(7, nd) = Eigen::VectorXd::LinSpaced(nd, 1e-4, 3e-4);            // q of the integrated modes
    y.segment<3>(10 + nd) = w;
    y.segment(13 + nd, nd) = Eigen::VectorXd::LinSpaced(nd, -0.2, 0.1);       // their velocities
    body.quasistatic_modes() = Eigen::VectorXd::LinSpaced(nq - nd, -2e-4, 5e-4);
    const Eigen::VectorXd q = body.q(y.data()), qdot = body.qdot(y.data());

    Eigen::Matrix<double, 6, 1> w2;
    w2 << w.x() * w.x(), w.y() * w.y(), w.z() * w.z(), w.x() * w.y(), w.y() * w.z(), w.z() * w.x();
    Eigen::VectorXd expected = -sid.Oe.at(q) * w2;
    Eigen::VectorXd magnitude = sid.Oe.at(q).cwiseAbs() * w2.cwiseAbs();  // of the summed terms
    for (Eigen::Index j = 0; j < nq; ++j) {
      expected -= qdot(j) * (sid.Ge.M0.middleCols(3 * j, 3) * w);
      magnitude += std::abs(qdot(j)) * (sid.Ge.M0.middleCols(3 * j, 3).cwiseAbs() * w.cwiseAbs());
    }
    Eigen::VectorXd loads = Eigen::VectorXd::Zero(nq - nd);
    body.add_quasistatic_loads(y.data(), Eigen::Vector3d(0.0, -9.81, 0.0), loads);  // gravity: a free body's frame balances it
    INFO(nd << " integrated modes, w = " << w.transpose());
    // the same sums in another order: their round-off, a few eps of the summed terms' magnitudes
    // (about 70 terms a row: 1e-13 leaves a margin of five)
    const double scale = magnitude.maxCoeff();
    CHECK((loads - expected.tail(nq - nd)).cwiseAbs().maxCoeff() <= 1e-13 * scale);
    CHECK(loads.norm() > 1e3 * 1e-13 * scale);  // the loads themselves are far above that
  }
}

TEST_CASE("FloatingBody: the rotation loads on the quasistatic modes leave out only terms that could not move a point by a rounding of its position",
          "[runtime][unit]") {
  // The quasistatic modes' response to the loads, z = Ke_hh^-1 f_h, moves every node, contact
  // point and control point by less than the bound, at spins from 1e-12 to 1e2 rad/s; where the
  // bound lies below the resolution the loads are not formed, elsewhere they are the SID's but
  // for terms whose response together stays below it.
  const format::Sid sid = format::read_sid(std::string(ISOSID_GOLDEN_DIR) + "/beam_small.sid.h5");
  const Eigen::Index nq = sid.nq();
  run::BodySpec spec;
  spec.name = "beam";
  spec.high_modes = "quasistatic";
  spec.quasistatic_above_hz = 2000.0;  // 2 integrated modes
  const run::FloatingBody body(spec, sid, run::Dimension::Solid);
  const Eigen::Index nd = body.n_dynamic(), nh = nq - nd;
  REQUIRE(nh > 0);
  REQUIRE(body.position_resolution() > 0);
  Eigen::VectorXd y = Eigen::VectorXd::Zero(body.state_size());
  body.initial_state(y.data());
  y.segment(7, nd) = Eigen::VectorXd::LinSpaced(nd, 1e-4, 3e-4);
  y.segment(13 + nd, nd) = Eigen::VectorXd::LinSpaced(nd, -0.2, 0.1);
  body.quasistatic_modes() = Eigen::VectorXd::LinSpaced(nh, -2e-4, 5e-4);
  // the largest displacement of a point the SID knows for held coordinates z
  auto largest_displacement = [&](const Eigen::VectorXd& z) {
    double most = 0;
    auto rows = [&](const Eigen::MatrixXd& modes, Eigen::Index dim) {
      for (Eigen::Index r = 0; r + dim <= modes.rows(); r += dim) most = std::max(most, (modes.block(r, nd, dim, nh) * z).norm());
    };
    for (const auto& node : sid.nodes) rows(node.phi, 3);
    for (const auto& c : sid.contact_surfaces) rows(c.Psi, c.position.cols());
    for (const auto& m : sid.master_patches) rows(m.Phi, m.control_points.cols());
    return most;
  };
  int skipped = 0, formed = 0, partial = 0;
  for (double spin = 1e-12; spin < 1e3; spin *= 10) {
    const Eigen::Vector3d w = spin * Eigen::Vector3d(0.3, -0.5, 0.8).normalized();
    y.segment<3>(10 + nd) = w;
    const Eigen::VectorXd q = body.q(y.data()), qdot = body.qdot(y.data());
    Eigen::Matrix<double, 6, 1> w2;
    w2 << w.x() * w.x(), w.y() * w.y(), w.z() * w.z(), w.x() * w.y(), w.y() * w.z(), w.z() * w.x();
    Eigen::VectorXd expected = -sid.Oe.at(q) * w2;
    for (Eigen::Index j = 0; j < nq; ++j) expected -= qdot(j) * (sid.Ge.M0.middleCols(3 * j, 3) * w);
    const Eigen::VectorXd z = sid.Ke.M0.bottomRightCorner(nh, nh).ldlt().solve(expected.tail(nh));
    const double bound = body.rotation_response_bound(q, qdot, w);
    INFO("spin " << spin << " rad/s: bound " << bound << " m, displacement " << largest_displacement(z) << " m");
    CHECK(largest_displacement(z) <= bound);
    Eigen::VectorXd loads = Eigen::VectorXd::Zero(nh);
    const bool added = body.add_uncoupled_quasistatic_loads(y.data(), Eigen::Vector3d::Zero(), loads);
    CHECK(added == (bound > body.position_resolution()));
    if (added) {
      ++formed;
      // the terms left out (the smallest, while together below the resolution) move no point
      // by more than the resolution; the sums' round-off comes on top (1e-12 of the loads')
      const Eigen::VectorXd left_out = loads - expected.tail(nh);
      const double roundoff = 1e-12 * largest_displacement(sid.Ke.M0.bottomRightCorner(nh, nh).ldlt().solve(expected.tail(nh)));
      CHECK(largest_displacement(sid.Ke.M0.bottomRightCorner(nh, nh).ldlt().solve(left_out)) <= body.position_resolution() + roundoff);
      partial += left_out.norm() > 1e-12 * expected.tail(nh).norm();
    } else {
      ++skipped;
      CHECK(loads.isZero(0.0));
    }
  }
  CHECK(skipped > 0);
  CHECK(formed > 0);
  CHECK(partial > 0);  // spins whose first-order term alone was left out
}

TEST_CASE("ModalMatrix: products and quadratic forms equal the dense matrix's, diagonal, block and coupled alike", "[runtime][unit]") {
  // Three forms of the SID's Ke: diagonal (a modal SID), diagonal modes beside a dense
  // interface block (Craig-Bampton: the modes' rows hold only round-off besides their
  // diagonal), and modes coupled to the block (MacNeal). Round-off (here 1e-15 of the largest
  // entry, far below 1e-8 of sqrt(M_ii M_jj)) is dropped, so the reference is the matrix
  // without it; the sums then differ only in their order (1e-14 of the terms' magnitude).
  const Eigen::Index n = 12, modes = 5;
  Eigen::MatrixXd dense = Eigen::MatrixXd::Random(n - modes, n - modes);
  dense = dense * dense.transpose() + Eigen::MatrixXd::Identity(n - modes, n - modes);
  Eigen::MatrixXd block = Eigen::MatrixXd::Zero(n, n);
  block.diagonal().head(modes) = Eigen::VectorXd::LinSpaced(modes, 1.0, 9.0);
  block.bottomRightCorner(n - modes, n - modes) = dense;
  Eigen::MatrixXd diagonal = Eigen::MatrixXd(Eigen::VectorXd::LinSpaced(n, 1.0, 12.0).asDiagonal());
  Eigen::MatrixXd coupled = block;
  coupled.block(0, modes, modes, n - modes).setConstant(0.3);
  coupled.block(modes, 0, n - modes, modes).setConstant(0.3);
  struct Case {
    const char* name;
    Eigen::MatrixXd exact;
    bool diagonal;
  };
  for (const Case& c : {Case{"diagonal", diagonal, true}, Case{"modes beside a block", block, false}, Case{"coupled", coupled, false}}) {
    Eigen::MatrixXd with_roundoff = c.exact;
    with_roundoff(0, n - 1) = with_roundoff(n - 1, 0) += 1e-15 * c.exact.cwiseAbs().maxCoeff();  // dropped in the first two forms
    const run::ModalMatrix M(with_roundoff);
    INFO(c.name);
    CHECK(M.is_diagonal() == c.diagonal);
    const Eigen::MatrixXd& reference = c.name == std::string("coupled") ? with_roundoff : c.exact;
    const double scale = reference.cwiseAbs().maxCoeff();
    for (const Eigen::VectorXd& x : {Eigen::VectorXd(Eigen::VectorXd::LinSpaced(n, -1.0, 2.0)),
                                     Eigen::VectorXd((Eigen::VectorXd(n) << Eigen::VectorXd::LinSpaced(modes, 1.0, 2.0),
                                                      Eigen::VectorXd::Zero(n - modes)).finished())}) {
      CHECK(std::abs(M.quadratic_form(x) - x.dot(reference * x)) <= 1e-14 * scale * x.squaredNorm() * n);
      for (Eigen::Index rows : {Eigen::Index(0), modes, n - 2, n}) {
        Eigen::VectorXd out = Eigen::VectorXd::Ones(rows);
        M.subtract_product(x, out);
        const Eigen::VectorXd expected = Eigen::VectorXd::Ones(rows) - reference.topRows(rows) * x;
        CHECK((out - expected).norm() <= 1e-14 * scale * x.cwiseAbs().sum());  // rows may be 0
      }
    }
  }
}

TEST_CASE("CondensedEnergy: the condensed form is the dense energy, in contact and while the held coordinates follow", "[runtime][unit]") {
  // K of a MacNeal SID's shape: d integrated modes coupled densely to h held coordinates, all
  // positive definite. For any q the split form equals 1/2 q^T K q to the sums' round-off; where
  // the held coordinates follow the modes statically (q_h = -K_hh^-1 K_hd q_d, up to a rounding
  // of q_h) the skipped h x h form would add less than 1e-15 of the energy.
  const Eigen::Index d = 6, h = 30, n = d + h;
  Eigen::MatrixXd A = Eigen::MatrixXd::Random(n, n);
  const Eigen::MatrixXd K = A * A.transpose() + double(n) * Eigen::MatrixXd::Identity(n, n);
  const auto split = run::CondensedEnergy::of(K, d);
  REQUIRE(split);
  const double scale = K.cwiseAbs().maxCoeff();
  const Eigen::VectorXd loaded = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
  CHECK(std::abs((*split)(loaded) - 0.5 * loaded.dot(K * loaded)) <= 1e-14 * scale * loaded.squaredNorm() * double(n));
  Eigen::VectorXd following(n);
  following.head(d) = Eigen::VectorXd::LinSpaced(d, 1.0, 2.0);
  following.tail(h) = -K.bottomRightCorner(h, h).llt().solve(K.bottomLeftCorner(h, d) * following.head(d));
  following.tail(h) *= 1.0 + 1e-16;  // the static solve's rounding: r is round-off, its form is skipped
  const double dense = 0.5 * following.dot(K * following);
  CHECK(std::abs((*split)(following) - dense) <= 1e-13 * std::abs(dense));
  // no split without held or integrated coordinates, without coupling, or with a held block
  // that is not positive definite
  CHECK_FALSE(run::CondensedEnergy::of(K, 0));
  CHECK_FALSE(run::CondensedEnergy::of(K, n));
  Eigen::MatrixXd uncoupled = K;
  uncoupled.bottomLeftCorner(h, d).setZero();
  uncoupled.topRightCorner(d, h).setZero();
  CHECK_FALSE(run::CondensedEnergy::of(uncoupled, d));
  Eigen::MatrixXd indefinite = K;
  indefinite(n - 1, n - 1) = -1.0;
  CHECK_FALSE(run::CondensedEnergy::of(indefinite, d));
}

TEST_CASE("FloatingBody: the kinetic energy is the SID's mass matrix form over all coordinates", "[runtime][unit]") {
  // T = 1/2 [v; w; qdot]^T M(q) [v; w; qdot] with M's Taylor terms summed over all coordinates
  // (quasistatic ones set too); the body forms it from the rows with velocities and the
  // coefficients with inertia alone. Same sums in another order: 1e-13 of T.
  const format::Sid sid = format::read_sid(std::string(ISOSID_GOLDEN_DIR) + "/beam_small.sid.h5");
  REQUIRE(sid.Cr.order() == 1);  // and J and mdCM: first-order terms the coordinates move
  for (double split_hz : {0.0, 2000.0}) {  // every mode integrated, or two (the rest quasistatic)
    run::BodySpec spec;
    spec.name = "beam";
    if (split_hz > 0) spec.high_modes = "quasistatic", spec.quasistatic_above_hz = split_hz;
    const run::FloatingBody body(spec, sid, run::Dimension::Solid);
    const Eigen::Index nd = body.n_dynamic(), nq = sid.nq();
    Eigen::VectorXd y = Eigen::VectorXd::Zero(body.state_size());
    body.initial_state(y.data());
    const Eigen::Quaterniond p = Eigen::Quaterniond(0.9, 0.1, -0.3, 0.2).normalized();
    y(3) = p.w(), y(4) = p.x(), y(5) = p.y(), y(6) = p.z();
    y.segment(7, nd) = Eigen::VectorXd::LinSpaced(nd, 1e-4, 3e-4);
    y.segment<3>(7 + nd) = Eigen::Vector3d(0.4, -1.1, 0.2);
    y.segment<3>(10 + nd) = Eigen::Vector3d(3.0, -20.0, 7.0);
    y.segment(13 + nd, nd) = Eigen::VectorXd::LinSpaced(nd, -0.2, 0.1);
    if (nq > nd) body.quasistatic_modes() = Eigen::VectorXd::LinSpaced(nq - nd, -2e-4, 5e-4);
    const Eigen::VectorXd q = body.q(y.data()), qdot = body.qdot(y.data());
    const Eigen::Vector3d vK = p.toRotationMatrix().transpose() * y.segment<3>(7 + nd), w = y.segment<3>(10 + nd);
    const Eigen::Vector3d mc = sid.mdCM.at(q);
    const double expected = 0.5 * sid.refmod.mass * vK.squaredNorm() + 0.5 * w.dot(sid.J.at(q) * w) +
                            0.5 * qdot.dot(sid.Me.M0 * qdot) + vK.dot(format::skew(mc).transpose() * w) +
                            vK.dot(sid.Ct.at(q).transpose() * qdot) + w.dot(sid.Cr.at(q).transpose() * qdot);
    INFO(nd << " integrated modes of " << nq);
    CHECK(std::abs(body.kinetic_energy(y.data()) - expected) <= 1e-13 * expected);
  }
}

TEST_CASE("Simulation: an interrupt the observer asks for ends the run at that step, sampled there", "[runtime][unit][signals]") {
  // one output interval for the whole flight: without the step's interrupt the integrator
  // would return only at the end
  run::Scene scene = free_flight_scene(0.02);
  scene.simulation.output_interval = 0.02;
  scene.simulation.max_step = 1e-5;
  run::BodySpec beam;
  beam.name = "beam";
  beam.velocity = {1, 0, 0};
  scene.bodies.push_back(beam);
  run::Simulation simulation(scene, {format::read_sid(std::string(ISOSID_GOLDEN_DIR) + "/beam_small.sid.h5")});
  struct Interrupting : CountingObserver {
    bool interrupt_requested() const override { return steps >= 10; }
  } observer;
  const run::RunOutcome outcome = simulation.run(observer);
  CHECK(outcome.status == "interrupted");
  CHECK(observer.steps == 10);
  CHECK(simulation.time() > 0);
  CHECK(simulation.time() < 1e-3);
  CHECK(observer.last_sample == simulation.time());  // the results end where the run stopped
}

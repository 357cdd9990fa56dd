// Impact detection against known answers: a sphere flying rigidly toward a plane touches it
// when its distance has closed, at the point of the sphere facing the plane. The run must find
// that instant (to 1e-9 s) and the point's parameter on the sphere's NURBS surface (to 1e-9 of
// the parameter range), for a level and a tilted plane.
#include "body/floating_body.hpp"
#include "contact/deformed_patch.hpp"
#include "contact/surface_touch.hpp"
#include "isosid/format/sid_io.hpp"
#include "scene/scene.hpp"
#include "solve/multibody_system.hpp"
#include "solve/simulation.hpp"
#include "support/flexible_sphere_pair.hpp"
#include "support/impact_scene.hpp"
#include "support/scene_text.hpp"
#include "support/run_program.hpp"

#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

using namespace isosid;

namespace {
struct TouchObserver : run::SimulationObserver {
  std::vector<std::pair<double, run::Touch>> touches;
  void sample(double, const double*) override {}
  void step(double, const double*) override {}
  void contact_event(int, bool, double) override {}
  void touch(int, double t, const run::Touch& touch) override { touches.emplace_back(t, touch); }
};
}  // namespace

namespace {
/// Runs `sid` (a body of radius R about its origin, facing the plane through the origin whose
/// unit normal n leans in the section's plane) flying straight down from clearance + R along n,
/// and checks its single touch against the closed form.
void check_first_touch(const test::ScratchDir& dir, const std::string& dimension, const std::string& sid_file, double R,
                       const Eigen::Vector3d& n) {
  const double v = 0.1, clearance = 1e-6;  // m/s, m
  const Eigen::Vector3d centre = (R + clearance) * n;
  std::ofstream scene_file(dir.path("s.scene.toml"));
  scene_file << std::setprecision(17);  // the closed form below holds for the numbers as written
  scene_file << "[simulation]\ndimension = \"" << dimension << "\"\nend_time = 2e-5\noutput_interval = 1e-6\n"
                                          << "[[flexible_body]]\nname = \"body\"\nsid = \"" << sid_file << "\"\nposition = ["
                                          << centre.x() << ", " << centre.y() << ", 0.0]\nvelocity = [0.0, " << -v << ", 0.0]\n"
                                          << "[[fixed_plane]]\nname = \"ground\"\npoint = [0.0, 0.0, 0.0]\nnormal = [" << n.x() << ", "
                                          << n.y() << ", 0.0]\n[[contact]]\nname = \"c\"\nbody = \"body\"\nsurface = \"contact\"\n"
                                          << "target = \"ground\"\npenalty = 1e15\n";
  scene_file.close();
  const run::Scene scene = run::read_scene_file(dir.path("s.scene.toml"));
  const format::Sid sid = format::read_sid(scene.bodies[0].sid_file);
  run::Simulation simulation(scene, {sid});
  TouchObserver observer;
  REQUIRE(simulation.run(observer).completed());
  REQUIRE(observer.touches.size() == 1);
  const auto& [time, touch] = observer.touches.front();

  // before the touch no force acts: the distance to the plane closes at v n_y
  const double expected_time = clearance / (v * n.y());
  INFO(dimension << ", normal (" << n.x() << ", " << n.y() << "): touch at " << time << " s, expected " << expected_time << " s");
  CHECK(std::abs(time - expected_time) < 1e-9);
  CHECK(std::abs(touch.gap) < 1e-12);  // the root of the gap, located by the integrator
  // the world point is the body's point facing the plane: the centre then, less R n
  const Eigen::Vector3d centre_then = centre + Eigen::Vector3d(0.0, -v * expected_time, 0.0);
  CHECK((touch.point - (centre_then - R * n)).norm() < 1e-9 * R);

  // the parameter, independently: where the undeformed patch's tangent is normal to n (bisection),
  // or the end of the patch that lies on the axis when n is the axis
  const format::MasterPatch& patch = *format::find_master_patch(sid, sid.contact_surfaces.front().master_patch);
  run::DeformedPatch curve(patch, 2);
  run::DeformedPatch::Point p;
  auto facing = [&](double u) {  // n . dC/du: zero where the surface faces the plane
    curve.evaluate(Eigen::Vector2d(u, 0.0), p);
    return n.dot(p.dC[0]);
  };
  double lo = curve.lower(0), hi = curve.upper(0);
  const double range = hi - lo;
  double expected_parameter = 0;
  curve.evaluate(Eigen::Vector2d(lo, 0.0), p);
  if (dimension == "axisymmetric") {
    expected_parameter = std::abs(p.C.x()) < 1e-12 ? lo : hi;
  } else {
    REQUIRE(facing(lo) * facing(hi) < 0);  // the facing point lies on the patch
    for (int i = 0; i < 200 && hi - lo > 1e-15 * range; ++i) {
      const double mid = 0.5 * (lo + hi);
      (facing(lo) * facing(mid) <= 0 ? hi : lo) = mid;
    }
    expected_parameter = 0.5 * (lo + hi);
  }
  CHECK(touch.parameter_dim == 1);
  CHECK(std::abs(touch.slave_parameter(0) - expected_parameter) < 1e-9 * range);
  CHECK(std::isnan(touch.target_parameter(0)));  // a plane has no parameters
}
}  // namespace

TEST_CASE("impact detection: a sphere's first touch of a plane, at its pole", "[runtime][unit]") {
  const test::ScratchDir dir("touch_sphere");
  check_first_touch(dir, "axisymmetric", std::string(ISOSID_GOLDEN_DIR) + "/sphere_small.sid.h5", 0.01, Eigen::Vector3d::UnitY());
}

TEST_CASE("impact detection: a disk's first touch of a tilted plane, off its patch's ends", "[runtime][unit]") {
  const test::ScratchDir dir("touch_disk");
  // a coarse plane-strain disk of radius 0.05 m, contact on the middle of its bottom side
  std::ofstream(dir.path("disk.model.toml")) << "[body]\nname = \"disk\"\nanalysis = \"plane_strain\"\nthickness = 1.0\n"
                                             << "[material]\nyoungs_modulus = 2.1e11\npoisson_ratio = 0.3\ndensity = 7850.0\n"
                                             << "[geometry]\nprimitive = \"disk\"\nradius = 0.05\n"
                                             << "[refinement]\ndegrees = [2, 2]\nsubdivisions = [2, 2]\n"
                                             << "[[contact_surface]]\nname = \"contact\"\nside = \"bottom\"\ninterval = [[0.2, 0.8]]\n"
                                             << "[reduction]\nmethod = \"modal\"\nnormal_modes = 4\n";
  const test::ProgramResult prep =
      test::run_program(std::string(ISOSID_PREP_EXE) + " -q " + dir.path("disk.model.toml") + " -o " + dir.path("disk.sid.h5"));
  INFO(prep.err);
  REQUIRE(prep.exit_status == 0);
  const double tilt = 0.15;  // rad: the facing point 7.5 mm from the bottom, inside the contact patch
  check_first_touch(dir, "planar", dir.path("disk.sid.h5"), 0.05, Eigen::Vector3d(std::sin(tilt), std::cos(tilt), 0.0));
}

TEST_CASE("impact detection: a bouncing sphere's surfaces touch once per impact", "[runtime][unit]") {
  // strong gravity brings the sphere back within 0.4 ms: three impacts, each found where its
  // Gauss points start to carry load (the touch rearms once the contact has opened)
  const test::ScratchDir dir("touch_bounce");
  std::ofstream(dir.path("s.scene.toml")) << "[simulation]\ndimension = \"axisymmetric\"\nend_time = 4e-4\noutput_interval = 1e-6\n"
                                          << "gravity = [0.0, -2000.0, 0.0]\n[[flexible_body]]\nname = \"sphere\"\nsid = \""
                                          << ISOSID_GOLDEN_DIR << "/sphere_small.sid.h5\"\nposition = [0.0, 0.0100001, 0.0]\n"
                                          << "velocity = [0.0, -0.1, 0.0]\nhigh_modes = \"quasistatic\"\n[[fixed_plane]]\nname = \"ground\"\n"
                                          << "[[contact]]\nname = \"c\"\nbody = \"sphere\"\nsurface = \"contact\"\ntarget = \"ground\"\n"
                                          << "penalty = 5e17\n";
  const run::Scene scene = run::read_scene_file(dir.path("s.scene.toml"));
  run::Simulation simulation(scene, {format::read_sid(scene.bodies[0].sid_file)});
  struct Observer : TouchObserver {
    std::vector<double> onsets;
    bool open = true;
    void contact_event(int, bool closing, double t) override {
      if (closing && open) onsets.push_back(t);
      open = !closing;
    }
  } observer;
  REQUIRE(simulation.run(observer).completed());
  REQUIRE(observer.touches.size() == 3);
  REQUIRE(observer.onsets.size() >= 3);
  // the first: 0.1 um closed at 0.1 m/s under 2000 m/s^2
  CHECK(std::abs(observer.touches[0].first - (-0.1 + std::sqrt(0.01 + 4 * 1000 * 1e-7)) / 2000) < 1e-9);
  for (const auto& [time, touch] : observer.touches) {
    // each touch comes first, the Gauss points' onset of the same impact after it (within 2 us)
    const auto onset = std::lower_bound(observer.onsets.begin(), observer.onsets.end(), time);
    REQUIRE(onset != observer.onsets.end());
    CHECK(*onset - time < 2e-6);
    CHECK(std::abs(touch.gap) < 1e-12);
  }
}

TEST_CASE("impact detection: two flexible spheres touch at their poles, found on both patches", "[runtime][unit]") {
  // 0.2 um apart, closing at 0.2 m/s: the touch at 1 us, at each sphere's pole (the end of its
  // patch on the axis), the target's parameter from the projection onto its deformed patch
  const test::ScratchDir dir("touch_pair");
  std::ofstream(dir.path("s.scene.toml")) << "[simulation]\ndimension = \"axisymmetric\"\nend_time = 3e-6\noutput_interval = 1e-6\n"
                                          << test::flexible_sphere_pair("0.1");
  const run::Scene scene = run::read_scene_file(dir.path("s.scene.toml"));
  const format::Sid sid = format::read_sid(scene.bodies[0].sid_file);
  run::Simulation simulation(scene, {sid, sid});
  TouchObserver observer;
  REQUIRE(simulation.run(observer).completed());
  REQUIRE(observer.touches.size() == 1);
  const auto& [time, touch] = observer.touches.front();
  CHECK(std::abs(time - 1e-6) < 1e-9);
  CHECK(touch.point.norm() < 1e-9 * 0.01);  // the poles meet at the origin
  run::DeformedPatch curve(*format::find_master_patch(sid, sid.contact_surfaces.front().master_patch), 2);
  run::DeformedPatch::Point p;
  curve.evaluate(Eigen::Vector2d(curve.lower(0), 0.0), p);
  const double pole = std::abs(p.C.x()) < 1e-12 ? curve.lower(0) : curve.upper(0), range = curve.upper(0) - curve.lower(0);
  CHECK(std::abs(touch.slave_parameter(0) - pole) < 1e-9 * range);
  CHECK(std::abs(touch.target_parameter(0) - pole) < 1e-9 * range);
}

TEST_CASE("impact detection: the bounding spheres' clearance bounds the closest approach from below", "[runtime][unit]") {
  // Two flexible spheres apart by 0.2 um to 40 mm: the root functions take the clearance for
  // the exact search where it is positive, which holds only as a lower bound of the gap
  const test::ScratchDir dir("touch_clearance");
  std::ofstream(dir.path("s.scene.toml")) << "[simulation]\ndimension = \"axisymmetric\"\nend_time = 1e-6\n" << test::flexible_sphere_pair("0.0");
  const run::Scene scene = run::read_scene_file(dir.path("s.scene.toml"));
  const format::Sid sid = format::read_sid(scene.bodies[0].sid_file);
  const run::MultibodySystem system(scene, {sid, sid});
  const run::SurfaceTouch touch(system.contacts().front());
  REQUIRE(touch.available());
  Eigen::VectorXd y(system.size());
  system.initial_state(y.data());
  const Eigen::Index upper = system.bodies()[0]->offset() + 1;
  int positive = 0;
  for (double lift : {0.0, 1e-6, 1e-4, 1e-3, 1e-2, 2e-2, 4e-2}) {
    Eigen::VectorXd state = y;
    state(upper) += lift;
    const double bound = touch.clearance(state.data()), gap = touch.evaluate(state.data()).gap;
    INFO("lift " << lift << " m: clearance " << bound << " m, gap " << gap << " m");
    CHECK(bound <= gap);  // infinite where the target sees none of the surface (far apart)
    if (std::isfinite(gap)) CHECK(std::abs(gap - (2e-7 + lift)) < 1e-9);  // the poles face each other
    positive += bound > 0;
  }
  CHECK(positive >= 2);  // apart by more than their patches' bounding spheres (12.5 mm here): cleared
}

namespace {
/// Scene E's coarse ball (models/pendulum_ball.model.toml, spherical coordinates), built here.
format::Sid scene_e_coarse_ball(const test::ScratchDir& dir) {
  const test::ProgramResult prep =
      test::run_program(std::string(ISOSID_PREP_EXE) + " -q --coarse " + ISOSID_MODELS_DIR + "/pendulum_ball.model.toml -o " + dir.path("ball.sid.h5"));
  INFO(prep.err);
  REQUIRE(prep.exit_status == 0);
  return format::read_sid(dir.path("ball.sid.h5"));
}

/// The scene's x-y-z angles of Rz(phi) R0, where R0 turns that ball's poles (model y) to z and
/// its longitude 90 deg to +x: its equator's point at longitude 90 deg + phi faces +x.
std::string ball_turned_by(double phi) {
  const Eigen::Matrix3d A = Eigen::AngleAxisd(phi, Eigen::Vector3d::UnitZ()) * (Eigen::Matrix3d() << 0, 0, 1, 1, 0, 0, 0, 1, 0).finished();
  const Eigen::Vector3d angles = run::tait_bryan_angles(A);
  std::ostringstream s;
  s << std::setprecision(17) << "[" << angles(0) << ", " << angles(1) << ", " << angles(2) << "]";
  return s.str();
}
}  // namespace

TEST_CASE("impact detection: balls touch wherever on the bands round their equators they meet", "[runtime][unit]") {
  // two of scene E's coarse balls (spherical coordinates), their contact surfaces bands of
  // +-18 deg round the equator but the hinge, turned so that the equator points at longitudes lon_l and
  // lon_r face each other; 0.2 um apart, closing at 0.2 m/s: the touch at 1 us at the origin,
  // on both equators. The search's start grid must find it far from the side's grid points:
  // a 9 x 9 grid over the whole side had its points 45 deg apart along the equator, and at
  // 22.5 deg from the line of centres a point lies 1.4 mm from the other ball, beyond the
  // bounding sphere of its net (scene E's balls passed 56 um into each other unseen so)
  const test::ScratchDir dir("touch_band");
  const double R = 0.01, deg = M_PI / 180;
  const format::Sid sid = scene_e_coarse_ball(dir);
  for (const auto& [lon_l, lon_r] : std::vector<std::pair<double, double>>{{119.04, 179.75}, {157.5, 67.5}, {202.5, 292.5}, {40, 300}, {330, 60}}) {
    std::ofstream(dir.path("s.scene.toml")) << std::setprecision(17) << "[simulation]\ndimension = \"3d\"\nend_time = 3e-6\noutput_interval = 1e-6\n"
                                            << "[[flexible_body]]\nname = \"left\"\nsid = \"ball.sid.h5\"\nposition = [" << -(R + 1e-7)
                                            << ", 0.0, 0.0]\norientation = " << ball_turned_by((lon_l - 90) * deg) << "\nvelocity = [0.1, 0.0, 0.0]\nhigh_modes = \"quasistatic\"\n"
                                            << "[[flexible_body]]\nname = \"right\"\nsid = \"ball.sid.h5\"\nposition = [" << R + 1e-7
                                            << ", 0.0, 0.0]\norientation = " << ball_turned_by((lon_r + 90) * deg) << "\nvelocity = [-0.1, 0.0, 0.0]\nhigh_modes = \"quasistatic\"\n"
                                            << "[[contact]]\nname = \"balls\"\nbody = \"left\"\nsurface = \"contact\"\ntarget = \"right\"\n"
                                            << "target_surface = \"contact\"\npenalty = 1e17\n";
    const run::Scene scene = run::read_scene_file(dir.path("s.scene.toml"));
    run::Simulation simulation(scene, {sid, sid});
    TouchObserver observer;
    INFO("longitudes " << lon_l << " and " << lon_r << " deg");
    REQUIRE(simulation.run(observer).completed());
    REQUIRE(observer.touches.size() == 1);
    const auto& [time, touch] = observer.touches.front();
    CHECK(std::abs(time - 1e-6) < 1e-9);
    CHECK(touch.point.norm() < 1e-9 * R);
    // the parameters name the facing points: the left ball's surface there is its point at
    // lon_l on the equator (body frame), and the right's at lon_r
    run::DeformedPatch patch(*format::find_master_patch(sid, sid.contact_surfaces.front().master_patch), 3);
    run::DeformedPatch::Point p;
    for (const auto& [u, lon] : {std::pair{touch.slave_parameter, lon_l}, std::pair{touch.target_parameter, lon_r}}) {
      patch.evaluate(u, p);
      CHECK((p.C - R * Eigen::Vector3d(std::cos(lon * deg), 0, std::sin(lon * deg))).norm() < 1e-9 * R);
    }
  }
}

TEST_CASE("impact detection: a spinning ball's closest approach crosses the seam of its longitudes", "[runtime][unit]") {
  // scene E's coarse ball on the left spins about its poles (the hinge axis z) so that its
  // point facing the other ball runs from longitude 20 deg down across the seam at 0 (the
  // hinge's, outside its band) to 340 deg, where they touch: 2 mm apart, closing at 0.2 m/s,
  // the touch at 10 ms. Tracked from the last call, the closest approach stops on the search's
  // bound at the seam, where the gap still falls beyond it; the grid must find it again.
  const test::ScratchDir dir("touch_seam");
  const format::Sid sid = scene_e_coarse_ball(dir);
  const double R = 0.01, deg = M_PI / 180, t_touch = 0.01;
  // the facing longitude is 90 deg + phi: phi0 = -70 deg and omega = -40 deg / t_touch
  std::ofstream(dir.path("s.scene.toml")) << std::setprecision(17) << "[simulation]\ndimension = \"3d\"\nend_time = " << 1.02 * t_touch
                                          << "\noutput_interval = 1e-4\n[[flexible_body]]\nname = \"left\"\nsid = \"ball.sid.h5\"\nposition = ["
                                          << -(R + 1e-3) << ", 0.0, 0.0]\norientation = " << ball_turned_by(-70 * deg)
                                          << "\nvelocity = [0.1, 0.0, 0.0]\nangular_velocity = [0.0, " << -40 * deg / t_touch
                                          << ", 0.0]\nhigh_modes = \"quasistatic\"\n[[flexible_body]]\nname = \"right\"\nsid = \"ball.sid.h5\"\n"
                                          << "position = [" << R + 1e-3 << ", 0.0, 0.0]\norientation = " << ball_turned_by(120 * deg)
                                          << "\nvelocity = [-0.1, 0.0, 0.0]\nhigh_modes = \"quasistatic\"\n"
                                          << "[[contact]]\nname = \"balls\"\nbody = \"left\"\nsurface = \"contact\"\ntarget = \"right\"\n"
                                          << "target_surface = \"contact\"\npenalty = 1e17\n";
  const run::Scene scene = run::read_scene_file(dir.path("s.scene.toml"));
  run::Simulation simulation(scene, {sid, sid});
  TouchObserver observer;
  REQUIRE(simulation.run(observer).completed());
  REQUIRE(observer.touches.size() == 1);
  const auto& [time, touch] = observer.touches.front();
  // the spin stretches each ball by about rho omega^2 R^3 / E = 2e-10 m: the touch comes
  // within 2e-9 s of the rigid balls' closing time
  CHECK(std::abs(time - t_touch) < 1e-8);
  run::DeformedPatch patch(*format::find_master_patch(sid, sid.contact_surfaces.front().master_patch), 3);
  run::DeformedPatch::Point p;
  patch.evaluate(touch.slave_parameter, p);
  CHECK((p.C - R * Eigen::Vector3d(std::cos(340 * deg), 0, std::sin(340 * deg))).norm() < 1e-6 * R);  // the spin's round-off in angle
}

TEST_CASE("impact detection: an interrupt in the step where a contact closes still reports the closing", "[runtime][unit][signals]") {
  // the observer stops the run at the first accepted step that ends with a closed gap: the
  // integrator's root search for that step never runs, so the run itself must compare the
  // gaps it stopped at with what it last reported
  const test::ScratchDir dir("touch_interrupt");
  // the golden sphere's impact with one output interval for the whole run: only the step's
  // interrupt can end it early
  std::ofstream(dir.path("s.scene.toml")) << test::replace(test::golden_impact_scene(std::string(ISOSID_GOLDEN_DIR) + "/sphere_small.sid.h5"),
                                                           "output_interval = 1e-6", "output_interval = 1e-4");
  const run::Scene scene = run::read_scene_file(dir.path("s.scene.toml"));
  run::Simulation simulation(scene, {format::read_sid(scene.bodies[0].sid_file)});
  struct Observer : TouchObserver {
    const run::MultibodySystem* system = nullptr;
    bool gap_closed = false;
    std::vector<std::pair<bool, double>> events;
    void step(double, const double* y) override {
      double gap = 0;
      system->gaps(y, &gap);
      gap_closed = gap_closed || gap < 0;
    }
    bool interrupt_requested() const override { return gap_closed; }
    void contact_event(int, bool closing, double t) override { events.emplace_back(closing, t); }
  } observer;
  observer.system = &simulation.system();
  const run::RunOutcome outcome = simulation.run(observer);
  REQUIRE(outcome.status == "interrupted");
  REQUIRE(observer.events.size() == 1);
  CHECK(observer.events[0].first);                        // closing
  CHECK(observer.events[0].second == simulation.time());  // at the end of the step it was found in
  // 0.1 um closed at 0.1 m/s: the gap closes at 1 us, and the step that found it ends soon after
  CHECK(simulation.time() >= 1e-6 * (1 - 1e-9));
  CHECK(simulation.time() < 1e-5);
}

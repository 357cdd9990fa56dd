// Massless boundaries ([R3], [R4] in docs/references.md) through isosid-prep and isosid-run: the
// exact bouncing bar (H), whose contact lives on the massless boundary coordinates, with penalty
// and exact contact; the leapfrog's energy over a million steps; scenes that ask for the
// impossible.
#include "isosid/format/hdf5_file.hpp"
#include "isosid/format/sid_io.hpp"
#include "scene_runner.hpp"
#include "support/one_line_exit.hpp"

#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

using namespace isosid;
using nlohmann::json;
using test::rel_error;
using test::replace;

namespace {
/// Largest |E(t) - E(0)| / E(0) over the samples of results.h5 in [from, to) (fractions of the run).
double energy_error(const format::h5::Reader& results, double from, double to) {
  const Eigen::VectorXd E = results.vector("/energy/total");
  double worst = 0;
  for (Eigen::Index i = Eigen::Index(from * double(E.size())); i < Eigen::Index(to * double(E.size())); ++i)
    worst = std::max(worst, std::abs(E(i) - E(0)) / E(0));
  return worst;
}
}  // namespace

TEST_CASE("bar dropped flat on a wall with a massless boundary: duration 2L/c, rebound v0, force plateau", "[runtime][massless]") {
  const test::ScratchDir dir("bar-drop");
  const json s = test::run_seed_scene(dir, "bar_drop.scene.toml", "bar_drop_macneal.model.toml");
  // exact: 2 L / c and v0 (measured -0.33 % and -0.06 % with 30 modes; the acceptance's 0.5 %)
  CHECK(rel_error(s, "contact_time_s") < 0.005);
  CHECK(rel_error(s, "rebound_velocity_m_s") < 0.005);
  // the semi-discrete system is conservative (no damping, frictionless): only the integrator's
  // error remains (measured 1.1e-6 at rtol 1e-6)
  CHECK(s["energy"]["max_rel_error"].get<double>() < 1e-5);
  // the top reverses when the wave reaches it, at L / c (measured -0.3 %)
  const double c = std::sqrt(2.1e11 / 7800.0), L = 0.1;
  CHECK(s["monitors"][0]["reversal_s"].get<double>() == Approx(L / c).epsilon(0.01));

  // the cost split (bench/cost_model.py): every right-hand side is timed, its parts add up to
  // less than the run, and the massless boundary is solved statically in each one
  CHECK(s["rhs_cost"]["evaluations"].get<long>() == s["rhs_evaluations"].get<long>());
  CHECK(s["rhs_cost"]["mean_active_points"].get<double>() > 0);
  double parts = 0;
  for (const auto& [part, seconds] : s["time_split_s"].items()) {
    CHECK(seconds.get<double>() >= 0);
    parts += seconds.get<double>();
  }
  CHECK(parts <= s["wall_time_s"].get<double>());
  CHECK(s["time_split_s"]["static_solve"].get<double>() > 0);

  // the SID: the boundary carries no mass, and the contact points move with it alone
  const format::Sid sid = format::read_sid(dir.path("bar_drop_macneal.sid.h5"));
  REQUIRE(sid.refmod.n_massless() == 4);  // two control points, x and y
  const Eigen::Index n_modes = sid.nq() - 4;
  CHECK(s["bodies"][0]["nq"].get<Eigen::Index>() == sid.nq());
  CHECK(s["bodies"][0]["quasistatic_modes"].get<Eigen::Index>() >= 4);  // massless coordinates are always static
  CHECK(sid.Me.M0.bottomRows(4).isZero(0.0));
  CHECK(sid.Me.M0.topLeftCorner(n_modes, n_modes).isIdentity(1e-10));
  // (to the round-off of shape functions that vanish on the side: 1e-17 where a mode is O(1))
  const Eigen::MatrixXd& Psi = sid.contact_surfaces[0].Psi;
  CHECK(Psi.leftCols(n_modes).cwiseAbs().maxCoeff() < 1e-12 * Psi.rightCols(4).cwiseAbs().maxCoeff());

  // the force's mean over the middle 70 % of the contact is the plateau rho c A v0: the
  // truncated modes make it ring about that value at the constrained model's highest frequency
  // (~300 kHz, 8 periods in the window), which the mean over whole and part periods leaves
  // within 3 % (measured +2.0 %)
  const format::h5::Reader results(dir.path("out-bar_drop.scene.toml/results.h5"));
  const Eigen::VectorXd t = results.vector("/time");
  const Eigen::MatrixXd F = results.matrix("/contacts/impact/force");
  const double plateau = 7800.0 * c * (0.01 * 0.01) * 1.0, duration = 2 * L / c;
  double sum = 0;
  int n = 0;
  for (Eigen::Index i = 0; i < t.size(); ++i)
    if (t(i) > 0.15 * duration && t(i) < 0.85 * duration) sum += F(i, 1), ++n;
  REQUIRE(n > 100);
  CHECK(sum / n == Approx(plateau).epsilon(0.03));

  // results.h5 keeps each sample's boundary coordinates: while the wall presses, the bottom
  // (at y = 0 in the body frame) stays on it, r_y + u_y = minus the penetration (7.5 nm here)
  const Eigen::MatrixXd r = results.matrix("/bodies/bar/position"), q = results.matrix("/bodies/bar/q");
  int pressed = 0;
  for (Eigen::Index i = 0; i < t.size(); ++i) {
    if (F(i, 1) < 0.01 * plateau) continue;
    ++pressed;
    for (const Eigen::Index y_of_point : {n_modes + 1, n_modes + 3}) CHECK(std::abs(r(i, 1) + q(i, y_of_point)) < 2e-8);
  }
  CHECK(pressed > 300);

  // after the bar has left the wall its boundary follows the modes, and the modal energies
  // (1/2 (eta_dot^2 + omega^2 eta^2) per free-interface mode) hold all of its elastic energy:
  // with the frame's kinetic energy they make up the total (to round-off: measured 3e-15)
  const json& bar = s["bodies"][0];
  double modal = 0;
  for (const json& e : bar["final_modal_energy_j"]) modal += e.get<double>();
  const double v = bar["final_velocity"][1].get<double>(), rigid = 0.5 * 0.078 * v * v;
  const double total = s["energy"]["final_j"].get<double>();
  INFO("modal " << modal << " J, rigid " << rigid << " J, total " << total << " J");
  CHECK(std::abs(modal + rigid - total) < 1e-9 * total);
  CHECK(modal > 0);
  CHECK(results.matrix("/bodies/bar/modal_energy").cols() == n_modes);
}

TEST_CASE("the leapfrog keeps a massless-boundary body's free vibration energy bounded over a million steps", "[runtime][massless][leapfrog]") {
  const test::ScratchDir dir("leapfrog-energy");
  // the bar with 6 free-interface modes (highest 54.5 kHz: omega dt = 0.07 at dt = 0.2 us),
  // free in space, its six modes started at once; no contact
  std::ofstream(dir.path("bar.model.toml")) << replace(test::model_text("bar_drop_macneal.model.toml"), "normal_modes = 30", "normal_modes = 6");
  const json s = test::run_scene(dir, test::scene_fixture("bar_free_vibration.scene.toml"));
  REQUIRE(s["steps"].get<long>() == 1000000);
  // one static solve of the boundary per step, a single Newton iteration without contact: the
  // step's end (gaps, output) keeps the solve of its right-hand side, whose state differs from
  // it only by the closing kick (solving there again made two per step)
  INFO("Newton iterations " << s["newton_iterations"].get<long>());
  CHECK(s["newton_iterations"].get<long>() <= s["steps"].get<long>() + 1);
  const format::h5::Reader results(dir.path("out-s.scene.toml/results.h5"));
  // Stoermer-Verlet conserves a modified energy: the energy oscillates by O((omega dt)^2)
  // (measured 3.3e-4 in the first tenth) and does not drift: the last tenth departs no further
  // than the first (measured 3.6e-4; the room is for where in its beat a window ends)
  const double first = energy_error(results, 0.0, 0.1), last = energy_error(results, 0.9, 1.0);
  INFO("energy error: first tenth " << first << ", last tenth " << last);
  CHECK(first < 1e-3);
  CHECK(last < 1.5 * first);
}

TEST_CASE("exact contact on the massless boundary: the bouncing bar with the leapfrog closes its gaps", "[runtime][massless][leapfrog]") {
  const test::ScratchDir dir("bar-drop-exact");
  test::copy_model_file(dir, "bar_drop_macneal.model.toml");
  std::string scene = test::model_text("bar_drop.scene.toml");
  scene = replace(scene, "rtol = 1e-6\natol = 1e-12\n", "integrator = \"leapfrog\"\nstep = 1e-8\n");
  scene = replace(scene, "output_interval = 0.1e-6", "output_interval = 0.5e-6");
  scene = replace(scene, "penalty = 1e16", "enforcement = \"exact\"\npenalty = 1e16");
  const json s = test::run_scene(dir, scene);
  // the gaps close to round-off (1e-12 of the bar's size is the solve's tolerance)
  CHECK(s["contacts"][0]["max_penetration_m"].get<double>() < 1e-13);
  CHECK(s["contacts"][0]["intervals"].get<int>() == 1);
  // exact contact on MacNeal's model: duration -0.58 %, rebound -0.09 % at this step (the
  // release follows the ringing force to its zero: 1 %); energy 2e-6
  CHECK(rel_error(s, "contact_time_s") < 0.01);
  CHECK(rel_error(s, "rebound_velocity_m_s") < 0.005);
  CHECK(s["energy"]["max_rel_error"].get<double>() < 1e-5);
}

TEST_CASE("scenes that ask for a fixed step or exact contact wrongly, or contact beyond a massless boundary: exit 2, one line", "[runtime][massless][bad-input]") {
  const test::ScratchDir dir("massless-bad");
  test::copy_model_file(dir, "bar_drop_macneal.model.toml");
  const std::string scene = test::model_text("bar_drop.scene.toml");
  struct Case {
    std::string from, to, expected;
  };
  for (const Case& c : std::vector<Case>{
           {"rtol = 1e-6\natol = 1e-12\n", "integrator = \"leapfrog\"\n", "simulation.step: missing"},
           {"atol = 1e-12\n", "atol = 1e-12\nintegrator = \"leapfrog\"\nstep = 1e-8\n", "simulation.rtol: not used by the leapfrog"},
           {"atol = 1e-12\n", "atol = 1e-12\nstep = 1e-8\n", "simulation.step: only used by integrator = \"leapfrog\""},
           {"rtol = 1e-6\natol = 1e-12\n", "integrator = \"leapfrog\"\nstep = 1e-12\n", "simulation.step: end_time / step needs at least"},
           // beyond 2/omega of the bar's highest mode the leapfrog blows up (it used to end as "penalty too stiff")
           {"rtol = 1e-6\natol = 1e-12\n", "integrator = \"leapfrog\"\nstep = 1e-5\n", "simulation.step: 1e-05 s exceeds the leapfrog's stability limit"},
           {"penalty = 1e16", "enforcement = \"rigid\"\npenalty = 1e16", "contact[0].enforcement: must be penalty or exact"},
           // the augmented Lagrangian works at the leapfrog's fixed steps only
           {"penalty = 1e16", "enforcement = \"exact\"\npenalty = 1e16", "contact[0].enforcement: exact contact needs integrator = \"leapfrog\""},
           // the contact points of a modal body move with its integrated modes
           {"model = \"bar_drop_macneal.model.toml\"", "model = \"modal.model.toml\"", "enforcement: exact contact needs a massless boundary under surface 'bottom'"},
           // a contact surface of a MacNeal body beyond its boundary: its points move with the modes too
           {"surface = \"bottom\"", "surface = \"side\"", "surface: the massless boundary of 'bar' does not cover its surface 'side'"},
       }) {
    INFO(c.to);
    std::string text = replace(scene, c.from, c.to);
    if (c.to.find("modal.model") != std::string::npos) {
      std::string model = test::model_text("bar_drop_macneal.model.toml");
      model = replace(replace(model, "method = \"macneal\"", "method = \"modal\""), "boundary_surface = \"bottom\"\n", "");
      std::ofstream(dir.path("modal.model.toml")) << model;
      REQUIRE(test::run_program(std::string(ISOSID_PREP_EXE) + " -q " + dir.path("modal.model.toml")).exit_status == 0);
      text = replace(replace(text, "sid = \"bar_drop_macneal.sid.h5\"", "sid = \"modal.sid.h5\""), "penalty = 1e16", "enforcement = \"exact\"\npenalty = 1e16");
      text = replace(text, "rtol = 1e-6\natol = 1e-12\n", "integrator = \"leapfrog\"\nstep = 1e-8\n");
    }
    if (c.to == "surface = \"side\"") {  // the bar with a second contact surface along its left side
      std::string model = test::model_text("bar_drop_macneal.model.toml");
      model = replace(model, "[reduction]", "[[contact_surface]]\nname = \"side\"\nside = \"xi0\"\n\n[reduction]");
      std::ofstream(dir.path("bar_drop_macneal.model.toml")) << model;
      REQUIRE(test::run_program(std::string(ISOSID_PREP_EXE) + " -q " + dir.path("bar_drop_macneal.model.toml")).exit_status == 0);
    }
    std::ofstream(dir.path("s.scene.toml")) << text;
    const auto r = test::run_program("ISOSID_PREP=" + std::string(ISOSID_PREP_EXE) + " " + ISOSID_RUN_EXE + " -q " + dir.path("s.scene.toml") +
                                     " -o " + dir.path("out"));
    test::check_one_line_exit(r, 2, c.expected);
  }
}

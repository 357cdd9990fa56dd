// Contact in gap space between impacts (condensation/gap_pairing.hpp): once a pairing is
// released, its pairs watch the gap, and they are evaluated only when the bodies' motion since
// their last evaluation could have closed a pair to twice the pairing distance. In between the
// watched gap is a lower bound. It must never exceed the pairs' smallest gap, so that it keeps
// the gap's sign for the event functions, and the contact closing again must be found as
// without the bound. An axisymmetric sphere bouncing on a plane exercises the frame's move and
// the coordinates' change; the terms of turning frames are not exercised here.
#include "isosid/format/sid_io.hpp"
#include "paired_step_observer.hpp"
#include "scene/scene.hpp"
#include "solve/multibody_system.hpp"
#include "solve/simulation.hpp"
#include "support/run_program.hpp"

#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <vector>

using namespace isosid;

namespace {
/// The golden sphere_small (its interface modes quasistatic) dropped at 0.3 m/s on a plane from
/// 0.1 um, brought back by gravity (200 m/s^2): two impacts in 4 ms, with a flight of about 3 ms
/// between them (it rises about 0.2 mm, beyond twice its pairing distance of 49 um).
std::string bouncing_sphere_scene(const std::string& formulation) {
  return std::string("[simulation]\ndimension = \"axisymmetric\"\nend_time = 4e-3\noutput_interval = 1e-6\n") +
         "gravity = [0.0, -200.0, 0.0]\n[[flexible_body]]\nname = \"sphere\"\nsid = \"" + ISOSID_GOLDEN_DIR +
         "/sphere_small.sid.h5\"\nposition = [0.0, 0.0100001, 0.0]\nvelocity = [0.0, -0.3, 0.0]\nhigh_modes = \"quasistatic\"\n" +
         "[[fixed_plane]]\nname = \"ground\"\n[[contact]]\nname = \"c\"\nbody = \"sphere\"\nsurface = \"contact\"\n" +
         "target = \"ground\"\npenalty = 5e17\n" + formulation;
}

/// Compares, after every step, the gap the run used with the released pairs' smallest gap.
struct WatchObserver : run::SimulationObserver {
  const run::Simulation* simulation = nullptr;
  int watched = 0, bounded = 0;
  std::vector<double> closings;   ///< s, the contact's onsets
  double largest_excess = 0;      ///< m, of the watched gap over the pairs' smallest
  double smallest_margin = INFINITY;  ///< of the pairs' smallest gap over twice the pairing distance, m
  void sample(double, const double*) override {}
  void contact_event(int, bool closing, double t) override {
    if (closing) closings.push_back(t);
  }
  void step(double, const double* y) override {
    if (!simulation) return;  // the general path's run: nothing watches
    const run::SurfaceContact& c = simulation->system().contacts()[0];
    run::GapPairing& pairing = c.gap_pairing();
    if (pairing.paired() || !pairing.watching()) return;
    const double used = c.min_gap(y);  // the step's own value (cached for this state)
    if (!pairing.watching()) return;   // watching ended at this state: the gap was projected
    const double exact = pairing.min_gap(y);
    ++watched;
    bounded += used < exact - 1e-12 * std::abs(exact);
    largest_excess = std::max(largest_excess, used - exact);
    smallest_margin = std::min(smallest_margin, exact - 2 * pairing.pairing_distance());
  }
};
}  // namespace

TEST_CASE("gap space: between impacts the watched gap never exceeds its pairs' smallest, and the sphere lands again as on the general path",
          "[runtime][unit][gap-space]") {
  const test::ScratchDir dir("gap_watch");
  auto run_scene = [&](const std::string& formulation, run::SimulationObserver& observer, WatchObserver* watch) {
    std::ofstream(dir.path("s.scene.toml")) << bouncing_sphere_scene(formulation);
    const run::Scene scene = run::read_scene_file(dir.path("s.scene.toml"));
    run::Simulation simulation(scene, {format::read_sid(scene.bodies[0].sid_file)});
    if (watch) watch->simulation = &simulation;
    REQUIRE(simulation.run(observer).completed());
    const run::SurfaceContact& c = simulation.system().contacts()[0];
    return c.gap_space() ? c.gap_pairing().pairings() : 0L;
  };
  WatchObserver gap_space;
  const long pairings = run_scene("formulation = \"gap-space\"\n", gap_space, &gap_space);
  WatchObserver general;
  run_scene("", general, nullptr);

  INFO("watched states " << gap_space.watched << ", bounded " << gap_space.bounded << ", pairings " << pairings);
  // two impacts: the second paired anew from pairs that watched the flight
  REQUIRE(gap_space.closings.size() == 2);
  CHECK(pairings == 2);
  // the pairs watched the flight's steps, nearly all through the bound alone (measured 10 335
  // of 10 336: the pairs themselves were evaluated at the stages between)
  CHECK(gap_space.watched > 1000);
  CHECK(gap_space.bounded > gap_space.watched / 2);
  // a lower bound, exact to round-off where it was evaluated, and the pairs never watched
  // within twice the pairing distance: the projection takes over before
  CHECK(gap_space.largest_excess <= 0);
  CHECK(gap_space.smallest_margin > 0);
  // the general path's touch-downs at the same times: against a plane both paths' gaps are the
  // same functions of the state. The first impacts differ by the solvers' round-off (peak
  // force 1e-5), which moves the second touch-down by 8e-12 s (measured); a touch-down found
  // late would be a flight step off (0.4 us)
  REQUIRE(general.closings.size() == 2);
  for (std::size_t i = 0; i < 2; ++i) {
    INFO("closing " << i << ": " << gap_space.closings[i] - general.closings[i] << " s apart");
    CHECK(std::abs(gap_space.closings[i] - general.closings[i]) < 1e-9);
  }
}

namespace {
/// While the contact is paired, checks the pairs' kept evaluations at each step's state and at
/// states moved from it: they must be those evaluate() gives there, never those of another state.
struct KeptEvaluationsObserver : test::PairedStepObserver {
  int mismatches = 0, unchanged_after_move = 0;
  /// The solve's pressed pairs: steps without them, steps where they differ from the pairs whose
  /// gap closes by more than round-off, and moved states at which they were still given.
  int pressed_unknown = 0, pressed_mismatches = 0, pressed_after_move = 0;
  /// The largest difference between the pairing's smallest gap at the step's state (the solve's)
  /// and the smallest of the pairs evaluated there, relative to the deepest penetration.
  double min_gap_error = 0;
  void paired_step(const run::SurfaceContact&, const run::GapPairing& pairing, const double* y) override {
    const run::FloatingBody& body = *simulation->system().bodies()[0];
    const Eigen::VectorXd quasistatic = body.quasistatic_modes();
    std::vector<double> moved(y, y + simulation->system().size());
    moved[std::size_t(body.offset()) + 1] += 1e-9;  // the frame 1 nm up
    Eigen::VectorXd deformed = quasistatic;
    deformed.array() += 1e-9;  // the quasistatic coordinates
    const std::vector<double> step_gaps = gaps(pairing, pairing.poses(y));
    check_pressed(pairing.pressed_evaluations(pairing.poses(y)) ? &pairing.pressed_pairs() : nullptr, step_gaps);
    const double smallest = *std::min_element(step_gaps.begin(), step_gaps.end());
    if (smallest < 0) min_gap_error = std::max(min_gap_error, std::abs(pairing.min_gap(y) - smallest) / -smallest);
    // each state in turn, and the step's own state last again: the kept evaluations must follow
    for (int state = 0; state < 4; ++state) {
      const double* at = state == 1 ? moved.data() : y;
      body.quasistatic_modes() = state == 2 ? deformed : quasistatic;
      const run::GapPairing::Poses poses = pairing.poses(at);
      const auto& kept = pairing.evaluations(poses);
      run::GapPairing::Evaluation e;
      for (std::size_t k = 0; k < kept.size(); ++k) {
        pairing.evaluate(poses, k, e);
        mismatches += kept[k].gap != e.gap || kept[k].slave_point != e.slave_point || kept[k].normal != e.normal;
      }
      if (state == 1 || state == 2) {
        unchanged_after_move += gaps_of(kept) == step_gaps;
        pressed_after_move += pairing.pressed_evaluations(poses) != nullptr;
      }
    }
    body.quasistatic_modes() = quasistatic;
  }
  void check_pressed(const std::vector<std::size_t>* pressed, const std::vector<double>& step_gaps) {
    if (!pressed) return void(++pressed_unknown);
    // a pair the solve presses has a closed gap, and one it leaves open a gap open but for
    // round-off of the deepest penetration
    const double deepest = -*std::min_element(step_gaps.begin(), step_gaps.end());
    for (std::size_t k = 0; k < step_gaps.size(); ++k) {
      const bool listed = std::find(pressed->begin(), pressed->end(), k) != pressed->end();
      pressed_mismatches += listed ? !(step_gaps[k] < 0) : step_gaps[k] < -1e-9 * deepest;
    }
    pressed_mismatches += !std::is_sorted(pressed->begin(), pressed->end());
  }
  static std::vector<double> gaps(const run::GapPairing& pairing, const run::GapPairing::Poses& poses) {
    std::vector<double> out(pairing.pairs().size());
    run::GapPairing::Evaluation e;
    for (std::size_t k = 0; k < out.size(); ++k) pairing.evaluate(poses, k, e), out[k] = e.gap;
    return out;
  }
  static std::vector<double> gaps_of(const std::vector<run::GapPairing::Evaluation>& kept) {
    std::vector<double> out;
    for (const auto& e : kept) out.push_back(e.gap);
    return out;
  }
};
}  // namespace

TEST_CASE("gap space: the pairs' kept evaluations are those of the state asked for, after a move of the frame or of a quasistatic coordinate",
          "[runtime][unit][gap-space]") {
  // The static solve, the loads, the step's gaps and the recorder ask for the pairs at one
  // state in turn, and the pairing keeps its evaluations between them. A change of the frame
  // or of a coordinate the pairs read must be seen.
  const test::ScratchDir dir("gap_kept");
  std::ofstream(dir.path("s.scene.toml")) << bouncing_sphere_scene("formulation = \"gap-space\"\n");
  run::Scene scene = run::read_scene_file(dir.path("s.scene.toml"));
  scene.simulation.end_time = 60e-6;  // the first impact's approach and press (it lasts about 30 us)
  run::Simulation simulation(scene, {format::read_sid(scene.bodies[0].sid_file)});
  KeptEvaluationsObserver observer;
  observer.simulation = &simulation;
  REQUIRE(simulation.run(observer).completed());
  INFO("paired steps " << observer.paired_steps);
  CHECK(observer.paired_steps > 10);
  CHECK(observer.mismatches == 0);
  // the moved states' gaps are the moved ones (evaluate() itself sees the move)
  CHECK(observer.unchanged_after_move == 0);
  // the loads evaluate the pairs the solve pressed at its state, and only there
  CHECK(observer.pressed_unknown == 0);
  CHECK(observer.pressed_mismatches == 0);
  CHECK(observer.pressed_after_move == 0);
  // and the smallest gap there is the solve's: that of the pairs evaluated there but for the
  // gradients taken at the pairing's frames (measured 9.4e-9 of the deepest penetration)
  CHECK(observer.min_gap_error < 1e-6);
}

TEST_CASE("gap space: the rows' bound holds for every pair's rows, and follows the columns' scales", "[runtime][unit][gap-space]") {
  // Rows over columns of scales six orders apart (a Craig-Bampton body's normal modes and its
  // interface modes), with the coordinates' change mostly on the small-scale columns: the bound
  // must hold for every pair and be far tighter than the Frobenius one.
  std::srand(7);
  const Eigen::Index n = 60;
  std::vector<run::SparseRows> pairs(5);
  run::RowsBound bound;
  double frobenius = 0;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    Eigen::Matrix<double, 3, Eigen::Dynamic> rows = Eigen::Matrix<double, 3, Eigen::Dynamic>::Random(3, n);
    rows.rightCols(20) *= 1e6;              // the large-scale columns
    rows.col(Eigen::Index(3 * k)).setZero();  // columns a pair does not read
    pairs[k] = run::SparseRows::from(rows);
    frobenius = std::max(frobenius, rows.norm());
    bound.add(pairs[k]);
  }
  bound.finish();
  CHECK(bound.columns().size() == std::size_t(n));  // every column read by some pair
  for (int trial = 0; trial < 20; ++trial) {
    Eigen::VectorXd a = Eigen::VectorXd::Random(n), b = a;
    b.head(n - 20) += 1e-3 * Eigen::VectorXd::Random(n - 20);
    b.tail(20) += 1e-12 * Eigen::VectorXd::Random(20);
    for (const run::SparseRows& rows : pairs) {
      Eigen::Vector3d moved = Eigen::Vector3d::Zero(), at = Eigen::Vector3d::Zero();
      rows.add_product(a, at);
      rows.add_product(Eigen::VectorXd(a - b), moved);
      CHECK(at.norm() <= bound.of(a) * (1 + 1e-12));
      CHECK(moved.norm() <= bound.of_difference(a, b) * (1 + 1e-12));
    }
    // the column-wise sum sees that the change is on the small columns
    CHECK(bound.of_difference(a, b) < 1e-2 * frobenius * (a - b).norm());
  }
}

// MacNeal's massless boundary (seed 003) through isosid-prep and isosid-run: the exact
// bouncing bar of REFERENCE.md H, whose contact lives on the massless boundary coordinates.
#include "isosid/format/hdf5_file.hpp"
#include "isosid/format/sid_io.hpp"
#include "scene_runner.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <nlohmann/json.hpp>

using namespace isosid;
using nlohmann::json;
using test::rel_error;

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

  // the SID: the boundary carries no mass, and the contact points move with it alone
  const format::Sid sid = format::read_sid(dir.path("bar_drop_macneal.sid.h5"));
  REQUIRE(sid.refmod.n_massless() == 4);  // two control points, x and y
  const Eigen::Index n_modes = sid.nq() - 4;
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
}

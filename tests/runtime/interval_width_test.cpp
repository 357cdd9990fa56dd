// The adaptive loop's limits on a refined region's width ([adaptive] interval_width and Alg. 2's
// widening), from the contact surfaces' SIDs.
#include "adapt/interval_width.hpp"
#include "isosid/format/sid_io.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <string>

using namespace isosid;

TEST_CASE("adaptive: Alg. 2 widens a region at most to the contact surfaces it refines", "[runtime][adaptive][unit]") {
  // the widest region is the smaller control net of the two refined surfaces (the
  // preprocessor refuses a region wider than its patch); a surface of a body that is not
  // adaptive does not limit it
  const format::Sid sid = format::read_sid(std::string(ISOSID_GOLDEN_DIR) + "/sphere_small.sid.h5");
  const format::MasterPatch& patch = *format::find_master_patch(sid, sid.contact_surfaces.front().master_patch);
  const double across = (patch.control_points.colwise().maxCoeff() - patch.control_points.colwise().minCoeff()).norm();
  REQUIRE(across > 0);
  run::Scene scene;
  for (const char* name : {"a", "b"}) {
    run::BodySpec b;
    b.name = name;
    b.adaptive = true;
    scene.bodies.push_back(b);
  }
  format::Sid smaller = sid;
  smaller.contact_surfaces.front().name = "small";
  for (format::MasterPatch& m : smaller.master_patches) m.control_points *= 0.5;
  run::ContactSpec c;
  c.body = "a";
  c.surface = sid.contact_surfaces.front().name;
  c.target = "b";
  CHECK(run::widest_interval(scene, {sid, smaller}, c) == across);  // a flat target: the slave's surface
  c.target_surface = "small";
  CHECK(run::widest_interval(scene, {sid, smaller}, c) == 0.5 * across);
  scene.bodies[0].adaptive = scene.bodies[1].adaptive = false;
  CHECK(std::isinf(run::widest_interval(scene, {sid, smaller}, c)));
}

TEST_CASE("adaptive: Alg. 2's decision after a try, in each band of the utilization", "[runtime][adaptive][unit]") {
  const double w = 1e-3;
  const auto beyond = run::decide_interval(1.3, true, w);
  CHECK_FALSE(beyond.acceptable);
  CHECK(beyond.next_width == Approx(1.5 * w));  // widened by half, whatever the measured reach
  const auto narrow = run::decide_interval(0.95, false, w);
  CHECK_FALSE(narrow.acceptable);
  CHECK(narrow.next_width == Approx(w * 0.95 / 0.7));
  const auto wide = run::decide_interval(0.2, false, w);
  CHECK_FALSE(wide.acceptable);
  CHECK(wide.next_width == Approx(0.5 * w));  // narrowed to half at most
  const auto fits = run::decide_interval(0.6, false, w);
  CHECK(fits.acceptable);
  CHECK(fits.next_width == Approx(w * 0.6 / 0.7));  // the next impact moves toward 70 %
  // a touch that loaded nothing (a graze, as the double pendulums' balls brushing at 0.98 s)
  // is no evidence of a too wide region: narrowing it four times left the next, real impact
  // with a sixteenth of its width
  const auto graze = run::decide_interval(0.0, false, w);
  CHECK(graze.acceptable);
  CHECK(graze.next_width == w);
  CHECK(graze.reason == "nothing loaded (the surfaces grazed)");
  CHECK_FALSE(graze.learned);  // and the next impact's width is not scaled from its glancing estimate
  CHECK(fits.learned);
}

// The right-hand side and the gap functions run millions of times per simulation: after the
// first evaluations have sized every buffer they must not touch the heap. This executable
// counts malloc calls (it interposes malloc, so it holds only this test) around evaluations
// of scenes that exercise every path: quasistatic modes with plane contact and friction or in
// gap space,
// flexible-flexible contact on a master patch, a rigid body, a spinning 3D body with
// first-order SID terms, and joints.
#include "isosid/format/sid_io.hpp"
#include "scene/scene.hpp"
#include "solve/multibody_system.hpp"
#include "support/run_program.hpp"

#include <atomic>
#include <catch2/catch.hpp>
#include <cstdlib>
#include <fstream>

extern "C" void* __libc_malloc(std::size_t size);
extern "C" void* __libc_calloc(std::size_t n, std::size_t size);
extern "C" void* __libc_realloc(void* p, std::size_t size);

namespace {
std::atomic<long> g_allocations{0};
}  // namespace

// exported (the project builds with hidden visibility): libc and libstdc++ must call these
extern "C" __attribute__((visibility("default"))) void* malloc(std::size_t size) {
  ++g_allocations;
  return __libc_malloc(size);
}
extern "C" __attribute__((visibility("default"))) void* calloc(std::size_t n, std::size_t size) {
  ++g_allocations;
  return __libc_calloc(n, size);
}
extern "C" __attribute__((visibility("default"))) void* realloc(void* p, std::size_t size) {
  ++g_allocations;
  return __libc_realloc(p, size);
}

using namespace isosid;

namespace {
const std::string kGolden = ISOSID_GOLDEN_DIR;

/// Heap allocations of `evaluations` right-hand sides and gap evaluations at states along a
/// short free motion into contact, after the same number of warm-up evaluations.
long allocations_per_sweep(const std::string& scene_text, const test::ScratchDir& dir) {
  std::ofstream(dir.path("s.scene.toml")) << scene_text;
  const run::Scene scene = run::read_scene_file(dir.path("s.scene.toml"));
  std::vector<format::Sid> sids;
  for (const auto& b : scene.bodies)
    if (!b.rigid) sids.push_back(format::read_sid(b.sid_file));
  const run::MultibodySystem system(scene, std::move(sids));
  Eigen::VectorXd y(system.size()), ydot(system.size());
  std::vector<double> gaps(system.contacts().size());
  system.initial_state(y.data());
  // states that move the bodies 0 .. 2 um towards each other: through the contact onset
  Eigen::VectorXd state = y;
  auto sweep = [&] {
    for (int i = 0; i < 40; ++i) {
      for (const auto& b : system.bodies()) state(b->offset() + 1) = y(b->offset() + 1) - (i * 5e-8) * (y(b->offset() + 1) > 0 ? 1 : -1);
      system.gaps(state.data(), gaps.data());     // solves the quasistatic modes
      system.rhs(0, state.data(), ydot.data());   // reuses that solve
      system.rhs(0, state.data(), ydot.data());   // answered from the call before
    }
  };
  sweep();  // sizes every buffer
  const long before = g_allocations.load();
  sweep();
  return g_allocations.load() - before;
}

std::string sphere(const std::string& name, const std::string& y, const std::string& vy, const std::string& extra = "") {
  return "[[flexible_body]]\nname = \"" + name + "\"\nsid = \"" + kGolden + "/sphere_small.sid.h5\"\nposition = [0.0, " + y +
         ", 0.0]\nvelocity = [0.0, " + vy + ", 0.0]\nhigh_modes = \"quasistatic\"\n" + extra;
}
const std::string kAxisymmetric = "[simulation]\ndimension = \"axisymmetric\"\nend_time = 1e-4\n";
}  // namespace

TEST_CASE("the right-hand side and the gaps do not allocate", "[runtime][allocation]") {
  const test::ScratchDir dir("allocation");
  SECTION("quasistatic modes against a plane, with friction") {
    const std::string scene = kAxisymmetric + sphere("sphere", "0.0100001", "-0.1") +
                              "[[fixed_plane]]\nname = \"ground\"\n[[contact]]\nname = \"c\"\nbody = \"sphere\"\nsurface = "
                              "\"contact\"\ntarget = \"ground\"\npenalty = 5e17\nfriction = 0.2\n";
    CHECK(allocations_per_sweep(scene, dir) == 0);
  }
  SECTION("quasistatic modes against a plane, the contact in gap space") {
    const std::string scene = kAxisymmetric + sphere("sphere", "0.0100001", "-0.1") +
                              "[[fixed_plane]]\nname = \"ground\"\n[[contact]]\nname = \"c\"\nbody = \"sphere\"\nsurface = "
                              "\"contact\"\ntarget = \"ground\"\npenalty = 5e17\nformulation = \"gap-space\"\n";
    CHECK(allocations_per_sweep(scene, dir) == 0);
  }
  SECTION("two flexible spheres (master patch) and a rigid ball") {
    const std::string scene = kAxisymmetric + sphere("upper", "0.0100001", "-0.1") +
                              sphere("lower", "-0.0100001", "0.1", "orientation = [3.141592653589793, 0.0, 0.0]\n") +
                              "[[rigid_body]]\nname = \"ball\"\nshape = \"sphere\"\nradius = 0.01\nmass = 0.01\n"
                              "position = [0.0, 0.0300002, 0.0]\nvelocity = [0.0, -0.1, 0.0]\n"
                              "[[contact]]\nname = \"pair\"\nbody = \"lower\"\nsurface = \"contact\"\ntarget = \"upper\"\n"
                              "target_surface = \"contact\"\npenalty = 5e17\n";
    CHECK(allocations_per_sweep(scene, dir) == 0);
  }
  SECTION("a spinning 3D beam with first-order terms under gravity") {
    const std::string scene = "[simulation]\ndimension = \"3d\"\nend_time = 1e-3\ngravity = [0.0, -9.81, 0.0]\n"
                              "[[flexible_body]]\nname = \"beam\"\nsid = \"" + kGolden + "/beam_small.sid.h5\"\n"
                              "position = [0.0, 1.0, 0.0]\nangular_velocity = [0.5, 3.0, 40.0]\nqdot0 = [" +
                              std::string("1e-3, 0, 0, 0, 0, 0") + "]\n";
    CHECK(allocations_per_sweep(scene, dir) == 0);
  }
  SECTION("jointed bodies under gravity: a flexible beam on a revolute joint, a rigid box on a spherical one") {
    // bodies of different nq share the joints' unit loads; the reactions' solve runs at every evaluation
    const std::string scene = "[simulation]\ndimension = \"3d\"\nend_time = 1e-3\ngravity = [0.0, -9.81, 0.0]\n"
                              "[[flexible_body]]\nname = \"beam\"\nsid = \"" + kGolden + "/beam_small.sid.h5\"\n"
                              "[[rigid_body]]\nname = \"box\"\nshape = \"box\"\nsize = [0.1, 0.1, 0.1]\ndensity = 2700.0\n"
                              "position = [0.0, -0.2, 0.0]\n"
                              "[[joint]]\nname = \"hinge\"\ntype = \"revolute\"\nbody = \"beam\"\nnode = \"end\"\naxis = [0.0, 0.0, 1.0]\n"
                              "[[joint]]\nname = \"pivot\"\ntype = \"spherical\"\nbody = \"box\"\npoint = [0.0, 0.0, 0.0]\n";
    CHECK(allocations_per_sweep(scene, dir) == 0);
  }
}

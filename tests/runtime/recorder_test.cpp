// The recorder of a run that fails at its very first sample (the quasistatic solve at t = 0):
// it keeps no partial sample, and results.h5 is written with zero samples, every series empty.
#include "isosid/format/hdf5_file.hpp"
#include "isosid/format/sid_io.hpp"
#include "output/recorder.hpp"
#include "scene/scene.hpp"
#include "solve/simulation.hpp"
#include "support/impact_scene.hpp"
#include "support/run_program.hpp"

#include <catch2/catch.hpp>
#include <fstream>

using namespace isosid;

TEST_CASE("Recorder: a run that fails before its first sample writes results with zero samples", "[runtime][unit]") {
  const test::ScratchDir dir("recorder-no-samples");
  const std::string sid = std::string(ISOSID_GOLDEN_DIR) + "/sphere_small.sid.h5";
  // the golden sphere with quasistatic high modes, its first integrated mode far beyond any
  // deformation: the quasistatic solve of the first sample fails
  std::string scene = test::golden_impact_scene(sid);
  scene.insert(scene.find("high_modes"), "q0 = [-1e308, 0.0, 0.0, 0.0]\n");
  std::ofstream(dir.path("s.scene.toml")) << scene;
  run::Simulation simulation(run::read_scene_file(dir.path("s.scene.toml")), {format::read_sid(sid)});
  run::Recorder recorder(simulation.system(), simulation.scene());
  const run::RunOutcome outcome = simulation.run(recorder);
  REQUIRE(outcome.status == "failed");
  const nlohmann::json summary = recorder.summary(simulation.stats(), outcome, simulation.state().data());
  CHECK(summary["end_time_s"] == 0.0);
  recorder.write_results(dir.path("results.h5"));
  const format::h5::Reader results(dir.path("results.h5"));
  CHECK(results.shape("/time") == std::vector<hsize_t>{0});
  CHECK(results.shape("/bodies/sphere/q") == std::vector<hsize_t>{0, 10});
  CHECK(results.shape("/contacts/impact/force") == std::vector<hsize_t>{0, 3});
  CHECK(results.shape("/energy/total") == std::vector<hsize_t>{0});
}

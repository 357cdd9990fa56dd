// The record of the SIDs the runtime's preparation wrote (scene/sid_digest): a SID whose bytes
// still match it is read without a probe in a child process; any change, a missing record or a
// broken one brings the probe back.
#include "isosid/format/error.hpp"
#include "isosid/format/isolated_probe.hpp"
#include "scene/prep_process.hpp"
#include "scene/scene.hpp"
#include "scene/sid_digest.hpp"
#include "scene/sid_provider.hpp"
#include "support/run_program.hpp"

#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>

using namespace isosid;
namespace fs = std::filesystem;

TEST_CASE("SID digests: a SID the runtime built is read unprobed while its bytes match the record", "[runtime][unit][bad-input]") {
  ::setenv("ISOSID_PREP", ISOSID_PREP_EXE, 1);
  const test::ScratchDir dir("sid_digest");
  const std::string model = dir.path("sphere.model.toml"), sid = dir.path("sphere.sid.h5");
  fs::copy_file(std::string(ISOSID_MODELS_DIR) + "/sphere_axisym.model.toml", model);
  run::Scene scene;
  scene.file = dir.path("s.scene.toml");
  scene.simulation.dimension = run::Dimension::Axisymmetric;
  run::BodySpec body;
  body.name = "sphere";
  body.model_file = model;
  body.sid_file = sid;
  scene.bodies.push_back(body);

  // built here: recorded, and read without a probe, now and at the next run
  const long before = format::probes_started();
  const auto built = run::load_sids(scene, true);
  CHECK(run::sid_digest_matches(sid));
  CHECK(run::load_sids(scene, true).at(0).nq() == built.at(0).nq());
  CHECK(format::probes_started() == before);

  // without its record, or with a record of other bytes, the SID is probed as any file
  fs::remove(sid + ".sha256");
  CHECK_FALSE(run::sid_digest_matches(sid));
  run::load_sids(scene, true);
  CHECK(format::probes_started() == before + 1);
  run::record_sid_digest(sid);
  CHECK(run::sid_digest_matches(sid));
  std::ofstream(sid + ".sha256") << std::string(64, '0') << '\n';
  CHECK_FALSE(run::sid_digest_matches(sid));
  std::ofstream(sid + ".sha256") << "not a digest\n";
  CHECK_FALSE(run::sid_digest_matches(sid));

  // a byte changed after the record: probed, and refused where the change broke the file
  run::record_sid_digest(sid);
  {
    std::fstream file(sid, std::ios::in | std::ios::out | std::ios::binary);
    file.seekp(0);
    file.put('X');  // the HDF5 signature's first byte
  }
  CHECK_FALSE(run::sid_digest_matches(sid));
  const long probes = format::probes_started();
  CHECK_THROWS_AS(run::load_sids(scene, true), format::InputError);
  CHECK(format::probes_started() == probes + 1);
}

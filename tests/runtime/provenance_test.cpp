// Provenance of the three outputs: a SID names the isosid-prep command that made it, and a
// run's summary.json and results.h5 name isosid-run's version, its exact command line and the
// SHA-256 of every file it read, the same in both.
#include "support/impact_scene.hpp"
#include "support/run_program.hpp"
#include "support/scene_text.hpp"

#include "isosid/common/sha256.hpp"
#include "isosid/format/hdf5_file.hpp"
#include "isosid/format/sid_io.hpp"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

using namespace isosid;
using Catch::Matchers::StartsWith;

TEST_CASE("provenance: the SID, summary.json and results.h5 name the version, the command and the inputs' SHA-256",
          "[runtime][provenance]") {
  const test::ScratchDir dir("provenance");
  const std::string model = std::string(ISOSID_GOLDEN_DIR) + "/sphere_small.model.toml";
  const std::string sid = dir.path("sphere.sid.h5");
  const auto prep = test::run_program(std::string(ISOSID_PREP_EXE) + " -q " + model + " -o " + sid);
  REQUIRE(prep.exit_status == 0);
  const format::Sid made = format::read_sid(sid);
  CHECK(made.provenance.command_line == std::string(ISOSID_PREP_EXE) + " -q " + model + " -o " + sid);
  CHECK(made.provenance.model_sha256 == common::sha256_file(model));

  const std::string scene = dir.path("s.scene.toml");
  std::ofstream(scene) << test::replace(test::golden_impact_scene(sid), "end_time = 100e-6", "end_time = 5e-6")
                         << "[reference]\npeak_force_n = 1.0\ncontact_time_s = 1e-5\n";
  const std::string out = dir.path("out of run");  // an argument the command line must quote
  const auto run = test::run_program(std::string(ISOSID_RUN_EXE) + " -q " + scene + " -o '" + out + "'");
  REQUIRE(run.exit_status == 0);
  const nlohmann::json summary = nlohmann::json::parse(std::ifstream(out + "/summary.json"));
  CHECK(summary["reference"].contains("peak_force_n"));
  const nlohmann::json& p = summary["provenance"];
  CHECK_THAT(p["program_version"].get<std::string>(), StartsWith(std::string("isosid-run ") + ISOSID_VERSION));
  CHECK(p["command_line"] == std::string(ISOSID_RUN_EXE) + " -q " + scene + " -o '" + out + "'");
  CHECK(p["started_utc"].get<std::string>().size() == 20);  // 2026-11-28T05:10:00Z
  REQUIRE(p["inputs"].size() == 2);
  CHECK(p["inputs"][0] == nlohmann::json({{"role", "scene"}, {"path", scene}, {"sha256", common::sha256_file(scene)}}));
  CHECK(p["inputs"][1] == nlohmann::json({{"role", "sid sphere"}, {"path", sid}, {"sha256", common::sha256_file(sid)}}));

  const format::h5::Reader results(out + "/results.h5");
  CHECK(results.string("/provenance/program_version") == p["program_version"]);
  CHECK(results.string("/provenance/command_line") == p["command_line"]);
  CHECK(results.string("/provenance/started_utc") == p["started_utc"]);
  CHECK(results.strings("/provenance/input_roles") == std::vector<std::string>{"scene", "sid sphere"});
  CHECK(results.strings("/provenance/input_paths") == std::vector<std::string>{scene, sid});
  CHECK(results.strings("/provenance/input_sha256") == std::vector<std::string>{p["inputs"][0]["sha256"], p["inputs"][1]["sha256"]});
  CHECK(p["scene_overrides"].empty());
  CHECK_FALSE(results.exists("/provenance/scene_overrides"));

  // values set over the scene file are run and recorded beside its unchanged hash
  const std::string faster = dir.path("faster");
  const auto set = test::run_program(std::string(ISOSID_RUN_EXE) + " -q " + scene + " -o " + faster +
                                     " --set 'flexible_body.0.velocity=[0.0, -0.2, 0.0]' --set simulation.end_time=4e-6");
  REQUIRE(set.exit_status == 0);
  const nlohmann::json s = nlohmann::json::parse(std::ifstream(faster + "/summary.json"));
  CHECK(s["provenance"]["scene_overrides"] == nlohmann::json({"flexible_body.0.velocity = [0.0, -0.2, 0.0]", "simulation.end_time = 4e-6"}));
  CHECK(s["provenance"]["inputs"][0] == p["inputs"][0]);
  CHECK(s["end_time_s"].get<double>() == 4e-6);
  CHECK(s["reference"].empty());  // the file's reference values are the file's scene's
  CHECK(format::h5::Reader(faster + "/results.h5").strings("/provenance/scene_overrides").size() == 2);
  // a reference value set with the run's values is compared, the file's others are not
  const auto own = test::run_program(std::string(ISOSID_RUN_EXE) + " -q " + scene + " -o " + dir.path("own") +
                                     " --set simulation.end_time=4e-6 --set reference.peak_force_n=2.0");
  REQUIRE(own.exit_status == 0);
  const nlohmann::json o = nlohmann::json::parse(std::ifstream(dir.path("own/summary.json")))["reference"];
  CHECK(o["peak_force_n"]["reference"] == 2.0);
  CHECK_FALSE(o.contains("contact_time_s"));
}

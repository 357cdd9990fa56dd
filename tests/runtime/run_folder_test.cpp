// The results folder of a run (run::RunFolder): a path that is no folder and cannot become one,
// and a folder where the run would replace one of its inputs, are refused before any work; one
// run at a time writes a folder; a run removes what an earlier run left there, and nothing else.
#include "output/run_folder.hpp"

#include "isosid/format/error.hpp"
#include "support/run_program.hpp"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sys/stat.h>
#include <unistd.h>

using namespace isosid;
using Catch::Matchers::Contains;
namespace fs = std::filesystem;

namespace {
/// A scene read from `dir`, with one body's SID and model there.
run::Scene scene_in(const test::ScratchDir& dir, const std::string& sid = "body.sid.h5", const std::string& model = "") {
  run::Scene scene;
  scene.file = dir.path("s.scene.toml");
  scene.adaptive.cache = dir.path(".isosid-cache");
  run::BodySpec body;
  body.name = "body";
  body.sid_file = dir.path(sid);
  if (!model.empty()) body.model_file = dir.path(model);
  scene.bodies.push_back(body);
  return scene;
}

std::string text_of(const std::string& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), {}};
}
}  // namespace

TEST_CASE("a results folder (-o) that is a file, a FIFO or lies below a file is refused", "[runtime][run-folder]") {
  const test::ScratchDir dir("run-folder-kind");
  const run::Scene scene = scene_in(dir);
  std::ofstream(dir.path("file")) << "x";
  REQUIRE(::mkfifo(dir.path("fifo").c_str(), 0600) == 0);
  fs::create_symlink("fifo", dir.path("link_to_fifo"));
  fs::create_symlink("loop_b", dir.path("loop_a"));
  fs::create_symlink("loop_a", dir.path("loop_b"));
  CHECK_THROWS_WITH(run::RunFolder(dir.path("file"), scene), "-o: " + dir.path("file") + " is a file, not a results folder");
  CHECK_THROWS_WITH(run::RunFolder(dir.path("fifo"), scene), "-o: " + dir.path("fifo") + " is a FIFO, not a results folder");
  CHECK_THROWS_WITH(run::RunFolder(dir.path("link_to_fifo"), scene), Contains("is a FIFO, not a results folder"));
  CHECK_THROWS_WITH(run::RunFolder(dir.path("loop_a"), scene), Contains("-o: " + dir.path("loop_a") + ": "));
  CHECK_THROWS_WITH(run::RunFolder(dir.path("file/out"), scene),
                    "-o: " + dir.path("file/out") + " cannot be created: " + dir.path("file") + " is not a folder");
  CHECK_THROWS_WITH(run::RunFolder(dir.path("file/deeper/out"), scene), Contains("cannot be created: " + dir.path("file") + " is not a folder"));
  CHECK(fs::is_fifo(dir.path("fifo")));
  CHECK(text_of(dir.path("file")) == "x");
  // a folder to be made, or one that exists: accepted, and nothing is created yet
  CHECK_NOTHROW(run::RunFolder(dir.path("new/deeper"), scene));
  CHECK_FALSE(fs::exists(dir.path("new")));
  if (::geteuid() != 0) {  // root may write anywhere
    fs::create_directory(dir.path("read-only"));
    fs::permissions(dir.path("read-only"), fs::perms::owner_read | fs::perms::owner_exec);
    CHECK_THROWS_WITH(run::RunFolder(dir.path("read-only"), scene), Contains("is a folder this user cannot write"));
    CHECK_THROWS_WITH(run::RunFolder(dir.path("read-only/out"), scene), Contains("is not writable"));
  }
}

TEST_CASE("a results folder (-o) where the run would replace or remove an input is refused, the input kept", "[runtime][run-folder]") {
  const test::ScratchDir dir("run-folder-inputs");
  std::ofstream(dir.path("results.h5")) << "a SID named results.h5";
  // an input under each name the run replaces, also reached through another spelling of the folder
  const std::vector<std::pair<run::Scene, std::string>> cases = {
      {scene_in(dir, "results.h5"), "results.h5"},
      {scene_in(dir, "body.sid.h5", "summary.json"), "summary.json"},
      {scene_in(dir, "paraview/body.sid.h5"), "paraview"},
      {scene_in(dir, "phases/00-coarse/body.sid.h5"), "phases"}};
  for (const auto& [scene, name] : cases) {
    INFO(name);
    for (const std::string& out : {dir.dir(), dir.dir() + "/.", dir.path("sub/..")}) {
      CHECK_THROWS_WITH(run::RunFolder(out, scene), Contains("-o: ") && Contains(name) && Contains("an input of the scene; the run would"));
    }
  }
  run::Scene named_summary = scene_in(dir);
  named_summary.file = dir.path("summary.json");
  CHECK_THROWS_WITH(run::RunFolder(dir.dir(), named_summary), "-o: " + dir.path("summary.json") + " is an input of the scene; the run would replace it (choose another results folder)");
  CHECK(text_of(dir.path("results.h5")) == "a SID named results.h5");
  // the same inputs beside another results folder are fine
  CHECK_NOTHROW(run::RunFolder(dir.path("out"), scene_in(dir, "results.h5")));
}

TEST_CASE("one run at a time writes a results folder, the second is refused naming the first's pid", "[runtime][run-folder]") {
  const test::ScratchDir dir("run-folder-lock");
  const run::Scene scene = scene_in(dir);
  const std::string out = dir.path("out");
  const std::string busy = out + ": another isosid-run (pid " + std::to_string(::getpid()) + ") is writing there";
  {
    run::RunFolder first(out, scene);  // the folder does not exist yet: locked when the run starts
    run::RunFolder second(out, scene);
    first.start(scene.file);
    CHECK_THROWS_WITH(second.start(scene.file), busy);
    CHECK_THROWS_WITH(run::RunFolder(out, scene), busy);  // an existing folder: refused before any work
    CHECK(text_of(out + "/summary.json").find("running") != std::string::npos);
  }
  run::RunFolder after(out, scene);  // the first run is over: its lock is gone with it
  CHECK_NOTHROW(after.start(scene.file));
}

TEST_CASE("a run's start removes an earlier run's results, frames and phases, and nothing else", "[runtime][run-folder]") {
  const test::ScratchDir dir("run-folder-start");
  const run::Scene scene = scene_in(dir);
  const std::string out = dir.path("out");
  fs::create_directories(out + "/paraview");
  fs::create_directories(out + "/phases/00-coarse/paraview");
  fs::create_directories(dir.path("elsewhere"));
  std::ofstream(out + "/results.h5") << "old";
  std::ofstream(out + "/summary.json") << "{\"status\": \"completed\"}";
  std::ofstream(out + "/paraview/scene.pvd") << "old";
  std::ofstream(out + "/phases/00-coarse/results.h5") << "old";
  std::ofstream(out + "/notes.txt") << "the user's";
  std::ofstream(dir.path("elsewhere/frame.vtu")) << "the user's";
  run::RunFolder folder(out, scene);
  folder.start(scene.file);
  CHECK_FALSE(fs::exists(out + "/results.h5"));
  CHECK_FALSE(fs::exists(out + "/paraview"));
  CHECK_FALSE(fs::exists(out + "/phases"));
  CHECK(text_of(out + "/summary.json").find("\"running\"") != std::string::npos);
  CHECK(text_of(out + "/notes.txt") == "the user's");

  // a link named paraview is removed, not followed
  fs::create_directory_symlink(dir.path("elsewhere"), out + "/paraview");
  folder.start(scene.file);
  CHECK_FALSE(fs::exists(fs::symlink_status(out + "/paraview")));
  CHECK(text_of(dir.path("elsewhere/frame.vtu")) == "the user's");
}

TEST_CASE("a results folder whose results.h5 or summary.json is a FIFO is refused, the FIFO kept", "[runtime][run-folder]") {
  const test::ScratchDir dir("run-folder-fifo");
  const run::Scene scene = scene_in(dir);
  fs::create_directory(dir.path("out"));
  REQUIRE(::mkfifo(dir.path("out/results.h5").c_str(), 0600) == 0);
  CHECK_THROWS_WITH(run::RunFolder(dir.path("out"), scene), Contains("results.h5: is a FIFO, not a file"));
  CHECK(fs::is_fifo(dir.path("out/results.h5")));
}

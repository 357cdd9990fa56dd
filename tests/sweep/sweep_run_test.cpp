// isosid-sweep as a user runs it, on the small golden sphere dropped at several speeds: one
// table of every case (a refused case recorded, the rest run), a study that resumes after
// kill -9 without running any case twice, a job-array case, and an MPI job equal to one process.
#include "support/impact_scene.hpp"
#include "support/run_program.hpp"
#include "support/scene_text.hpp"
#include "support/one_line_exit.hpp"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>

using namespace isosid;
using Catch::Matchers::Contains;
namespace fs = std::filesystem;

namespace {

/// The golden sphere's impact beside a study of `speeds` (m/s, TOML list text) and two penalties.
void write_study(const test::ScratchDir& dir, const std::string& speeds, const std::string& extra = "") {
  std::ofstream(dir.path("s.scene.toml")) << test::golden_impact_scene(std::string(ISOSID_GOLDEN_DIR) + "/sphere_small.sid.h5");
  std::ofstream(dir.path("speeds.study.toml"))
      << "scene = \"s.scene.toml\"\ncollect = [\"contacts.impact.peak_force_n\", \"contacts.impact.duration_s\"]\n" << extra
      << "[[parameter]]\nkey = \"flexible_body.0.velocity.1\"\nvalues = " << speeds << "\n"
      << "[[parameter]]\nkey = \"contact.0.penalty\"\nvalues = [2e17, 5e17]\n";
}

test::ProgramResult sweep(const test::ScratchDir& dir, const std::string& args) {
  return test::run_program(std::string(ISOSID_SWEEP_EXE) + " -q " + dir.path("speeds.study.toml") + " " + args);
}

std::string text_of(const std::string& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The table without its timing columns (which differ between runs).
std::string results_of(const std::string& csv) {
  std::istringstream in(text_of(csv));
  std::string line, out;
  std::vector<bool> keep;
  while (std::getline(in, line)) {
    std::vector<std::string> fields;
    std::stringstream split(line);  // no field here holds a comma (messages are in the table test)
    for (std::string f; std::getline(split, f, ',');) fields.push_back(f);
    if (keep.empty())
      for (const std::string& name : fields) keep.push_back(name != "wall_time_s" && name != "cpu_time_s");
    for (std::size_t j = 0; j < fields.size(); ++j)
      if (j < keep.size() && keep[j]) out += fields[j] + ",";
    out += "\n";
  }
  return out;
}

/// Scene A (models/sphere_hertz.scene.toml and its model) beside a study of it with `parameters`.
void write_scene_a_study(const test::ScratchDir& dir, const std::string& parameters) {
  for (const char* f : {"sphere_hertz.scene.toml", "sphere_axisym.model.toml"})
    std::filesystem::copy_file(std::string(ISOSID_MODELS_DIR) + "/" + f, dir.path(f));
  std::ofstream(dir.path("speeds.study.toml")) << "scene = \"sphere_hertz.scene.toml\"\n" << parameters;
}

nlohmann::json row(const test::ScratchDir& dir, const std::string& out, int index) {
  char name[16];
  std::snprintf(name, sizeof name, "%06d", index);
  return nlohmann::json::parse(std::ifstream(dir.path(out + "/cases/" + name + "/row.json")));
}

}  // namespace

TEST_CASE("sweep: every case in one table, a case with a bad value is recorded and the rest run", "[sweep]") {
  const test::ScratchDir dir("sweep_table");
  write_study(dir, "[-0.05, -0.1, \"fast\", -0.2]");
  const test::ProgramResult r = sweep(dir, "-o " + dir.path("out"));
  INFO(r.err);
  REQUIRE(r.exit_status == 0);
  const std::string csv = text_of(dir.path("out/study.csv"));
  CHECK_THAT(csv, Contains("case,status,exit_class,message,flexible_body.0.velocity.1,contact.0.penalty,contacts.impact.peak_force_n"));
  for (int i = 0; i < 8; ++i) {
    const nlohmann::json r = row(dir, "out", i);
    INFO("case " << i);
    if (i / 2 == 2) {  // "fast": refused before any case ran, with the command line's class and message
      CHECK(r["status"] == "bad input");
      CHECK(r["exit_class"] == 2);
      CHECK(r["message"] == dir.path("s.scene.toml") + ": flexible_body[0].velocity[1]: must be a number");
      CHECK_FALSE(fs::exists(dir.path("out/cases/00000" + std::to_string(i) + "/results.h5")));
      continue;
    }
    CHECK(r["status"] == "completed");
    CHECK(r["settings"]["flexible_body.0.velocity.1"] == std::vector<std::string>{"-0.05", "-0.1", "", "-0.2"}[std::size_t(i / 2)]);
    CHECK(fs::exists(dir.path("out/cases/00000" + std::to_string(i) + "/results.h5")));
  }
  // each case as isosid-run with the same values set, to the last digit
  const double f05 = row(dir, "out", 1)["collected"]["contacts.impact.peak_force_n"], f2 = row(dir, "out", 7)["collected"]["contacts.impact.peak_force_n"];
  CHECK(f2 > 3 * f05);
  const auto cli = test::run_program(std::string(ISOSID_RUN_EXE) + " -q " + dir.path("s.scene.toml") + " -o " + dir.path("cli") +
                                     " --set flexible_body.0.velocity.1=-0.2 --set contact.0.penalty=5e17");
  REQUIRE(cli.exit_status == 0);
  const nlohmann::json s = nlohmann::json::parse(std::ifstream(dir.path("cli/summary.json")));
  CHECK(s["contacts"][0]["peak_force_n"] == f2);
  CHECK(fs::exists(dir.path("out/study.h5")));
}

TEST_CASE("sweep: a study file that cannot make a study exits 2 with one line and runs nothing", "[sweep]") {
  const test::ScratchDir dir("sweep_bad");
  write_study(dir, "[-0.1]", "sampling = \"random\"\n");
  const test::ProgramResult r = sweep(dir, "-o " + dir.path("out"));
  test::check_one_line_exit(r, 2, "speeds.study.toml: sampling: must be \"grid\", \"zip\" or \"latin_hypercube\"");
  CHECK_FALSE(fs::exists(dir.path("out")));
}

TEST_CASE("sweep: a study killed halfway resumes, runs no case twice, and its table equals an uninterrupted one's", "[sweep]") {
  const test::ScratchDir dir("sweep_resume");
  // 16 cases, each long enough (300 us of output) that the kill lands mid-study
  write_study(dir, "[-0.03, -0.05, -0.07, -0.09, -0.11, -0.13, -0.15, -0.17]",
              "[[parameter]]\nkey = \"simulation.end_time\"\nvalues = [300e-6]\n");
  REQUIRE(sweep(dir, "-o " + dir.path("whole")).exit_status == 0);
  // kill -9 once three cases have their rows
  const std::string out = dir.path("killed");
  const auto killed = test::run_program("bash -c '" + std::string(ISOSID_SWEEP_EXE) + " -q " + dir.path("speeds.study.toml") + " -o " + out +
                                        " & pid=$!; for i in $(seq 3000); do [ $(ls " + out + "/cases/*/row.json 2>/dev/null | wc -l) -ge 3 ] && break; sleep 0.01; done; "
                                        "kill -9 $pid; wait $pid'");
  CHECK(killed.exit_status == 128 + 9);
  std::vector<std::pair<std::string, fs::file_time_type>> before;
  for (const auto& e : fs::directory_iterator(out + "/cases"))
    if (fs::exists(e.path() / "row.json")) before.emplace_back(e.path().string(), fs::last_write_time(e.path() / "results.h5"));
  REQUIRE(before.size() >= 3);
  REQUIRE(before.size() < 16);
  const test::ProgramResult resumed = test::run_program(std::string(ISOSID_SWEEP_EXE) + " " + dir.path("speeds.study.toml") + " -o " + out);
  INFO(resumed.err);
  REQUIRE(resumed.exit_status == 0);
  CHECK_THAT(resumed.err, Contains("16 cases, " + std::to_string(16 - before.size()) + " to run"));
  for (const auto& [folder, written] : before) CHECK(fs::last_write_time(folder + "/results.h5") == written);  // not run again
  CHECK(results_of(out + "/study.csv") == results_of(dir.path("whole/study.csv")));
}

TEST_CASE("sweep: one case of a job array, then the study around it", "[sweep]") {
  const test::ScratchDir dir("sweep_case");
  write_study(dir, "[-0.05, -0.1]");
  REQUIRE(sweep(dir, "-o " + dir.path("out") + " --case 3").exit_status == 0);
  CHECK(row(dir, "out", 3)["status"] == "completed");
  CHECK_FALSE(fs::exists(dir.path("out/study.csv")));
  CHECK(sweep(dir, "-o " + dir.path("out") + " --case 4").exit_status == 2);
  const test::ProgramResult rest = test::run_program(std::string(ISOSID_SWEEP_EXE) + " " + dir.path("speeds.study.toml") + " -o " + dir.path("out"));
  REQUIRE(rest.exit_status == 0);
  CHECK_THAT(rest.err, Contains("4 cases, 3 to run"));
  const test::ProgramResult again = test::run_program(std::string(ISOSID_SWEEP_EXE) + " " + dir.path("speeds.study.toml") + " -o " +
                                                      dir.path("out") + " --case 3");
  CHECK(again.exit_status == 0);
  CHECK_THAT(again.err, Contains("case 3 is done"));
  // a study file changed under its folder: its old rows must not pass for the new cases
  write_study(dir, "[-0.05, -0.12]");
  const test::ProgramResult changed = sweep(dir, "-o " + dir.path("out"));
  CHECK(changed.exit_status == 2);
  CHECK_THAT(changed.err, Contains("case 2 there was run with flexible_body.0.velocity.1 = -0.1, the study file now says -0.12"));
}

TEST_CASE("sweep: model keys run each case on its own copy of the model, one per distinct value, checked before any case runs",
          "[sweep]") {
  const test::ScratchDir dir("sweep_model_keys");
  write_scene_a_study(dir, "[[parameter]]\nkey = \"model.sphere.material.density\"\nvalues = [2789.0, 7800.0, -1.0]\n"
                           "[[parameter]]\nkey = [\"flexible_body.0.velocity.1\", \"simulation.end_time\"]\n"
                           "values = [[-0.1, 150e-6], [-0.12, 150e-6]]\n");
  const test::ProgramResult r = test::run_program("ISOSID_PREP=" + std::string(ISOSID_PREP_EXE) + " " + ISOSID_SWEEP_EXE + " " +
                                                  dir.path("speeds.study.toml") + " -o " + dir.path("out"));
  INFO(r.err);
  REQUIRE(r.exit_status == 0);
  CHECK_THAT(r.err, Contains("6 cases, 4 to run on 1 rank (0 done before, 2 refused)"));  // refused before any case ran
  for (int i : {4, 5}) {  // isosid-prep's own check of the copy with the negative density
    const nlohmann::json bad = row(dir, "out", i);
    CHECK(bad["status"] == "bad input");
    CHECK_THAT(bad["message"].get<std::string>(), Contains("/out/models/sphere_axisym-") && Contains("material.density"));
  }
  std::map<std::string, std::set<std::string>> models;  // density -> the model files its cases read
  for (int i = 0; i < 4; ++i) {
    const nlohmann::json done = row(dir, "out", i);
    CHECK(done["status"] == "completed");
    for (const auto& input : done["inputs"])
      if (input["role"] == "model sphere") models[done["settings"]["model.sphere.material.density"]].insert(input["path"].get<std::string>());
  }
  REQUIRE(models.size() == 2);
  CHECK(models["2789.0"].size() == 1);  // one copy per distinct value, shared by its speeds
  CHECK(models["7800.0"].size() == 1);
  CHECK(*models["2789.0"].begin() != *models["7800.0"].begin());
  CHECK_THAT(*models["7800.0"].begin(), Contains("/out/models/sphere_axisym-"));
  std::ifstream copy(*models["7800.0"].begin());
  std::stringstream text;
  text << copy.rdbuf();
  CHECK_THAT(text.str(), Contains("density = 7800"));
  CHECK_THAT(text.str(), Contains("model.sphere.material.density = 7800.0"));  // its header says what was set
  // the heavier sphere (Al's stiffness, steel's density) hits harder at the same speed
  CHECK(row(dir, "out", 2)["collected"]["contacts.impact.peak_force_n"].get<double>() >
        1.2 * row(dir, "out", 0)["collected"]["contacts.impact.peak_force_n"].get<double>());
  // the scene's own model is untouched and no SID was built beside it
  CHECK_FALSE(fs::exists(dir.path("sphere_axisym.sid.h5")));
  // the study's plots: against one parameter, and as a map over two
  const std::string plot = std::string(ISOSID_SCRIPTS_DIR) + "/plot-study " + dir.path("out");
  const test::ProgramResult curve = test::run_program(plot + " --x model.sphere.material.density --quantity 'contacts.*.peak_force_n'");
  INFO(curve.err);
  CHECK(curve.exit_status == 0);
  CHECK(fs::file_size(dir.path("out/study_model-sphere-material-density.png")) > 1000);
  const test::ProgramResult map = test::run_program(plot + " --x model.sphere.material.density --y flexible_body.0.velocity.1");
  INFO(map.err);
  CHECK(map.exit_status == 0);
  CHECK(fs::exists(dir.path("out/study_model-sphere-material-density_flexible_body-0-velocity-1.png")));
  test::check_one_line_exit(test::run_program(plot + " --x contact.0.penalty"), 2, "--x contact.0.penalty: not a parameter of the study");
  test::check_one_line_exit(test::run_program(plot + " --x model.sphere.material.density --where contact.0.penalty=1"), 2,
                            "--where contact.0.penalty=1: contact.0.penalty is not a parameter of the study");
  CHECK(test::run_program(plot + " --x model.sphere.material.density --where flexible_body.0.velocity.1=-0.1 -o " + dir.path("one.png"))
            .exit_status == 0);
  CHECK(fs::exists(dir.path("one.png")));
  // a body the scene does not have, as bad input of the study
  std::ofstream(dir.path("speeds.study.toml"), std::ios::app) << "[[parameter]]\nkey = \"model.ball.material.density\"\nvalues = [1.0]\n";
  const test::ProgramResult unknown = test::run_program(std::string(ISOSID_SWEEP_EXE) + " -q " + dir.path("speeds.study.toml") + " -o " + dir.path("other"));
  CHECK(unknown.exit_status == 0);
  CHECK_THAT(row(dir, "other", 0)["message"].get<std::string>(), Contains("model.ball: the scene has no flexible body 'ball'"));
}

#ifdef ISOSID_MPIRUN
TEST_CASE("sweep: mpirun -np 2 gives the table of one process", "[sweep][mpi]") {
  const test::ScratchDir dir("sweep_mpi");
  write_study(dir, "[-0.03, -0.05, -0.07, -0.1, -0.15]");
  REQUIRE(sweep(dir, "-o " + dir.path("one")).exit_status == 0);
  // OpenMPI refuses root unless told (CI runs as root)
  const test::ProgramResult r = test::run_program("OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 " + std::string(ISOSID_MPIRUN) +
                                                  " -np 2 " + ISOSID_SWEEP_EXE + " " + dir.path("speeds.study.toml") + " -o " + dir.path("two"));
  INFO(r.err);
  REQUIRE(r.exit_status == 0);
  CHECK_THAT(r.err, Contains("10 cases, 10 to run on 2 ranks"));
  CHECK(results_of(dir.path("two/study.csv")) == results_of(dir.path("one/study.csv")));
  // what dispatching cost: rank 1 asked once before its first case and once after each, and
  // the last rewrite of the table held every row
  std::smatch m;
  REQUIRE(std::regex_search(r.err, m, std::regex(R"(dispatch: (\d+) requests answered with ([0-9.e+-]+) ms CPU each)")));
  CHECK(std::stoi(m[1]) >= 1);
  CHECK(std::stoi(m[1]) <= 11);
  CHECK(std::stod(m[2]) > 0);
  CHECK_THAT(r.err, Contains("(the last: 10 rows in"));
}

TEST_CASE("sweep: cases on 2 ranks build each distinct SID once", "[sweep][mpi]") {
  // scene A's sphere sizes its contact elements from each impact's contact radius: 0.05 and
  // 0.2 m/s need SIDs other than the scene's (made for 0.1 m/s), each wanted by three cases
  const test::ScratchDir dir("sweep_sids");
  write_scene_a_study(dir, "[[parameter]]\nkey = \"flexible_body.0.velocity.1\"\nvalues = [-0.05, -0.2]\n"
                           "[[parameter]]\nkey = \"simulation.end_time\"\nvalues = [120e-6]\n"
                           "[[parameter]]\nkey = \"contact.0.penalty\"\nvalues = [5e18, 2e18, 1e18]\n");
  const test::ProgramResult r = test::run_program("OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 ISOSID_PREP=" +
                                                  std::string(ISOSID_PREP_EXE) + " " + ISOSID_MPIRUN + " -np 2 " + ISOSID_SWEEP_EXE + " " +
                                                  dir.path("speeds.study.toml") + " -o " + dir.path("out"));
  INFO(r.err);
  REQUIRE(r.exit_status == 0);
  CHECK_THAT(r.err, Contains("6 completed"));
  std::vector<std::string> built;
  for (const auto& e : fs::directory_iterator(dir.path(".isosid-cache")))
    if (e.path().extension() == ".h5") built.push_back(e.path().filename().string());
  CHECK(built.size() == 2);  // one per speed: the lock lets the first case build, the others read it
  std::set<std::string> used;
  for (int i = 0; i < 6; ++i) {
    const nlohmann::json r = row(dir, "out", i);  // (a temporary's member would dangle in the loop)
    for (const auto& input : r["inputs"])
      if (input["role"] == "sid sphere") used.insert(input["path"].get<std::string>());
  }
  CHECK(used.size() == 2);
}
#endif

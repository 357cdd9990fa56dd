// Model files as users write them: every bad input is one line on stderr naming file and
// field, exit status 2; the beam model of case F is converged to 0.1 % in its first twelve modes.
#include "model/body_model.hpp"
#include "reduce/body_reduction.hpp"
#include "reduce/modal_analysis.hpp"
#include "isosid/format/sid_io.hpp"
#include "support/bad_input_cases.hpp"
#include "support/run_program.hpp"
#include "support/scene_text.hpp"
#include "preprocess/body_fixtures.hpp"
#include "support/one_line_exit.hpp"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

using namespace isosid;
using Catch::Matchers::Contains;

namespace {
const char* kValid = R"(
[body]
name = "block"
analysis = "plane_stress"
thickness = 0.01
[material]
youngs_modulus = 2.1e11
poisson_ratio = 0.3
density = 7850.0
[geometry]
primitive = "rectangle"
size = [0.1, 0.02]
[refinement]
degrees = [2, 2]
subdivisions = [4, 1]
)";

using test::replace;

test::ProgramResult prep_on(const test::ScratchDir& dir, const std::string& text) {
  const std::string file = dir.path("m.model.toml");
  std::ofstream(file) << text;
  return test::run_program(std::string(ISOSID_PREP_EXE) + " -q --json --modes 5 " + file);
}

const char* kPatch = R"(
[body]
name = "patch"
analysis = "plane_strain"
[material]
youngs_modulus = 1e9
poisson_ratio = 0.3
density = 1000.0
[geometry]
primitive = "patch"
degrees = [2, 1]
knots = [[0, 0, 0, 1, 1, 1], [0, 0, 1, 1]]
control_points = [[0, 0], [0.5, 0], [1, 0], [0, 1], [0.5, 1], [1, 1]]
weights = [1, 1, 1, 1, 1, 1]
)";

const std::string kHalfDisk = R"(
[body]
name = "sphere"
analysis = "axisymmetric"
[material]
youngs_modulus = 7e10
poisson_ratio = 0.3
density = 2700.0
[geometry]
primitive = "half_disk"
radius = 0.01
[refinement]
degrees = [2, 2]
)";
}  // namespace

TEST_CASE("a valid model file prints its size and frequencies as JSON", "[model]") {
  const test::ScratchDir dir("model-ok");
  const auto r = prep_on(dir, kValid);
  REQUIRE(r.exit_status == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["dofs"] == 2 * 6 * 3);
  CHECK(j["elements"] == 4);
  CHECK(j["frequencies_hz"].size() == 5);
  CHECK(j["rigid_body_modes"] == 3);
  CHECK(j.contains("timings_s"));
  CHECK(j["timings_s"].contains("assembly"));
  CHECK(prep_on(dir, kPatch).exit_status == 0);
  // a patch parametrized the other way round (det J < 0 throughout) is no fold
  CHECK(prep_on(dir, replace(kPatch, "[[0, 0], [0.5, 0], [1, 0], [0, 1], [0.5, 1], [1, 1]]",
                             "[[0, 1], [0.5, 1], [1, 1], [0, 0], [0.5, 0], [1, 0]]")).exit_status == 0);
}

TEST_CASE("a --modes count beyond the model's DOFs is bad input, not a silent cut", "[model]") {
  const test::ScratchDir dir("model-modes");
  const std::string file = dir.path("m.model.toml");
  std::ofstream(file) << kValid;  // 36 DOFs: at most 35 modes
  const auto most = test::run_program(std::string(ISOSID_PREP_EXE) + " -q --json --modes 35 " + file);
  REQUIRE(most.exit_status == 0);
  CHECK(nlohmann::json::parse(most.out)["frequencies_hz"].size() == 35);
  const auto r = test::run_program(std::string(ISOSID_PREP_EXE) + " -q --json --modes 36 " + file);
  CHECK(r.exit_status == 2);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  CHECK_THAT(r.err, Catch::Matchers::Contains("--modes: asks for 36 modes") && Catch::Matchers::Contains("36 free DOFs (at most 35 modes)"));
}

TEST_CASE("bad model files: exit 2 with one line naming file, field and problem", "[model]") {
  const test::ScratchDir dir("model-bad");
  struct Case {
    std::string text, expected;
  };
  // the cases of tests/bad_inputs/model_files.toml, and two texts too long to keep there
  std::vector<Case> cases;
  for (const auto& c : test::bad_input_cases("model_files.toml", {{"valid", kValid}, {"patch", kPatch}, {"half_disk", kHalfDisk}}, "valid"))
    cases.push_back({c.text, c.expected});
  const std::vector<Case> long_texts = {
      {[] {
         std::string text = kValid;
         for (int i = 0; i <= 10000; ++i) text += "[[node]]\nname = \"n" + std::to_string(i) + "\"\nparameter = [0.5, 0.5]\n";
         return text;
       }(),
       "node[10000].name: more than 10000 nodes"},
      {[] {
         std::string text = kValid;
         for (int i = 0; i <= 10; ++i)
           text += "[[stress_line]]\nname = \"s" + std::to_string(i) + "\"\nfrom = [0, 0.5]\nto = [1, 0.5]\npoints = 10000\n";
         return text;
       }(),
       "stress_line[10].points: the stress lines together have more than 100000 points"},
  };
  cases.insert(cases.end(), long_texts.begin(), long_texts.end());
  for (const Case& c : cases) {
    INFO(c.expected);
    const auto r = prep_on(dir, c.text);
    CHECK(r.exit_status == 2);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK_THAT(r.err, Contains("m.model.toml") && Contains(c.expected));
    CHECK(r.out.empty());
  }
  // found only once the model is refined and reduced: still the model's field, exit 2
  const std::vector<Case> reduced = {
      {std::string(kValid) + "[reduction]\nmethod = \"modal\"\nnormal_modes = 1000\n",
       "reduction.normal_modes: 1000 modes need 1003 free DOFs with the rigid-body modes, but the refined model has"},
      {std::string(kValid) + "[[contact_surface]]\nname = \"c\"\nside = \"bottom\"\n[reduction]\nmethod = \"craig-bampton\"\n"
                             "normal_modes = 2\ninterface_surface = \"c\"\ninterface_points = 2\ninterface_center = [1.5]\n",
       "reduction.interface_center: parameter 1.500000 lies outside the side's range"},
      // a contact surface without area: a side that collapses, an interval below round-off
      {std::string(kValid) + "[[contact_surface]]\nname = \"c\"\nside = \"bottom\"\ninterval = [[0.0, 1e-300]]\n",
       "contact_surface[0].interval: narrower than 1e-9 of the parameter range"},
      {kHalfDisk + "subdivisions = [2, 2]\n[[contact_surface]]\nname = \"c\"\nside = \"axis\"\n[reduction]\nmethod = \"modal\"\nnormal_modes = 2\n",
       "contact_surface c.side: side 'axis' has no area (it collapses to a line or a point)"}};
  for (const Case& c : reduced) {
    INFO(c.expected);
    std::ofstream(dir.path("m.model.toml")) << c.text;
    const auto r = test::run_program(std::string(ISOSID_PREP_EXE) + " -q " + dir.path("m.model.toml") + " -o " + dir.path("m.sid.h5"));
    CHECK(r.exit_status == 2);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK_THAT(r.err, Contains("m.model.toml") && Contains(c.expected));
    CHECK_FALSE(std::filesystem::exists(dir.path("m.sid.h5")));
  }
  const auto missing = test::run_program(std::string(ISOSID_PREP_EXE) + " " + dir.path("nope.model.toml"));
  CHECK(missing.exit_status == 2);
  CHECK_THAT(missing.err, Contains("file not found"));
  // the SID must not overwrite its own model
  const std::string golden = std::string(ISOSID_GOLDEN_DIR) + "/beam_small.model.toml";
  std::filesystem::copy_file(golden, dir.path("self.model.toml"));
  const auto self = test::run_program(std::string(ISOSID_PREP_EXE) + " -q " + dir.path("self.model.toml") + " -o " +
                                      dir.path("self.model.toml"));
  test::check_one_line_exit(self, 2, "-o: is the model file itself");
  std::ifstream original(golden), kept(dir.path("self.model.toml"));
  CHECK(std::string(std::istreambuf_iterator<char>(original), {}) == std::string(std::istreambuf_iterator<char>(kept), {}));
}

TEST_CASE("a node where the mapping collapses gets its rotations from just inside", "[model]") {
  // a reproducer: a rod with a spherical end and a node at the corner parameter [1, 1],
  // where the parametrization collapses; it was refused ("/nodes/top/psi: non-finite" on the
  // output SID). The rotation rows come from 1e-7 of the range inside: finite, and within 1e-4
  // of those taken 1e-5 inside (a smooth field)
  const test::ScratchDir dir("node-corner");
  auto psi_at = [&](const std::string& parameter, const std::string& name) {
    std::ofstream(dir.path(name + ".model.toml")) << test::scene_fixture("rod_corner_node.model.toml", {{"@PARAMETER@", parameter}});
    const auto r = test::run_program(std::string(ISOSID_PREP_EXE) + " -q " + dir.path(name + ".model.toml") + " -o " + dir.path(name + ".sid.h5"));
    INFO(r.err);
    REQUIRE(r.exit_status == 0);
    return format::read_sid(dir.path(name + ".sid.h5")).nodes.at(0).psi;
  };
  const Eigen::MatrixXd corner = psi_at("1.0, 1.0", "corner"), near = psi_at("0.99999, 0.99999", "near");
  CHECK(corner.allFinite());
  CHECK((corner - near).norm() <= 1e-4 * near.norm());
}

TEST_CASE("the seed beam model's first twelve elastic frequencies are converged to 0.1 %", "[model][slow]") {
  auto spec = prep::read_model_file(std::string(ISOSID_MODELS_DIR) + "/beam_free_free.model.toml");
  auto frequencies = [](const prep::ModelSpec& s) {
    const auto b = prep::build_body(s);
    const auto sys = prep::assemble_system(b.space, b.dofs, b.elasticity);
    const auto m = prep::lowest_modes(sys.K, sys.M, 18, prep::eigenvalue_scale(s.patches[0].material.youngs_modulus, s.patches[0].material.density, 0.21));
    REQUIRE(m.rigid_body_modes == 6);
    return Eigen::VectorXd(m.frequencies_hz().segment(6, 12));
  };
  const Eigen::VectorXd base = frequencies(spec);
  for (int& n : spec.patches[0].refinement.subdivisions) n = n * 3 / 2;  // 1.5x finer in every direction
  const Eigen::VectorXd finer = frequencies(spec);
  const double change = ((base - finer).array() / finer.array()).abs().maxCoeff();
  INFO("largest relative change " << change);
  CHECK(change < 1e-3);
  CHECK((base.array() >= finer.array() * (1 - 1e-12)).all());  // refinement lowers Galerkin frequencies
  // first bending mode in the 10 mm direction: Euler-Bernoulli 1209 Hz, shear lowers it ~1 %
  CHECK(base(0) == Approx(1199.8).epsilon(1e-3));
}

TEST_CASE("isosid-prep writes a SID beside the model and reports it as JSON", "[model][sid]") {
  const test::ScratchDir dir("prep-sid");
  std::string text = kValid;
  text += R"(
[[contact_surface]]
name = "contact"
side = "top"
[reduction]
method = "craig-bampton"
normal_modes = 3
interface_surface = "contact"
interface_points = 3
interface_center = [0.5]
[[node]]
name = "tip"
parameter = [1.0, 0.5]
)";
  std::ofstream(dir.path("block.model.toml")) << text;
  const auto r = test::run_program(std::string(ISOSID_PREP_EXE) + " -q --json " + dir.path("block.model.toml"));
  REQUIRE(r.exit_status == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["output"] == dir.path("block.sid.h5"));
  CHECK(j["nq"] == 3 + 6 - 3);  // 3 normal + 3 points x 2 DOFs - 3 rigid-body directions
  CHECK(j["n_low"] == 3);
  CHECK(j["n_high"] == 3);
  for (const char* stage : {"refine", "assembly", "mass", "reduction", "sid_terms", "write"}) CHECK(j["timings_s"].contains(stage));
  const auto info = test::run_program(std::string(ISOSID_INFO_EXE) + " --json " + dir.path("block.sid.h5"));
  REQUIRE(info.exit_status == 0);
  const auto sid = nlohmann::json::parse(info.out);
  CHECK(sid["mass"].get<double>() == Approx(7850.0 * 0.1 * 0.02 * 0.01).epsilon(1e-12));
  CHECK(sid["nq"] == 6);
  CHECK(sid["nodes"][0]["name"] == "tip");
  CHECK(sid["contact_surfaces"][0]["points"] == 4 * 3);
}

TEST_CASE("massless-boundary SIDs from model files: MacNeal (free) and massless Craig-Bampton (clamped)", "[model][sid][macneal]") {
  const test::ScratchDir dir("prep-massless");
  // the block's top: quadratic along x with 4 spans, 6 control points, 12 DOFs
  const std::string surface = "\n[[contact_surface]]\nname = \"contact\"\nside = \"top\"\n";
  struct Case {
    std::string extra;
    int modes;
  };
  for (const Case& c : std::vector<Case>{
           {"[reduction]\nmethod = \"macneal\"\nnormal_modes = 4\nboundary_surface = \"contact\"\n", 4},
           {"[boundary]\nclamped = [\"left\"]\n[reduction]\nmethod = \"craig-bampton-massless\"\nnormal_modes = 5\nboundary_surface = \"contact\"\n", 5},
       }) {
    INFO(c.extra);
    std::ofstream(dir.path("m.model.toml")) << std::string(kValid) + surface + c.extra;
    const auto r = test::run_program(std::string(ISOSID_PREP_EXE) + " -q --json " + dir.path("m.model.toml"));
    INFO(r.err);
    REQUIRE(r.exit_status == 0);
    const auto j = nlohmann::json::parse(r.out);
    CHECK(j["n_low"] == c.modes);
    // the clamped corner's control point is not free: 6 points x 2 DOFs, less its two
    const int boundary = c.extra.find("clamped") != std::string::npos ? 10 : 12;
    CHECK(j["n_high"] == boundary);
    // the SID passes the reader's validation (massless rows of Me, names of the boundary DOFs)
    const format::Sid sid = format::read_sid(dir.path("m.sid.h5"));
    CHECK(sid.refmod.n_massless() == boundary);
    CHECK(sid.Me.M0.bottomRows(boundary).isZero(0.0));
    CHECK_THAT(sid.refmod.mode_names.back(), Contains("boundary " + std::to_string(boundary) + ": control point"));
  }
  // a hierarchically refined body: prepared once, no coarse model and no transfer; its boundary
  // is every function of the refined space on the side (more than the 6 points of the plain
  // block: the refined box adds level-1 functions there)
  const std::string thb = std::string(kValid) + "[refinement.hierarchical]\nbox = [[0.25, 0.5], [0.5, 1.0]]\nelements_across = 4\n" + surface +
                          "[reduction]\nmethod = \"macneal\"\nnormal_modes = 4\nboundary_surface = \"contact\"\n";
  std::ofstream(dir.path("thb.model.toml")) << thb;
  const auto refined = test::run_program(std::string(ISOSID_PREP_EXE) + " -q --json " + dir.path("thb.model.toml"));
  INFO(refined.err);
  REQUIRE(refined.exit_status == 0);
  const auto j = nlohmann::json::parse(refined.out);
  const int boundary = j["n_high"].get<int>();
  CHECK(boundary > 12);
  CHECK(boundary % 2 == 0);
  CHECK_FALSE(j["timings_s"].contains("coarse_model"));
  const format::Sid thb_sid = format::read_sid(dir.path("thb.sid.h5"));
  CHECK(thb_sid.refmod.n_massless() == boundary);
  CHECK(thb_sid.Me.M0.bottomRows(boundary).isZero(0.0));
  CHECK_FALSE(thb_sid.transfer.has_value());
  // an impact's refined model needs the transfer: refused before any work
  const auto adaptive = test::run_program(std::string(ISOSID_PREP_EXE) + " -q " + dir.path("thb.model.toml") +
                                          " --refine-at contact:0.5 --refine-width 0.01 -o " + dir.path("refined.sid.h5"));
  CHECK(adaptive.exit_status == 2);
  CHECK_THAT(adaptive.err, Contains("--refine-at: an impact's refined model takes its state through a transfer"));
  // a free body has no massless Craig-Bampton model
  std::ofstream(dir.path("m.model.toml")) << std::string(kValid) + surface +
                                                 "[reduction]\nmethod = \"craig-bampton-massless\"\nnormal_modes = 5\nboundary_surface = \"contact\"\n";
  const auto r = test::run_program(std::string(ISOSID_PREP_EXE) + " -q " + dir.path("m.model.toml"));
  CHECK(r.exit_status == 2);
  CHECK_THAT(r.err, Contains("reduction.method: craig-bampton-massless needs a body that its [boundary] holds"));
}

TEST_CASE("reduction settings are validated", "[model][sid]") {
  const test::ScratchDir dir("prep-sid-bad");
  const std::string base = std::string(kValid) + "\n[[contact_surface]]\nname = \"contact\"\nside = \"top\"\n";
  struct Case {
    std::string extra, expected;
  };
  for (const Case& c : std::vector<Case>{
           {"[reduction]\nmethod = \"guyan\"\n", "reduction.method: unknown method"},
           {"[reduction]\nmethod = \"craig-bampton\"\nnormal_modes = 3\ninterface_surface = \"nope\"\ninterface_points = 2\ninterface_center = [0.5]\n",
            "reduction.interface_surface: no contact_surface named 'nope'"},
           {"[reduction]\nmethod = \"modal\"\ninterface_points = 2\n", "reduction.interface_points: only used by method"},
           // bounded before the cast to int (2^31 crashed, 2^32 + 1 became 1), then by the side's nodes
           {"[reduction]\nmethod = \"craig-bampton\"\nnormal_modes = 3\ninterface_surface = \"contact\"\ninterface_points = 2147483648\ninterface_center = [0.5]\n",
            "reduction.interface_points: must lie in 1..2000000, is 2147483648"},
           {"[reduction]\nmethod = \"craig-bampton\"\nnormal_modes = 3\ninterface_surface = \"contact\"\ninterface_points = 4294967297\ninterface_center = [0.5]\n",
            "reduction.interface_points: must lie in 1..2000000, is 4294967297"},
           {"[reduction]\nmethod = \"craig-bampton\"\nnormal_modes = 3\ninterface_surface = \"contact\"\ninterface_points = 2000000\ninterface_center = [0.5]\n",
            "reduction.interface_points: 2000000 requested, the side has"},
           {"[reduction]\nmethod = \"modal\"\nnormal_modes = 4294967306\n", "reduction.normal_modes: must lie in 0..100000"},
           // an interface on a clamped side has no DOF left (it was a failed computation, exit 1)
           {"[boundary]\nclamped = [\"top\"]\n[reduction]\nmethod = \"craig-bampton\"\nnormal_modes = 3\ninterface_surface = \"contact\"\ninterface_points = 2\ninterface_center = [0.5]\n",
            "reduction.interface_points: the 2 control points of 'contact' nearest the interface centre are all held by [boundary]"},
           {"[reduction]\nmethod = \"macneal\"\nnormal_modes = 3\nboundary_surface = \"nope\"\n",
            "reduction.boundary_surface: no contact_surface named 'nope'"},
           {"[reduction]\nmethod = \"macneal\"\nnormal_modes = 3\n", "reduction.boundary_surface: missing"},
           {"[reduction]\nmethod = \"macneal\"\nnormal_modes = 0\nboundary_surface = \"contact\"\n", "reduction.normal_modes: must be a positive count"},
           {"[reduction]\nmethod = \"modal\"\nboundary_surface = \"contact\"\n", "reduction.boundary_surface: only used by the massless-boundary methods"},
           {"[damping]\nkappa = -1\n", "damping.kappa: is a damping ratio: must lie in [0, 1]"},
           {"[damping]\nf1 = 100.0\n", "damping.f2: give both f1 and f2"},
           {"[visual]\nsubdivisions = 0\n", "visual.subdivisions: must lie in 1..8"},
           {"[visual]\nstress = 1\n", "visual.stress:"},
           {"[visual]\ncells = 4\n", "visual.cells: unknown key"},
           {"[[node]]\nname = \"n\"\nparameter = [2.0, 0.5]\n", "node[0].parameter: outside"},
           {"[[contact_surface]]\nname = \"contact\"\nside = \"left\"\n", "contact_surface[1].name: duplicate name"},
           // nodes and stress lines in metres (the block is 0.1 x 0.02 m)
           {"[[node]]\nname = \"n\"\npoint = [0.15, 0.01]\n", "node[0].point: the point lies 0.05 m outside the body"},
           {"[[node]]\nname = \"n\"\nparameter = [0.5, 0.5]\npoint = [0.05, 0.01]\n", "node[0].parameter: give exactly one of"},
           {"[[node]]\nname = \"n\"\npoint = [0.05, 0.01, 0.0]\n", "node[0].point: needs 2 coordinates"},
           {"[[stress_line]]\nname = \"s\"\nfrom_point = [0.05, 0.01]\nto_point = [0.05, 0.03]\n",
            "stress_line[0].to_point: the point lies 0.01 m outside the body"},
           {"[[stress_line]]\nname = \"s\"\nfrom = [0.5, 0.5]\nto_point = [0.05, 0.01]\n",
            "stress_line[0].from: give both ends as parameters or both in metres"},
       }) {
    std::ofstream(dir.path("m.model.toml")) << base + c.extra;
    const auto r = test::run_program(std::string(ISOSID_PREP_EXE) + " -q " + dir.path("m.model.toml"));
    INFO(c.extra);
    test::check_one_line_exit(r, 2, c.expected);
  }
}

TEST_CASE("nodes and stress lines placed in metres: reported by parameter and position", "[model][sid][placement]") {
  const test::ScratchDir dir("prep-placement");
  std::ofstream(dir.path("block.model.toml")) << std::string(kValid) + R"(
[[node]]
name = "corner"
point = [0.1, 0.02]
[[node]]
name = "middle"
parameter = [0.5, 0.5]
[[stress_line]]
name = "across"
from_point = [0.025, 0.0]
to_point = [0.025, 0.02]
points = 3
)";
  const auto r = test::run_program(std::string(ISOSID_PREP_EXE) + " -q --json " + dir.path("block.model.toml"));
  REQUIRE(r.exit_status == 0);
  const auto placement = nlohmann::json::parse(r.out)["placement"];
  auto close = [](const nlohmann::json& v, std::vector<double> expected) {
    for (std::size_t i = 0; i < expected.size(); ++i) CHECK(v[i].get<double>() == Approx(expected[i]).margin(1e-12));
  };
  CHECK(placement["nodes"][0]["name"] == "corner");
  CHECK(placement["nodes"][0]["given"] == "point");
  close(placement["nodes"][0]["parameter"], {1.0, 1.0});
  close(placement["nodes"][0]["point_m"], {0.1, 0.02});
  CHECK(placement["nodes"][1]["given"] == "parameter");
  close(placement["nodes"][1]["point_m"], {0.05, 0.01});
  const auto& line = placement["stress_lines"][0];
  CHECK(line["given"] == "point");
  CHECK(line["points"] == 3);
  close(line["from"]["parameter"], {0.25, 0.0});
  close(line["to"]["parameter"], {0.25, 1.0});
  const auto text = test::run_program(std::string(ISOSID_PREP_EXE) + " -q " + dir.path("block.model.toml"));
  CHECK_THAT(text.out, Contains("node corner at parameter [1, 1] = [0.1, 0.02] m (given by point)"));
  CHECK_THAT(text.out, Contains("stress line across, 3 points from parameter [0.25, 0] = [0.025, 0] m to parameter [0.25, 1] = [0.025, 0.02] m (given by points)"));
}

TEST_CASE("a stress line in metres must stay inside the body between its ends", "[model][placement]") {
  const test::ScratchDir dir("prep-placement-bad");
  // a quarter annulus (radii 0.8, 1): the chord between points on its two straight sides crosses the hole
  std::ofstream(dir.path("m.model.toml")) << replace(replace(kValid, "primitive = \"rectangle\"", "primitive = \"quarter_annulus\""),
                                                     "size = [0.1, 0.02]", "inner_radius = 0.8\nouter_radius = 1.0") +
                                                 "[[stress_line]]\nname = \"chord\"\nfrom_point = [0.9, 0.0]\nto_point = [0.0, 0.9]\npoints = 5\n";
  const auto r = test::run_program(std::string(ISOSID_PREP_EXE) + " -q " + dir.path("m.model.toml"));
  test::check_one_line_exit(r, 2, Contains("m.model.toml") && Contains("stress_line[0].to_point: the line's point 2 lies"));
}

TEST_CASE("contact elements sized from the expected contact radius", "[model][contact]") {
  // [contact_resolution] with smallest = "contact": the graded elements at the contact point
  // are a / elements_per_radius; --contact-radius replaces a, and the SID records it
  const test::ScratchDir dir("contact-resolution");
  const std::string model = dir.path("sphere.model.toml");
  std::filesystem::copy_file(std::string(ISOSID_MODELS_DIR) + "/sphere_axisym.model.toml", model);
  auto spec = prep::read_model_file(model);
  REQUIRE(spec.contact_resolution);
  CHECK(spec.contact_resolution->element_size() == Approx(1.68e-4 / 8).epsilon(1e-12));
  for (const auto& g : spec.patches[0].refinement.graded) CHECK(g.smallest == Approx(1.68e-4 / 8).epsilon(1e-12));
  prep::set_contact_radius(spec, 4e-4, "test");
  for (const auto& g : spec.patches[0].refinement.graded) CHECK(g.smallest == Approx(5e-5).epsilon(1e-12));
  // the element at the pole along the lower arc: a/8 (graded knots meet the size exactly)
  const auto body = prep::build_body(spec);
  double pole = 1e9;
  for (const auto& e : body.space.elements)
    if (e.lo(0) == 0.0 && e.lo(1) == 0.0)
      pole = (body.refined[0].point(Eigen::Vector2d(e.hi(0), 0)) - body.refined[0].point(Eigen::Vector2d(0, 0))).norm();
  CHECK(pole == Approx(5e-5).epsilon(0.01));  // a chord of an arc element: 1 % above its length at most

  const auto r = test::run_program(std::string(ISOSID_PREP_EXE) + " -q --contact-radius 4e-4 " + model + " -o " + dir.path("s.sid.h5"));
  REQUIRE(r.exit_status == 0);
  const auto info = test::run_program(std::string(ISOSID_INFO_EXE) + " --json " + dir.path("s.sid.h5"));
  CHECK(nlohmann::json::parse(info.out)["mesh"]["contact_radius_m"].get<double>() == 4e-4);
  // a model that sizes nothing from a contact radius refuses the option
  const std::string beam = std::string(ISOSID_GOLDEN_DIR) + "/beam_small.model.toml";
  const auto refused = test::run_program(std::string(ISOSID_PREP_EXE) + " -q --contact-radius 4e-4 " + beam + " -o " + dir.path("b.sid.h5"));
  test::check_one_line_exit(refused, 2, Contains("--contact-radius") && Contains("sizes no elements from a contact radius"));
}


TEST_CASE("isosid-prep --refine-at moves a hierarchical refinement and its Craig-Bampton interface, malformed requests exit 2", "[model][thb]") {
  const std::string thb = std::string(ISOSID_MODELS_DIR) + "/sphere_axisym_thb.model.toml";
  auto spec = prep::read_model_file(thb);
  prep::set_refinement_point(spec, "contact", {0.05}, 0.5e-3, "test");
  const auto& request = *spec.patches[0].refinement.hierarchical;
  CHECK(request.box.empty());
  CHECK(request.point == std::vector<double>{0.05, 0.0});  // the lower arc is the side eta = 0
  CHECK(request.width == 0.5e-3);
  REQUIRE(spec.reduction.interface_center.size() == 1);
  CHECK(spec.reduction.interface_center(0) == 0.05);
  CHECK(spec.reduction.interface_radius == 0.25e-3);

  // the interface spans the refined region however fine its elements: every node of the side
  // within half the width (a fixed count of 16 nodes of 10 um elements covered 0.16 mm, less
  // than the contact it was to soften; scene D's peak force came out 12 % high)
  spec.patches[0].refinement.hierarchical->smallest = 10e-6;
  const prep::BodyModel body = prep::build_body(spec);
  std::string description;
  const std::vector<int> dofs = prep::interface_dofs(body, description);
  CHECK(dofs.size() > 2 * 16);
  INFO(description);

  // a rod hit at its far end: the interface moves to that face
  auto rod = prep::read_model_file(std::string(ISOSID_MODELS_DIR) + "/wave_rod.model.toml");
  prep::set_refinement_point(rod, "top", {0.0}, 0.6e-3, "test");
  CHECK(rod.reduction.interface_surface == "top");
  CHECK(rod.patches[0].refinement.hierarchical->point == std::vector<double>{0.0, 1.0});

  const test::ScratchDir dir("refine-at");
  const auto refused = [&](const std::string& options, const std::string& problem) {
    const auto r = test::run_program(std::string(ISOSID_PREP_EXE) + " -q " + options + " " + thb + " -o " + dir.path("s.sid.h5"));
    test::check_one_line_exit(r, 2, Contains("sphere_axisym_thb.model.toml") && Contains("--refine-at") && Contains(problem));
    CHECK_FALSE(std::filesystem::exists(dir.path("s.sid.h5")));
  };
  refused("--refine-at contact:0.05", "goes with --refine-width");
  refused("--refine-at contact0.05 --refine-width 1e-3", "must be SURFACE:U");
  refused("--refine-at contact:0.05, --refine-width 1e-3", "must be SURFACE:U");
  refused("--refine-at contact:nan --refine-width 1e-3", "must be SURFACE:U");
  refused("--refine-at contact:0.05 --refine-width 0", "positive length");
  refused("--refine-at contact:1.5 --refine-width 1e-3", "outside the parameter range of xi");
}

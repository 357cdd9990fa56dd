// The preprocessing pipeline called in process: it reproduces the golden SIDs (compared as
// isosid-diff compares them), reports its stages in order to an observer, writes the SID
// when asked, builds a hierarchical body's transfer, and its modal-only variant finds the
// rigid-body modes of free bodies (1 axisymmetric, 3 planar, 6 solid).
#include "geometry/primitives.hpp"
#include "isosid/format/sid_compare.hpp"
#include "isosid/format/sid_io.hpp"
#include "model/model_file.hpp"
#include "pipeline/prepare.hpp"
#include "preprocess/body_fixtures.hpp"
#include "support/run_program.hpp"

#include <catch2/catch.hpp>

using namespace isosid;

namespace {

prep::ModelSpec golden_model(const std::string& name) {
  return prep::read_model_file(std::string(ISOSID_GOLDEN_DIR) + "/" + name + ".model.toml");
}

std::vector<std::string> names(const prep::StageTimings& timings) {
  std::vector<std::string> out;
  for (const auto& [stage, seconds] : timings) out.push_back(stage);
  return out;
}

/// Remembers what it was told, in order.
struct RecordingObserver : prep::StageObserver {
  std::vector<std::string> events;
  void started(const std::string& stage, const std::string&) override { events.push_back("start " + stage); }
  void finished(const std::string& stage, double seconds) override {
    CHECK(seconds >= 0);
    events.push_back("end " + stage);
  }
};

void check_golden(const std::string& name) {
  const prep::PreparedBody prepared = prep::prepare(golden_model(name));
  const format::Sid golden = format::read_sid(std::string(ISOSID_GOLDEN_DIR) + "/" + name + ".sid.h5");
  const format::Comparison c = format::compare_sids(golden, prepared.sid, 1e-6);  // isosid-diff's tolerance in golden_sid_test
  for (const auto& d : c.differences) INFO(d.what << ": " << d.difference << " > " << d.tolerance);
  CHECK(c.equal());
  const std::vector<std::string> stages = {"refine", "assembly", "mass", "reduction", "sid_terms"};
  CHECK(names(prepared.timings) == stages);  // nothing written without an output
  CHECK(prepared.sid.provenance.timings_s == prepared.timings);
  CHECK(prepared.scalar_mass.sum() == Approx(golden.refmod.mass).epsilon(1e-12));
}

}  // namespace

TEST_CASE("prepare() reproduces the golden axisymmetric Craig-Bampton sphere", "[pipeline][golden]") { check_golden("sphere_small"); }
TEST_CASE("prepare() reproduces the golden 3D modal beam", "[pipeline][golden]") { check_golden("beam_small"); }

TEST_CASE("prepare() tells its observer every stage in order and writes the SID last", "[pipeline]") {
  const test::ScratchDir dir("pipeline-write");
  RecordingObserver observer;
  const prep::PreparedBody prepared = prep::prepare(golden_model("sphere_small"), {.build_sid = true, .output = dir.path("s.sid.h5")}, observer);
  std::vector<std::string> expected;
  for (const char* stage : {"refine", "assembly", "mass", "reduction", "sid_terms", "write"})
    for (const char* event : {"start ", "end "}) expected.push_back(event + std::string(stage));
  CHECK(observer.events == expected);
  CHECK(names(prepared.timings).back() == "write");
  CHECK(prepared.sid.provenance.timings_s.size() == 5);  // the SID cannot hold its own write time
  CHECK(format::compare_sids(format::read_sid(dir.path("s.sid.h5")), prepared.sid, 1e-12).equal());
}

TEST_CASE("prepare() without a SID stops after the reduction", "[pipeline]") {
  const prep::PreparedBody reduced = prep::prepare(golden_model("beam_small"), {.build_sid = false, .output = ""});
  CHECK(names(reduced.timings) == std::vector<std::string>{"refine", "assembly", "reduction"});
  CHECK(reduced.basis.Phi.cols() == 6);
  CHECK(reduced.sid.nq() == 0);
}

TEST_CASE("prepare() gives a hierarchical body its coarse model's transfer", "[pipeline][thb]") {
  const prep::PreparedBody prepared = prep::prepare(prep::read_model_file(std::string(ISOSID_MODELS_DIR) + "/sphere_axisym_thb.model.toml"));
  CHECK(names(prepared.timings) == std::vector<std::string>{"refine", "assembly", "mass", "coarse_model", "reduction", "sid_terms"});
  REQUIRE(prepared.sid.transfer);
  CHECK(prepared.sid.transfer->coarse_to_fine.rows() == prepared.sid.nq());
  CHECK(prepared.sid.transfer->coarse_model_sha256 == prepared.sid.provenance.model_sha256);
  const Eigen::MatrixXd round = prepared.sid.transfer->fine_to_coarse * prepared.sid.transfer->coarse_to_fine;
  CHECK((round - Eigen::MatrixXd::Identity(round.rows(), round.cols())).cwiseAbs().maxCoeff() < 1e-10);
}

TEST_CASE("analyse_modes() finds the rigid-body modes of free bodies", "[pipeline][modes]") {
  using format::AnalysisType;
  struct Case {
    std::string what;
    prep::ModelSpec spec;
    int rigid;
  };
  const std::vector<Case> cases = {
      {"golden sphere", golden_model("sphere_small"), 1},
      {"rectangle", test::spec_for(prep::primitives::rectangle(0.3, 0.1), AnalysisType::PlaneStress, 7e10, 0.33, 2700, test::uniform({2, 2}, {6, 2})), 3},
      {"ball", test::spec_for(prep::primitives::ball(0.01), AnalysisType::Solid, 7.28e10, 0.33, 2789, test::uniform({2, 2, 2}, {2, 2, 1})), 6}};
  for (const Case& c : cases) {
    INFO(c.what);
    const prep::ModalAnalysis a = prep::analyse_modes(c.spec, 10);
    CHECK(a.modes.rigid_body_modes == c.rigid);
    CHECK(a.modes.frequencies_hz().size() == 10);
    CHECK(names(a.timings) == std::vector<std::string>{"refine", "assembly", "mass", "eigen"});
  }
  CHECK(prep::analyse_modes(cases[1].spec, 4).mass == Approx(0.3 * 0.1 * 2700).epsilon(1e-12));  // unit thickness
  CHECK(prep::analyse_modes(cases[0].spec, 4).mass ==
        Approx(format::read_sid(std::string(ISOSID_GOLDEN_DIR) + "/sphere_small.sid.h5").refmod.mass).epsilon(1e-12));
}

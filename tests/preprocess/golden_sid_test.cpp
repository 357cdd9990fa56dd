// Regression: the committed golden SIDs are reproduced by today's isosid-prep, compared with
// isosid-diff (frequencies, invariants, reduced matrices, mode subspaces; rtol 1e-6 leaves
// room for round-off differences between machines, not for changed physics).
#include "support/run_program.hpp"

#include <catch2/catch.hpp>
#include <fstream>

using namespace isosid;

namespace {
void check_golden(const std::string& name) {
  const test::ScratchDir dir("golden");
  const std::string golden = std::string(ISOSID_GOLDEN_DIR) + "/" + name;
  const auto prep = test::run_program(std::string(ISOSID_PREP_EXE) + " -q " + golden + ".model.toml -o " + dir.path("new.sid.h5"));
  REQUIRE(prep.exit_status == 0);
  const auto diff = test::run_program(std::string(ISOSID_DIFF_EXE) + " --rtol 1e-6 " + golden + ".sid.h5 " + dir.path("new.sid.h5"));
  INFO(diff.out << diff.err);
  CHECK(diff.exit_status == 0);
}
}  // namespace

TEST_CASE("golden SID: small axisymmetric Craig-Bampton sphere", "[golden]") { check_golden("sphere_small"); }
TEST_CASE("golden SID: small 3D modal beam", "[golden]") { check_golden("beam_small"); }

TEST_CASE("a changed model no longer matches its golden SID", "[golden]") {
  const test::ScratchDir dir("golden-changed");
  const std::string golden = std::string(ISOSID_GOLDEN_DIR) + "/beam_small";
  std::ifstream in(golden + ".model.toml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  text.replace(text.find("density = 7800.0"), 16, "density = 7810.0");
  std::ofstream(dir.path("changed.model.toml")) << text;
  REQUIRE(test::run_program(std::string(ISOSID_PREP_EXE) + " -q " + dir.path("changed.model.toml") + " -o " + dir.path("c.sid.h5"))
              .exit_status == 0);
  const auto diff = test::run_program(std::string(ISOSID_DIFF_EXE) + " " + golden + ".sid.h5 " + dir.path("c.sid.h5"));
  CHECK(diff.exit_status == 1);
  CHECK(diff.out.find("mass") != std::string::npos);
}

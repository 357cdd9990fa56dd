// Study files and their cases without running any: the grid's order, zipped values, a Latin
// hypercube's strata, ranges, values found in a summary by dotted path, and refused study files.
#include "case_run.hpp"
#include "dispatch.hpp"
#include "study_file.hpp"
#include "support/run_program.hpp"
#include "support/scene_text.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <set>

using namespace isosid;
using Catch::Matchers::Contains;

namespace {
sweep::Study study_of(const test::ScratchDir& dir, const std::string& text) {
  std::ofstream(dir.path("s.study.toml")) << "scene = \"s.scene.toml\"\n" << text;
  return sweep::read_study_file(dir.path("s.study.toml"));
}
}  // namespace

TEST_CASE("sweep: a grid's cases vary the last parameter fastest, zip pairs values, ranges end where given", "[sweep][unit]") {
  const test::ScratchDir dir("study_plan");
  const sweep::Study grid = study_of(dir, "[[parameter]]\nkey = \"a\"\nvalues = [1, 2]\n[[parameter]]\nkey = \"b.c\"\n"
                                          "range = [1e17, 1e19]\ncount = 3\nspacing = \"log\"\n");
  const std::vector<sweep::Case> cases = sweep::plan_cases(grid);
  REQUIRE(cases.size() == 6);
  CHECK(cases[0].settings[0].value == "1");
  CHECK(cases[0].settings[1].value == "1e+17");  // the ends exactly as given
  CHECK(std::stod(cases[1].settings[1].value) == Approx(1e18).epsilon(1e-12));  // evenly in the logarithm
  CHECK(cases[2].settings[1].value == "1e+19");
  CHECK(cases[3].settings[0].value == "2");
  CHECK(cases[5].index == 5);
  CHECK(cases[5].settings[1].key == "b.c");
  const sweep::Study zip = study_of(dir, "sampling = \"zip\"\n[[parameter]]\nkey = \"a\"\nvalues = [0.1, \"x\", [1, 2]]\n"
                                         "[[parameter]]\nkey = \"b\"\nvalues = [true, 2.5, -3]\n");
  const std::vector<sweep::Case> zipped = sweep::plan_cases(zip);
  REQUIRE(zipped.size() == 3);
  CHECK(zipped[0].settings[0].value == "0.1");  // the shortest text that reads back exactly
  CHECK(zipped[1].settings[0].value == "'x'");
  CHECK(zipped[2].settings[0].value == "[ 1, 2 ]");
  CHECK(zipped[0].settings[1].value == "true");
  CHECK(zipped[2].settings[1].value == "-3");
}

TEST_CASE("sweep: keys set together take one list of values per case, each key its own setting", "[sweep][unit]") {
  const test::ScratchDir dir("study_together");
  const sweep::Study study = study_of(dir, "[[parameter]]\nkey = [\"p.0\", \"model.beam.t\", \"model.beam.i\"]\n"
                                           "values = [[0.1, 0.5, [1, 2]], [0.2, 0.6, [3, 4]]]\n[[parameter]]\nkey = \"v\"\nvalues = [1, 2, 3]\n");
  REQUIRE(study.parameters.size() == 2);
  CHECK(study.parameters[0].name() == "p.0 + model.beam.t + model.beam.i");
  const std::vector<sweep::Case> cases = sweep::plan_cases(study);
  REQUIRE(cases.size() == 6);  // the group is one parameter of the grid
  REQUIRE(cases[4].settings.size() == 4);
  CHECK(cases[4].settings[0].key == "p.0");
  CHECK(cases[4].settings[0].value == "0.2");
  CHECK(cases[4].settings[1].value == "0.6");
  CHECK(cases[4].settings[2].key == "model.beam.i");
  CHECK(cases[4].settings[2].value == "[ 3, 4 ]");
  CHECK(cases[4].settings[3].value == "2");
}

TEST_CASE("sweep: a Latin hypercube puts one point in every stratum of each range, the same for the same seed", "[sweep][unit]") {
  const test::ScratchDir dir("study_lhs");
  const std::string text = "sampling = \"latin_hypercube\"\nsamples = 40\nseed = 7\n[[parameter]]\nkey = \"v\"\nrange = [0.1, 0.5]\n"
                           "[[parameter]]\nkey = \"p\"\nrange = [1e16, 1e18]\nspacing = \"log\"\n";
  const std::vector<sweep::Case> a = sweep::plan_cases(study_of(dir, text)), b = sweep::plan_cases(study_of(dir, text));
  REQUIRE(a.size() == 40);
  std::set<int> strata_v, strata_p;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double v = std::stod(a[i].settings[0].value), p = std::stod(a[i].settings[1].value);
    CHECK(v >= 0.1);
    CHECK(v < 0.5);
    strata_v.insert(int((v - 0.1) / 0.4 * 40));
    strata_p.insert(int(std::log(p / 1e16) / std::log(100.0) * 40));  // equal strata of the logarithm
    CHECK(a[i].settings[0].value == b[i].settings[0].value);  // reproducible from the seed
  }
  CHECK(strata_v.size() == 40);
  CHECK(strata_p.size() == 40);
  const std::vector<sweep::Case> other = sweep::plan_cases(study_of(dir, test::replace(text, "seed = 7", "seed = 8")));
  CHECK(other[0].settings[0].value != a[0].settings[0].value);
}

TEST_CASE("sweep: values in a summary by dotted path, list entries by number, name or label", "[sweep][unit]") {
  const nlohmann::json summary = nlohmann::json::parse(R"({"contacts": [{"name": "impact", "peak_force_n": 51.7,
      "impact_modes": {"modes": [{"label": "1F", "energy_ratio": 0.02}, {"label": "3F", "energy_ratio": 0.01}]}}], "steps": 9})");
  CHECK(sweep::value_at(summary, "contacts.impact.peak_force_n") == 51.7);
  CHECK(sweep::value_at(summary, "contacts.0.peak_force_n") == 51.7);
  CHECK(sweep::value_at(summary, "contacts.impact.impact_modes.modes.3F.energy_ratio") == 0.01);
  CHECK(sweep::value_at(summary, "steps") == 9);
  CHECK(sweep::value_at(summary, "contacts.other.peak_force_n").is_null());
  CHECK(sweep::value_at(summary, "steps.x").is_null());
  CHECK(sweep::value_at(summary, "contacts.5").is_null());
}

TEST_CASE("sweep: study files that cannot make a study are refused naming the field", "[sweep][unit]") {
  const test::ScratchDir dir("study_bad");
  const auto refused = [&](const std::string& text, const std::string& problem) {
    INFO(text);
    CHECK_THROWS_WITH(study_of(dir, text), Contains(problem));
  };
  refused("", "parameter: a study needs at least one [[parameter]]");
  refused("[[parameter]]\nkey = \"a\"\n", "values: give either values (a list) or a range [from, to]");
  refused("[[parameter]]\nkey = \"a\"\nvalues = []\n", "values: must be a non-empty list");
  refused("[[parameter]]\nkey = \"a\"\nrange = [1, 2]\n", "count");
  refused("[[parameter]]\nkey = \"a\"\nrange = [0, 2]\ncount = 2\nspacing = \"log\"\n", "range: a log spacing needs positive ends");
  refused("sampling = \"random\"\n[[parameter]]\nkey = \"a\"\nvalues = [1]\n", "sampling: must be \"grid\", \"zip\" or \"latin_hypercube\"");
  refused("sampling = \"zip\"\n[[parameter]]\nkey = \"a\"\nvalues = [1]\n[[parameter]]\nkey = \"b\"\nvalues = [1, 2]\n",
          "needs as many values of 'b' as of 'a'");
  refused("sampling = \"latin_hypercube\"\nsamples = 4\n[[parameter]]\nkey = \"a\"\nvalues = [1]\n", "a Latin hypercube samples ranges");
  refused("seed = 3\n[[parameter]]\nkey = \"a\"\nvalues = [1]\n", "seed: only for sampling = \"latin_hypercube\"");
  refused("[[parameter]]\nkey = \"a\"\nvalues = [1]\n[[parameter]]\nkey = \"a\"\nvalues = [2]\n", "key 'a' is varied twice");
  refused("[[parameter]]\nkey = \"a\"\nrange = [1, 2]\ncount = 100000\n[[parameter]]\nkey = \"b\"\nrange = [1, 2]\ncount = 100\n",
          "more than 1e6");
  refused("[[parameter]]\nkey = \"a\"\nvalues = [1]\nstep = 2\n", "step");
  refused("[[parameter]]\nkey = [\"a\", \"b\"]\nvalues = [[1, 2], [3]]\n", "with 2 keys set together, each value is a list of 2");
  refused("[[parameter]]\nkey = [\"a\", \"b\"]\nvalues = [1, 2]\n", "each value is a list of 2 (one per key)");
  refused("[[parameter]]\nkey = [\"a\", \"b\"]\nrange = [1, 2]\ncount = 2\n", "keys set together take values");
  refused("[[parameter]]\nkey = [\"a\", \"b\"]\nvalues = [[1, 2]]\n[[parameter]]\nkey = \"b\"\nvalues = [2]\n", "key 'b' is varied twice");
  refused("[[parameter]]\nkey = \"model.sphere\"\nvalues = [1]\n", "a model key is model.<body>.<key into its model file>");
  refused("[[parameter]]\nkey = \"a..b\"\nvalues = [1]\n", "'a..b' is not a dotted key");
}

TEST_CASE("sweep: ranks building SIDs side by side share their node's cores", "[sweep][unit]") {
  using isosid::sweep::prep_threads_per_rank;
  CHECK(prep_threads_per_rank(1, 2, 2) == 1);     // two ranks bound to a core each
  CHECK(prep_threads_per_rank(8, 16, 4) == 4);    // four ranks bound to a socket of 8 each
  CHECK(prep_threads_per_rank(16, 16, 4) == 4);   // four ranks unbound
  CHECK(prep_threads_per_rank(16, 16, 1) == 16);  // one rank: the whole node
  CHECK(prep_threads_per_rank(2, 2, 8) == 1);     // more ranks than cores: one thread each
}

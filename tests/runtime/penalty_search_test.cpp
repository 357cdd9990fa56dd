// [R2] Fig. 3's penalty trial (docs/references.md) as a decision rule (adapt/penalty_search): the
// steps of eq. 8's c_p = m 10^e, and which probe ends the quick increase and why. The runs that use
// it are in adaptive_run_test.cpp.
#include "adapt/penalty_search.hpp"

#include <catch2/catch.hpp>
#include <vector>

using namespace isosid::run;

namespace {
/// A search from the penalty `start` that has recorded these probes in turn.
PenaltySearch probed(double start, const std::vector<PenaltyProbe>& probes) {
  PenaltySearch search(PenaltyFactor{start});
  for (const PenaltyProbe& p : probes) search.record(p);
  return search;
}
}  // namespace

TEST_CASE("penalty factor: quick increase by decades, slow decrease by the leading digit ([R2] eq. 8)", "[runtime][adaptive]") {
  // exact in binary to the last bit is not the point: one unit of the leading digit off, to round-off
  CHECK(PenaltyFactor(5e18).raised().value() == Approx(5e19).epsilon(1e-15));
  CHECK(PenaltyFactor(5e18).lowered().value() == Approx(4e18).epsilon(1e-15));
  CHECK(PenaltyFactor(2e18).lowered().value() == Approx(1e18).epsilon(1e-15));
  CHECK(PenaltyFactor(1e18).lowered().value() == Approx(9e17).epsilon(1e-15));   // [R2]: 1e19 down to 9e18
  CHECK(PenaltyFactor(3.93e17).lowered().value() == Approx(2.93e17).epsilon(1e-15));
  CHECK(PenaltyFactor(1.5e17).lowered().value() == Approx(1.4e17).epsilon(1e-15));
  CHECK(PenaltyFactor(1e-3).lowered().value() == Approx(9e-4).epsilon(1e-15));  // powers of ten whose log10 rounds down
  // nine steps take 9e17 to 9e16 through 8e17 .. 1e17
  PenaltyFactor p(9e17);
  for (int i = 0; i < 9; ++i) p = p.lowered();
  CHECK(p.value() == Approx(9e16).epsilon(1e-12));
}

TEST_CASE("penalty search: the increase stops where the force stops changing, at the lower penalty", "[runtime][adaptive]") {
  PenaltySearch search(PenaltyFactor(1e15));
  // a penalty layer in series with the contact: the force approaches 10 N as 1/(1 + k/c)
  auto force = [](double c) { return 10.0 / (1 + 1e17 / c); };
  while (!search.done()) {
    const PenaltyFactor c = search.next();
    search.record({c, force(c.value()), 100, ""});
  }
  // 1e19 -> 1e20 changes the force by 0.9 %, under kForceTolerance; 1e18 -> 1e19 by 9 %
  CHECK(search.result().value() == Approx(1e19));
  CHECK(search.probes().size() == 6);
  CHECK_THAT(search.reason(), Catch::Matchers::StartsWith("converged"));
}

TEST_CASE("penalty search: an error ends the increase at the last penalty without one", "[runtime][adaptive]") {
  const auto probe = [](double penalty, double force, long steps, const char* error = "") {
    return PenaltyProbe{PenaltyFactor(penalty), force, steps, error};
  };
  SECTION("a failed probe") {
    const PenaltySearch search = probed(1e15, {probe(1e15, 1.0, 100), probe(1e16, 2.0, 100, "the quasistatic modes did not converge")});
    REQUIRE(search.done());
    CHECK(search.result().value() == Approx(1e15));
    CHECK_THAT(search.reason(), Catch::Matchers::Contains("did not converge"));
  }
  SECTION("a probe that needs more than twice the steps for the same window") {
    CHECK_FALSE(probed(1e15, {probe(1e15, 1.0, 100), probe(1e16, 2.0, 200)}).done());  // twice: still fine
    const PenaltySearch search = probed(1e15, {probe(1e15, 1.0, 100), probe(1e16, 2.0, 200), probe(1e17, 3.0, 401)});
    REQUIRE(search.done());
    CHECK(search.result().value() == Approx(1e16));
    CHECK_THAT(search.reason(), Catch::Matchers::Contains("steps grew from 200 to 401"));
  }
  SECTION("an error at the start penalty lowers it one step (the seed's slow decrease)") {
    const PenaltySearch search = probed(5e22, {probe(5e22, 1.0, 100, "failed")});
    REQUIRE(search.done());
    CHECK(search.result().value() == Approx(4e22));
  }
  SECTION("a force that never settles: the last of kMaxProbes decades") {
    PenaltySearch search(PenaltyFactor(1));
    for (int i = 0; !search.done(); ++i) search.record({search.next(), double(1 << i), 100, ""});
    CHECK(search.probes().size() == std::size_t(PenaltySearch::kMaxProbes));
    CHECK(search.result().value() == Approx(1e7));
  }
}

// isosid-diff: are two SIDs the same body model? Exit 0 equal, 1 different, 2 bad input.
#include "isosid/common/cli_parse.hpp"
#include "isosid/format/sid_compare.hpp"
#include "isosid/format/sid_io.hpp"

#include <algorithm>
#include <cstdio>
#include <iostream>

int main(int argc, char** argv) {
  using namespace isosid::format;
  return isosid::common::run_guarded("isosid-diff", [&] {
    CLI::App app{"Compares two SID files: scalars, invariants, frequencies, reduced matrices, and mode bases\n"
                 "by principal angles (mode signs and rotations within repeated frequencies do not count).",
                 "isosid-diff"};
    std::string file_a, file_b;
    double rtol = 1e-6;
    app.add_option("a", file_a, "first SID file")->required();
    app.add_option("b", file_b, "second SID file")->required();
    app.add_option("--rtol", rtol, "relative tolerance (default 1e-6)")->check(isosid::common::kFiniteNonNegative);
    if (auto status = isosid::common::parse_command_line(app, argc, argv)) return *status;
    const Sid a = read_sid(file_a);
    const Sid b = read_sid(file_b);
    const Comparison c = compare_sids(a, b, rtol);
    double worst_sine = 0;
    for (const ModeCluster& cl : c.clusters) worst_sine = std::max(worst_sine, cl.max_sine);
    for (const std::string& note : c.notes) std::cout << "note: " << note << "\n";
    if (c.equal()) {
      std::printf("equal within rtol %g (%zu frequency clusters, largest principal-angle sine %.2e)\n", std::max(rtol, kComparisonRoundOff),
                  c.clusters.size(), worst_sine);
      return 0;
    }
    std::printf("%zu differences (rtol %g):\n", c.differences.size(), std::max(rtol, kComparisonRoundOff));
    for (const Difference& d : c.differences)
      std::printf("  %s: %s (difference %.3e, allowed %.3e)\n", d.what.c_str(), d.detail.c_str(), d.difference,
                  d.tolerance);
    return 1;
  });
}

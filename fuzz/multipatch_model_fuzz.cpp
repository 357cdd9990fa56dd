// Fuzz target: bodies of several patches. The model file is read, its patches' interfaces are
// found and checked for connectedness, and a small body (at most kMaxFuzzedControlPoints after
// its uniform refinement, no grading or THB) is built: knots made conforming across the
// interfaces, coincident control points merged into one DOF map. Bad input must end in
// InputError. Seeds: models/ and tests/golden with their multi-patch models.
#include "fuzz_input.hpp"
#include "model/body_model.hpp"
#include "model/model_file.hpp"
#include "model/patch_interfaces.hpp"

namespace {

/// Bodies larger than this are read and their interfaces checked, but not built: under the
/// sanitizers and coverage a build takes 20-40 times its Release time (the glued clamped beam,
/// 0.8 s in Release, took 14-35 s and ended a run at libFuzzer's 30 s limit at 2e4).
constexpr double kMaxFuzzedControlPoints = 5e3;

/// The control points the uniform refinement gives, or infinity if the spec grades or refines
/// hierarchically (whose counts depend on the geometry).
double uniform_control_points(const isosid::prep::ModelSpec& spec) {
  double total = 0;
  for (const isosid::prep::PatchSpec& p : spec.patches) {
    if (!p.refinement.graded.empty() || p.refinement.hierarchical) return INFINITY;
    const std::vector<int> counts = p.patch.counts();
    double points = 1;
    for (std::size_t d = 0; d < counts.size(); ++d) {
      const int split = d < p.refinement.subdivisions.size() ? p.refinement.subdivisions[d] : 1;
      const int degree = d < p.refinement.degrees.size() ? p.refinement.degrees[d] : p.patch.degrees[d];
      points *= (double(counts[d]) + std::max(0, degree - p.patch.degrees[d])) * std::max(split, 1) + degree;
    }
    total += points;
  }
  return total;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return isosid::fuzz::load_input(data, size, ".model.toml", [](const std::string& path) {
    const isosid::prep::ModelSpec spec = isosid::prep::read_model_file(path);
    if (spec.patches.size() < 2) return;
    if (spec.mesh)
      isosid::prep::find_mesh_interfaces(spec.patches);
    else
      isosid::prep::find_interfaces(spec.patches, spec.file);
    if (uniform_control_points(spec) <= kMaxFuzzedControlPoints) isosid::prep::build_body(spec);
  });
}

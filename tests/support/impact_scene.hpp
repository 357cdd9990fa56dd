// Test support: the scene text of the golden sphere's impact, shared by the in-process and the
// isosid-run tests.
#pragma once
#include <string>

namespace isosid::test {

/// The golden sphere (sphere_small, quasistatic high modes) dropped on a plane at 0.1 m/s for
/// 100 us, its SID at `sid`.
std::string golden_impact_scene(const std::string& sid);

}  // namespace isosid::test

// Scene texts for tests: the small golden sphere's impact on its symmetry plane (scene A on a
// coarse sphere), and editing a text in place.
#pragma once
#include <catch2/catch.hpp>
#include <string>

namespace isosid::test {

/// `text` with its first `from` replaced by `to` (which must be there).
inline std::string replace(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

/// The golden sphere (`golden_dir`/sphere_small.sid.h5) 0.1 um above its symmetry plane at
/// 0.1 m/s, with quasistatic high modes and the seed's penalty scaled to it; 100 us.
inline std::string golden_impact_scene(const std::string& golden_dir) {
  return R"(
[simulation]
dimension = "axisymmetric"
end_time = 100e-6
rtol = 1e-6
atol = 1e-12
output_interval = 1e-6
[[flexible_body]]
name = "sphere"
sid = ")" + golden_dir + R"(/sphere_small.sid.h5"
position = [0.0, 0.0100001, 0.0]
velocity = [0.0, -0.1, 0.0]
high_modes = "quasistatic"
[[fixed_plane]]
name = "ground"
normal = [0.0, 1.0, 0.0]
[[contact]]
name = "impact"
body = "sphere"
surface = "contact"
target = "ground"
penalty = 5e17
)";
}

}  // namespace isosid::test

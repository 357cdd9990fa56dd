// The golden sphere's impact scene; see impact_scene.hpp.
#include "support/impact_scene.hpp"

namespace isosid::test {

std::string golden_impact_scene(const std::string& sid) {
  return R"(
[simulation]
dimension = "axisymmetric"
end_time = 100e-6
rtol = 1e-6
atol = 1e-12
output_interval = 1e-6
[[flexible_body]]
name = "sphere"
sid = ")" + sid + R"("
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

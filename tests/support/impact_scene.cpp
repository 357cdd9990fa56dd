// Impact scenes of the tests; see impact_scene.hpp.
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

std::string free_beam_model() {
  return R"(
[body]
name = "beam"
analysis = "solid"
[material]
youngs_modulus = 2.1e11
poisson_ratio = 0.3
density = 7800.0
[geometry]
primitive = "box"
size = [0.1, 0.01, 0.015]
[refinement]
degrees = [2, 2, 2]
subdivisions = [12, 2, 2]
[[refinement.graded]]
direction = "xi"
toward = 0.5
smallest = 0.3e-3
growth = 1.6
[[refinement.graded]]
direction = "zeta"
toward = 0.5
smallest = 0.3e-3
growth = 1.6
[[contact_surface]]
name = "impact"
side = "top"
interval = [[0.49, 0.51], [0.45, 0.55]]
[reduction]
method = "macneal"
normal_modes = 12
boundary_surface = "impact"
[damping]
kappa = 0.0
)";
}

std::string sphere_on_free_beam_scene(const std::string& contact_lines, const std::string& velocity) {
  return R"(
[simulation]
dimension = "3d"
end_time = 40e-6
integrator = "leapfrog"
step = 0.1e-6
output_interval = 0.5e-6
[[flexible_body]]
name = "sphere"
sid = "sphere.sid.h5"
model = "sphere_impactor_macneal.model.toml"
position = [0.05, 0.015550001, 0.0075]
velocity = )" + velocity + R"(
[[flexible_body]]
name = "beam"
sid = "beam.sid.h5"
model = "beam.model.toml"
[[contact]]
name = "impact"
body = "sphere"
surface = "contact"
target = "beam"
target_surface = "impact"
)" + contact_lines;
}

std::string two_spheres(double v, const std::string& extra, const std::string& steps) {
  return R"([simulation]
dimension = "3d"
end_time = 2e-4
)" + steps + R"(output_interval = 1e-6
[[rigid_body]]
name = "a"
shape = "sphere"
radius = 0.01
density = 7850.0
position = [-0.0100001, 0.0, 0.0]
velocity = [)" + std::to_string(v) + R"(, 0.0, 0.0]
[[rigid_body]]
name = "b"
shape = "sphere"
radius = 0.01
density = 7850.0
position = [0.0100001, 0.0, 0.0]
velocity = [)" + std::to_string(-v) + R"(, 0.0, 0.0]
[[hertz_contact]]
name = "ab"
body = "a"
target = "b"
youngs_modulus = 2.1e11
poisson_ratio = 0.3
)" + extra;
}

}  // namespace isosid::test

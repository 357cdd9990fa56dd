// Impact scenes of the tests, from the fixtures in tests/scenes; see impact_scene.hpp.
#include "support/impact_scene.hpp"

#include "support/scene_text.hpp"

namespace isosid::test {

std::string golden_impact_scene(const std::string& sid) { return scene_fixture("golden_impact.scene.toml", {{"@SID@", sid}}); }

std::string free_beam_model() { return scene_fixture("free_beam.model.toml"); }

std::string sphere_on_free_beam_scene(const std::string& contact_lines, const std::string& velocity) {
  return scene_fixture("sphere_on_free_beam.scene.toml", {{"@VELOCITY@", velocity}}) + contact_lines;
}

std::string two_spheres(double v, const std::string& extra, const std::string& steps) {
  return scene_fixture("two_rigid_spheres.scene.toml", {{"@V@", std::to_string(v)}, {"@MINUS_V@", std::to_string(-v)}, {"@STEPS@", steps}}) + extra;
}

}  // namespace isosid::test

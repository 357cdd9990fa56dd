// Test support: impact scenes shared by tests: the golden sphere's on a plane (in-process and
// isosid-run tests), the seed sphere's on a short free beam (impact modes, gap space), and two
// rigid spheres meeting by Hertz's law.
#pragma once
#include <string>

namespace isosid::test {

/// A short free-free steel beam (100 x 10 x 15 mm, bending in y lowest), graded to 0.3 mm under
/// the centre of its top face, a MacNeal model whose massless boundary is the contact surface
/// "impact" there.
std::string free_beam_model();
/// models/sphere_impactor_macneal.model.toml's sphere (sphere.sid.h5) dropped on that beam
/// (beam.model.toml, beam.sid.h5) at `velocity` (m/s, world; its y the approach), its lower pole
/// 1 nm above the centre of the top face; 40 us of the leapfrog at 0.1 us. The text ends in
/// the contact's table, followed by `contact_lines`.
std::string sphere_on_free_beam_scene(const std::string& contact_lines, const std::string& velocity = "[0.0, -1.1, 0.0]");

/// The golden sphere (sphere_small, quasistatic high modes) dropped on a plane at 0.1 m/s for
/// 100 us, its SID at `sid`.
std::string golden_impact_scene(const std::string& sid);

/// Two rigid steel spheres (r = 10 mm) 0.2 um apart, closing head-on along x at v each, their
/// contact by Hertz's law ("ab"), for 200 us; `steps`: the integrator's tolerances and step
/// limit, `extra`: tables after the contact's.
std::string two_spheres(double v, const std::string& extra = "",
                        const std::string& steps = "rtol = 1e-10\natol = 1e-14\nmax_step = 2e-8\n");

}  // namespace isosid::test

// The modal view of an impact of [R3] (output/impact_modes; docs/references.md): its sphere drops
// centrically on a short free-free steel beam, both MacNeal models. The report must close the
// energy balance, keep each mode's energy after the release, excite only the symmetric (odd)
// bending modes of a centric impact, and label the bending modes in the impact direction; a
// monitor on the massless boundary moves with it.
#include "isosid/format/hdf5_file.hpp"
#include "scene_runner.hpp"
#include "support/impact_scene.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>

using namespace isosid;
using nlohmann::json;

TEST_CASE("impact modes: energies, restitution and bending labels of a centric impact on a free beam", "[runtime][massless][impact-modes]") {
  const test::ScratchDir dir("impact-modes");
  test::write_coarse_sphere_impactor(dir);
  // 100 x 10 x 15 mm, bending in y (10 mm) lowest; graded to 0.3 mm under the centre of the top face
  std::ofstream(dir.path("beam.model.toml")) << test::free_beam_model();
  const double v0 = 1.1, sphere_mass = 5.58e-3, beam_mass = 7800 * 0.1 * 0.01 * 0.015;
  const json s = test::run_scene(dir, test::sphere_on_free_beam_scene("") + R"(
[[monitor]]
name = "under"
body = "beam"
surface = "impact"
parameter = [0.5, 0.5]
quantity = "velocity"
)");
  REQUIRE(s["contacts"][0].contains("impact_modes"));
  const json& im = s["contacts"][0]["impact_modes"];
  const double E0 = im["kinetic_energy_j"].get<double>(), v_after = im["separation_velocity_m_s"].get<double>();
  CHECK(E0 == Approx(0.5 * sphere_mass * v0 * v0).epsilon(1e-3));  // the SID's mass: 5.58 g to the density's 4 digits
  CHECK(im["direction"][1].get<double>() == Approx(-1.0));
  CHECK(v_after < 0);  // rebounds

  // where E_0 went: the beam's modes, the beam's and the sphere's rigid motion, the sphere's
  // modes. The run conserves energy to its error (below 1e-4 here), the leapfrog's modal
  // energies beat by (omega dt)^2 / 4 < 1e-4 up to the 47 kHz mode
  const json& beam = s["bodies"][1];
  const json& sphere = s["bodies"][0];
  double sphere_modes = 0;
  for (const json& e : sphere["final_modal_energy_j"]) sphere_modes += e.get<double>();
  const double v_beam = beam["final_velocity"][1].get<double>();
  const double balance = im["energy_ratio_total"].get<double>() + (v_after * v_after) / (v0 * v0) +
                         0.5 * beam_mass * v_beam * v_beam / E0 + sphere_modes / E0;
  CHECK(balance == Approx(1.0).epsilon(1e-3));

  std::map<std::string, json> bending;
  int at_rest = 0;
  for (const json& m : im["modes"]) {
    // after the release each mode vibrates freely: its energy at the end of the run is the one
    // reported, to the leapfrog's beat of a modal energy, (omega dt)^2 / 4 < 1e-4 up to 47 kHz
    const double reported = m["energy_ratio"].get<double>() * E0;
    const double final_energy = beam["final_modal_energy_j"][m["index"].get<std::size_t>()].get<double>();
    CHECK(std::abs(reported - final_energy) <= 2e-4 * final_energy + 1e-15 * E0);
    // a mode left at rest returns the sphere's own rebound: r_k = -v(t_E) / v(t_S)
    if (m["energy_ratio"].get<double>() < 1e-20) {
      ++at_rest;
      CHECK(m["restitution"].get<double>() == Approx(-v_after / v0).epsilon(1e-12));
    }
    if (!m["label"].is_null()) bending[m["label"].get<std::string>()] = m;
  }
  CHECK(at_rest >= 4);  // the antisymmetric modes of a centric impact (2F and 4F among them)
  // the lowest mode bends in y, the impact direction (Euler-Bernoulli 5.34 kHz; shear and rotary
  // inertia lower it by ~3 % at L/h = 10); the next one bends in z (15 mm) and is no 'F' mode
  REQUIRE(bending.count("1F"));
  CHECK(bending["1F"]["index"].get<int>() == 0);
  CHECK(bending["1F"]["frequency_hz"].get<double>() == Approx(5340).epsilon(0.05));
  CHECK(im["modes"][1]["label"].is_null());
  // a centric impact excites the symmetric bending modes and leaves the antisymmetric ones at rest
  REQUIRE(bending.count("4F"));
  CHECK(bending["1F"]["energy_ratio"].get<double>() > 0.01);
  CHECK(bending["3F"]["energy_ratio"].get<double>() > 0.01);
  CHECK(bending["2F"]["energy_ratio"].get<double>() < 1e-12);
  CHECK(bending["4F"]["energy_ratio"].get<double>() < 1e-12);

  // results.h5 holds the same report
  const format::h5::Reader results(dir.path("out-s.scene.toml/results.h5"));
  const Eigen::VectorXd ratio = results.vector("/contacts/impact/impact_modes/energy_ratio");
  REQUIRE(ratio.size() == Eigen::Index(im["modes"].size()));
  CHECK(ratio(0) == Approx(bending["1F"]["energy_ratio"].get<double>()));
  CHECK(results.strings("/contacts/impact/impact_modes/label")[0] == "1F");

  // the beam's surface under the sphere lies on the massless boundary, whose coordinates are
  // solved, not integrated: the monitor takes their rate over the last step. At the peak force
  // the approach stops, and the surface moves with the sphere (to the sample's distance from
  // the peak: the sphere's velocity changes by F/m * 0.25 us = 0.03 m/s there; measured 0.022)
  const Eigen::VectorXd t = results.vector("/time");
  const Eigen::MatrixXd F = results.matrix("/contacts/impact/force"), v_sphere = results.matrix("/bodies/sphere/velocity"),
                        v_under = results.matrix("/monitors/under");
  Eigen::Index peak = 0;
  F.col(1).maxCoeff(&peak);
  INFO("at the peak, " << t(peak) << " s: sphere " << v_sphere(peak, 1) << " m/s, surface under it " << v_under(peak, 1) << " m/s");
  CHECK(std::abs(v_under(peak, 1) - v_sphere(peak, 1)) < 0.05 * v0);
  CHECK(v_under(peak, 1) < -0.1);  // pressed down, well beyond the beam's rigid motion
}

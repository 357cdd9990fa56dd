// A SID written and read back is identical to the last bit, including lists in their order.
#include "isosid/format/sid_io.hpp"
#include "support/lumped_sid.hpp"
#include "support/run_program.hpp"

#include <catch2/catch.hpp>

using namespace isosid;
using format::Sid;
using format::Taylor;

namespace {
void require_identical(const Taylor& a, const Taylor& b) {
  REQUIRE(a.M0.rows() == b.M0.rows());
  REQUIRE(a.M0.cols() == b.M0.cols());
  CHECK(a.M0 == b.M0);
  REQUIRE(a.M1.size() == b.M1.size());
  for (std::size_t k = 0; k < a.M1.size(); ++k) CHECK(a.M1[k] == b.M1[k]);
}
}  // namespace

TEST_CASE("SID write/read round trip is bit-exact", "[format][io]") {
  const test::ScratchDir dir("roundtrip");
  Sid a = test::lumped_sid(test::random_lumped_body(12, 5, 7));
  a.contact_surfaces[0].in_interface = Eigen::Vector4i(1, 1, 0, 1);  // (a Craig-Bampton SID's)
  format::write_sid(a, dir.path("body.sid.h5"));
  const Sid b = format::read_sid(dir.path("body.sid.h5"));

  CHECK(b.body_name == a.body_name);
  CHECK(b.analysis == a.analysis);
  CHECK(b.material.youngs_modulus == a.material.youngs_modulus);
  CHECK(b.material.poisson_ratio == a.material.poisson_ratio);
  CHECK(b.material.density == a.material.density);
  CHECK(b.thickness == a.thickness);
  CHECK(b.refmod.mass == a.refmod.mass);
  CHECK(b.refmod.frequencies_hz == a.refmod.frequencies_hz);
  CHECK(b.refmod.mode_names == a.refmod.mode_names);
  CHECK(b.refmod.n_low == a.refmod.n_low);
  CHECK(b.refmod.reduction_method == a.refmod.reduction_method);
  CHECK(b.damping.alpha1 == a.damping.alpha1);
  CHECK(b.damping.alpha2 == a.damping.alpha2);
  CHECK(b.damping.kappa == a.damping.kappa);
  for (const Taylor Sid::*term : {&Sid::mdCM, &Sid::J, &Sid::Ct, &Sid::Cr, &Sid::Me, &Sid::Gr, &Sid::Ge, &Sid::Oe,
                                  &Sid::ksigma, &Sid::Ke, &Sid::De})
    require_identical(a.*term, b.*term);

  REQUIRE(b.nodes.size() == a.nodes.size());
  CHECK(b.nodes[0].name == a.nodes[0].name);
  require_identical(a.nodes[0].origin, b.nodes[0].origin);
  require_identical(a.nodes[0].AP, b.nodes[0].AP);
  CHECK(b.nodes[0].phi == a.nodes[0].phi);
  CHECK(b.nodes[0].psi == a.nodes[0].psi);

  REQUIRE(b.contact_surfaces.size() == 1);
  const auto &ca = a.contact_surfaces[0], &cb = b.contact_surfaces[0];
  CHECK(cb.side == ca.side);
  CHECK(cb.master_patch == ca.master_patch);
  CHECK(cb.parameter == ca.parameter);
  CHECK(cb.element == ca.element);
  CHECK(cb.position == ca.position);
  CHECK(cb.normal == ca.normal);
  CHECK(cb.weight == ca.weight);
  CHECK(cb.Psi == ca.Psi);
  CHECK(cb.in_interface == ca.in_interface);

  REQUIRE(b.master_patches.size() == 1);
  CHECK(b.master_patches[0].degrees == a.master_patches[0].degrees);
  CHECK(b.master_patches[0].knots[1] == a.master_patches[0].knots[1]);
  CHECK(b.master_patches[0].control_points == a.master_patches[0].control_points);
  CHECK(b.master_patches[0].Phi == a.master_patches[0].Phi);

  REQUIRE(b.stress_recovery.size() == 1);
  CHECK(b.stress_recovery[0].components == a.stress_recovery[0].components);
  CHECK(b.stress_recovery[0].S == a.stress_recovery[0].S);

  REQUIRE(b.transfer.has_value());
  CHECK(b.transfer->coarse_to_fine == a.transfer->coarse_to_fine);
  CHECK(b.transfer->fine_to_coarse == a.transfer->fine_to_coarse);
  REQUIRE(b.visual.has_value());
  CHECK(b.visual->corners_per_cell == a.visual->corners_per_cell);
  CHECK(b.visual->position == a.visual->position);
  CHECK(b.visual->cells == a.visual->cells);
  CHECK(b.visual->Phi == a.visual->Phi);
  CHECK(b.visual->stress_components == a.visual->stress_components);
  CHECK(b.visual->S == a.visual->S);
  CHECK(b.provenance.timings_s == a.provenance.timings_s);
  CHECK(b.provenance.model_sha256 == a.provenance.model_sha256);

  // a reader that needs no viewing mesh (a run without ParaView output) skips it, and only it
  format::ReadOptions without_visual;
  without_visual.visual = false;
  const Sid c = format::read_sid(dir.path("body.sid.h5"), without_visual);
  CHECK_FALSE(c.visual.has_value());
  CHECK(c.Ke.M0 == b.Ke.M0);
  CHECK(c.contact_surfaces.size() == b.contact_surfaces.size());
}

TEST_CASE("lists keep the order in which they were written", "[format][io]") {
  const test::ScratchDir dir("order");
  Sid a = test::lumped_sid(test::random_lumped_body(8, 3, 1));
  for (const char* name : {"zeta", "alpha", "mid"}) {
    format::Node n = a.nodes[0];
    n.name = name;
    a.nodes.push_back(n);
  }
  format::write_sid(a, dir.path("b.sid.h5"));
  const Sid b = format::read_sid(dir.path("b.sid.h5"));
  REQUIRE(b.nodes.size() == 4);
  CHECK(b.nodes[1].name == "zeta");
  CHECK(b.nodes[2].name == "alpha");
  CHECK(b.nodes[3].name == "mid");
}

TEST_CASE("an order-0 SID without optional parts round-trips", "[format][io]") {
  const test::ScratchDir dir("minimal");
  Sid a = test::lumped_sid(test::random_lumped_body(6, 2, 3));
  a.nodes.clear();
  a.contact_surfaces.clear();
  a.master_patches.clear();
  a.stress_recovery.clear();
  a.transfer.reset();
  a.visual.reset();
  a.J.M1.clear();
  format::write_sid(a, dir.path("m.sid.h5"));
  const Sid b = format::read_sid(dir.path("m.sid.h5"));
  CHECK(b.nodes.empty());
  CHECK_FALSE(b.transfer.has_value());
  CHECK_FALSE(b.visual.has_value());
  CHECK(b.J.order() == 0);
  CHECK(b.J.M0 == a.J.M0);
}

// Section-translation shares (sid/section_translation): how much of a mode's kinetic energy its
// cross-sections carry as whole translations, from which isosid-run labels a beam's bending
// modes. Exact for rigid motions; for the modes of a free steel beam against beam theory.
#include "geometry/primitives.hpp"
#include "reduce/modal_analysis.hpp"
#include "sid/section_translation.hpp"
#include "sid/sid_builder.hpp"
#include "preprocess/body_fixtures.hpp"

#include <catch2/catch.hpp>

using namespace isosid;
using format::AnalysisType;

namespace {
struct Beam {
  test::AssembledBody body;
  prep::SparseMatrix scalar_mass;
};

/// A free steel bar along x, size lx x ly x lz, quadratic, `parts` elements per direction.
Beam bar(double lx, double ly, double lz, std::vector<int> parts) {
  const prep::ModelSpec spec = test::spec_for(prep::primitives::box(lx, ly, lz), AnalysisType::Solid, 2.1e11, 0.3, 7800,
                                              test::uniform({2, 2, 2}, std::move(parts)));
  Beam b{test::assembled(spec), {}};
  b.scalar_mass = prep::assemble_scalar_mass(b.body.body.space, b.body.body.dofs, b.body.body.elasticity);
  return b;
}
}  // namespace

TEST_CASE("section translation: rigid motions exactly, a beam's modes as beam theory says", "[section][sid]") {
  const Beam b = bar(0.2, 0.01, 0.015, {16, 2, 2});
  const Eigen::MatrixXd& X = b.body.body.dofs.node_points();
  const Eigen::Index nodes = X.rows();

  SECTION("translations carry all their energy along their direction; a spin about the long axis none") {
    Eigen::MatrixXd fields = Eigen::MatrixXd::Zero(3 * nodes, 4);
    const Eigen::Vector3d center(0.1, 0.005, 0.0075);
    for (Eigen::Index i = 0; i < nodes; ++i) {
      for (int a = 0; a < 3; ++a) fields(3 * i + a, a) = 1.0;
      const Eigen::Vector3d p = X.row(i).transpose();
      const Eigen::Vector3d spin = Eigen::Vector3d::UnitX().cross(p - center);
      fields.block(3 * i, 3, 3, 1) = spin;
    }
    const prep::SectionTranslation s = prep::section_translation(fields, X, b.scalar_mass);
    CHECK(s.long_axis.cwiseAbs().isApprox(Eigen::Vector3d::UnitX(), 1e-12));
    // sums of the same mass lumps: exact to round-off
    CHECK(s.shares.topRows(3).isApprox(Eigen::Matrix3d::Identity(), 1e-12));
    // the sections' mean of a spin about their centre line vanishes by the mesh's symmetry
    CHECK(s.shares.row(3).cwiseAbs().maxCoeff() < 1e-12);
  }

  SECTION("bending modes move their sections along their direction, torsion does not move them") {
    const prep::ModalResult modes = prep::lowest_modes(b.body.sys.K, b.body.sys.M, 16, b.body.scale);
    const Eigen::MatrixXd elastic = modes.modes.rightCols(modes.modes.cols() - modes.rigid_body_modes);
    const prep::SectionTranslation s =
        prep::section_translation(prep::nodal_modes(b.body.body.dofs, elastic), X, b.scalar_mass);
    const Eigen::VectorXd f = modes.frequencies_hz().tail(elastic.cols());
    // the lowest mode bends in y (10 mm, the thin direction): Euler-Bernoulli's 4.730^2/(2 pi)
    // sqrt(E I / (rho A)) / L^2 = 1334 Hz, shear and rotary inertia lower it by ~1 % at L/h = 20
    // (quadratic elements, 16 along the bar: within 3 %)
    CHECK(f(0) == Approx(1334.0).epsilon(0.03));
    // its sections translate along y with all but the rotary share (k r)^2 = (4.73/L)^2 h^2/12,
    // 0.5 %, and the cross-sections' Poisson breathing
    CHECK(s.shares(0, 1) > 0.98);
    CHECK(s.shares(0, 0) + s.shares(0, 2) < 1e-6);  // symmetric in x and z about the bar's centre
    int bending_y = 0, bending_z = 0, axial = 0, torsion = 0;
    for (Eigen::Index k = 0; k < s.shares.rows(); ++k) {
      INFO("mode " << k << " at " << f(k) << " Hz: shares " << s.shares.row(k));
      CHECK(s.shares.row(k).sum() < 1.0 + 1e-9);
      bending_y += s.shares(k, 1) > 0.8;
      bending_z += s.shares(k, 2) > 0.8;
      axial += s.shares(k, 0) > 0.8;
      torsion += s.shares.row(k).sum() < 0.05;  // twisting leaves each section's centre of mass at rest
    }
    // up to 16 kHz: bending in y 1334, 3680, 7210 Hz..., in z from 2000 Hz, the first axial
    // mode c/2L = 12.97 kHz, the first torsion mode: each class present
    CHECK(bending_y >= 3);
    CHECK(bending_z >= 2);
    CHECK(axial >= 1);
    CHECK(torsion >= 1);
  }

  SECTION("a body without a long axis has no shares") {
    const Beam cube = bar(0.01, 0.01, 0.01, {2, 2, 2});
    const Eigen::MatrixXd translation = Eigen::MatrixXd::Ones(3 * cube.body.body.dofs.node_count(), 1);
    CHECK(prep::section_translation(translation, cube.body.body.dofs.node_points(), cube.scalar_mass).shares.size() == 0);
  }
}

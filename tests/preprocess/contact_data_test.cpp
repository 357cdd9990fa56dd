// Contact data reproduce the body: weights sum to the surface's (2 pi r- or thickness-
// weighted) area, normals are outward unit vectors, N reproduces rigid translations, and
// Psi = N Phi. Areas to 1e-10: exact geometry, Gauss quadrature of smooth integrands on
// small elements. A Craig-Bampton SID's points within its interface take a point load as
// the full model does.
#include "geometry/primitives.hpp"
#include "reduce/body_reduction.hpp"
#include "sid/contact_data.hpp"
#include "sid/sid_builder.hpp"
#include "preprocess/body_fixtures.hpp"
#include "reduce/sparse_cholesky.hpp"
#include "support/run_program.hpp"
#include "support/scene_text.hpp"

#include <catch2/catch.hpp>
#include <fstream>

using namespace isosid;
using format::AnalysisType;

namespace {
prep::ModelSpec model(const std::string& name) { return prep::read_model_file(std::string(ISOSID_MODELS_DIR) + "/" + name); }

const prep::ContactSurfaceSpec& surface(const prep::ModelSpec& m) { return m.contact_surfaces.at(0); }

/// N applied to a rigid translation t of every node gives t at every point.
void check_translation(const prep::BodyModel& b, const prep::ContactSurfaceSpec& spec, const Eigen::VectorXd& t) {
  const auto N = prep::contact_shape_rows(b, spec);
  Eigen::VectorXd nodal(b.dofs.total_dofs());
  for (int n = 0; n < b.dofs.node_count(); ++n) nodal.segment(n * b.dofs.dim(), b.dofs.dim()) = t;
  const Eigen::VectorXd at_points = N * nodal;
  for (Eigen::Index g = 0; g < at_points.size() / b.dofs.dim(); ++g)
    CHECK((at_points.segment(g * b.dofs.dim(), b.dofs.dim()) - t).norm() < 1e-13 * t.norm());
}
}  // namespace

TEST_CASE("sphere contact cap: area 2 pi r^2 (1 - cos phi), outward normals, translations", "[contact]") {
  const auto spec = model("sphere_axisym.model.toml");
  const auto b = prep::build_body(spec);
  const auto s = prep::contact_points(b, surface(spec));
  const double r = 0.01;
  // the cap ends where the lower arc reaches the end of the surface's interval
  const Eigen::Vector2d end = spec.patches[0].patch.point(Eigen::Vector2d(spec.contact_surfaces.at(0).interval.at(0)[1], 0.0));
  const double cos_phi = -end(1) / r;
  CHECK(s.weight.sum() == Approx(2 * M_PI * r * r * (1 - cos_phi)).epsilon(1e-10));
  for (Eigen::Index g = 0; g < s.points(); ++g) {
    CHECK(s.normal.row(g).norm() == Approx(1.0).epsilon(1e-14));
    CHECK((s.normal.row(g) - s.position.row(g) / r).norm() < 1e-10);  // outward = radial on a sphere
  }
  check_translation(b, surface(spec), Eigen::Vector2d(0.3, -1.2));
}

TEST_CASE("disk contact arc: length times thickness", "[contact]") {
  const auto spec = model("disk_plane_strain.model.toml");
  const auto b = prep::build_body(spec);
  const auto s = prep::contact_points(b, surface(spec));
  const Eigen::Vector2d a = spec.patches[0].patch.point(Eigen::Vector2d(1.0, 0.3)), c = spec.patches[0].patch.point(Eigen::Vector2d(1.0, 0.7));
  const double angle = std::acos(a.dot(c) / (a.norm() * c.norm()));
  CHECK(s.weight.sum() == Approx(0.1 * angle * 1.0).epsilon(1e-10));
  for (Eigen::Index g = 0; g < s.points(); ++g) CHECK(s.position(g, 1) < 0);  // the bottom of the disk
  check_translation(b, surface(spec), Eigen::Vector2d(1.0, 2.0));
}

TEST_CASE("beam contact face: area and normals of a box face", "[contact]") {
  const auto spec = model("beam_free_free.model.toml");
  const auto b = prep::build_body(spec);
  const auto s = prep::contact_points(b, surface(spec));
  CHECK(s.weight.sum() == Approx(0.21 * 0.015).epsilon(1e-12));  // polynomial geometry: exact
  for (Eigen::Index g = 0; g < s.points(); ++g) CHECK((s.normal.row(g) - Eigen::RowVector3d(0, 1, 0)).norm() < 1e-14);
  check_translation(b, surface(spec), Eigen::Vector3d(1, -2, 3));
}

TEST_CASE("3D ball contact patch: area of the spherical cap on a revolved patch", "[contact]") {
  auto spec = model("ball_3d.model.toml");
  const auto b = prep::build_body(spec);
  const double r = 0.01;
  const Eigen::Vector3d end = spec.patches[0].patch.point(Eigen::Vector3d(0.25, 0.0, 0.0));
  const double exact = 2 * M_PI * r * r * (1 + end(1) / r);
  // the coarse quadratic 9-point circle makes the area integrand rational: p+1 points leave
  // 2.6e-7, 8 points per direction bring the quadrature error below 1e-10
  prep::ContactSurfaceSpec fine = surface(spec);
  fine.points_per_direction = 8;
  CHECK(prep::contact_points(b, fine).weight.sum() == Approx(exact).epsilon(1e-10));
  CHECK(prep::contact_points(b, surface(spec)).weight.sum() == Approx(exact).epsilon(1e-6));
  check_translation(b, surface(spec), Eigen::Vector3d(0.1, 0.2, -0.3));
}

TEST_CASE("the SID's Psi rows are N Phi and its master patch is the side's NURBS", "[contact]") {
  const auto spec = model("sphere_axisym.model.toml");
  const auto b = prep::build_body(spec);
  const auto sys = prep::assemble_system(b.space, b.dofs, b.elasticity);
  const auto Ms = prep::assemble_scalar_mass(b.space, b.dofs, b.elasticity);
  const auto basis = prep::reduce_body(b, sys);
  const auto sid = prep::build_sid(b, sys, Ms, basis);
  const Eigen::MatrixXd Phi = prep::nodal_modes(b.dofs, basis.Phi);
  const auto& c = sid.contact_surfaces.at(0);
  CHECK((c.Psi - prep::contact_shape_rows(b, surface(spec)) * Phi).norm() < 1e-14 * c.Psi.norm());
  const auto& m = sid.master_patches.at(0);
  REQUIRE(m.degrees == std::vector<int>{4});
  // evaluating the master patch as a NURBS curve gives the body's lower arc
  prep::NurbsPatch curve;
  curve.degrees = m.degrees;
  curve.knots = m.knots;
  curve.points = m.control_points;
  curve.weights = m.weights;
  for (double u : {0.0, 0.13, 0.5, 0.91})
    CHECK((curve.point(Eigen::VectorXd::Constant(1, u)) - spec.patches[0].patch.point(Eigen::Vector2d(u, 0.0))).norm() < 1e-15);
}

TEST_CASE("a Craig-Bampton SID marks the contact points its interface covers: a point load there deflects it as the full model",
          "[contact][reduction]") {
  // A square block clamped at its base, its top the contact surface, the interface 12 control
  // points about the middle of the top. The constraint modes make the reduction exact for loads
  // on interface DOFs, so a point that interface control points alone move has the full
  // model's normal flexibility n.N K^-1 N^T n. Any reduction is a subspace, so nowhere more
  // flexible than the full model; beyond the interface only the normal modes and the
  // constraint modes' tails move the surface, and a local load there meets a stiff one: the
  // case the runtime warns of where in_interface = 0 (the block, unlike a slender beam, takes
  // a point load mostly locally).
  const test::ScratchDir dir("interface-coverage");
  std::ofstream(dir.path("block.model.toml")) << test::scene_fixture("clamped_block_cb.model.toml");
  const auto spec = prep::read_model_file(dir.path("block.model.toml"));
  const auto b = prep::build_body(spec);
  const auto sys = prep::assemble_system(b.space, b.dofs, b.elasticity);
  const auto basis = prep::reduce_body(b, sys);
  const auto sid = prep::build_sid(b, sys, prep::assemble_scalar_mass(b.space, b.dofs, b.elasticity), basis);
  const auto& c = sid.contact_surfaces.at(0);
  REQUIRE(c.in_interface.size() == c.points());
  const auto N = prep::contact_shape_rows(b, surface(spec));
  const prep::SparseCholesky full_K(sys.K);
  const std::vector<int>& free = b.dofs.free_indices();
  const int dim = b.dofs.dim();
  int covered = 0;
  double stiffest_beyond = 1;  // the smallest reduced / full flexibility of a point beyond the interface
  for (Eigen::Index g = 0; g < c.points(); ++g) {
    // the point's normal load on the free DOFs, and its deflection along the normal
    Eigen::VectorXd load = Eigen::VectorXd::Zero(b.dofs.free_count());
    Eigen::RowVectorXd psi = Eigen::RowVectorXd::Zero(c.Psi.cols());
    for (int a = 0; a < dim; ++a) {
      const Eigen::SparseVector<double> row = N.row(g * dim + a);
      for (Eigen::SparseVector<double>::InnerIterator it(row); it; ++it)
        if (free[std::size_t(it.index())] >= 0) load(free[std::size_t(it.index())]) += c.normal(g, a) * it.value();
      psi += c.normal(g, a) * c.Psi.row(g * dim + a);
    }
    const Eigen::VectorXd deflection = full_K.solve(load);
    const double full = load.dot(deflection);
    const double reduced = psi.cwiseAbs2().cwiseQuotient(sid.Ke.M0.diagonal().transpose()).sum();  // Ke is diagonal
    INFO("point " << g << " at x = " << c.position(g, 0) << ": full " << full << ", reduced " << reduced);
    // round-off of K's condition (about 1e8) and of the basis' orthonormalization
    CHECK(reduced <= full * (1 + 1e-7));
    if (c.in_interface(g)) {
      ++covered;
      CHECK(std::abs(reduced - full) < 1e-7 * full);
    } else {
      // not "stiffer everywhere": beside the interface a point whose one outside control point
      // has a small basis value there keeps all but 1e-7 of the flexibility (the mark is the
      // guarantee, not the measure)
      stiffest_beyond = std::min(stiffest_beyond, reduced / full);
    }
  }
  CHECK(covered > 0);
  CHECK(covered < c.points());
  INFO("smallest reduced / full flexibility beyond the interface " << stiffest_beyond);
  CHECK(stiffest_beyond < 0.5);
}

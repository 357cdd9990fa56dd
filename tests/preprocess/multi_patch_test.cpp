// Bodies of several patches and materials: conforming interfaces merged into shared nodes,
// refinement kept conforming across them, one material per patch. Checked against closed
// forms (two-material bar, bi-material patch test), against the same body as one patch, and
// against the sum of the patches' own mass integrals.
#include "assemble/point_operator.hpp"
#include "geometry/primitives.hpp"
#include "reduce/modal_analysis.hpp"
#include "reduce/sparse_cholesky.hpp"
#include "refine/patch_refinement.hpp"
#include "pipeline/prepare.hpp"
#include "sid/body_integrals.hpp"
#include "sid/joined_surface.hpp"
#include "sid/transfer.hpp"
#include "space/reference_rule.hpp"
#include "preprocess/body_fixtures.hpp"
#include "support/run_program.hpp"
#include "isosid/format/sid_io.hpp"
#include "support/one_line_exit.hpp"

#include <catch2/catch.hpp>
#include <fstream>
#include <random>
#include <sstream>

using namespace isosid;
using format::AnalysisType;

namespace {

prep::ModelSpec model(const std::string& name) { return prep::read_model_file(std::string(ISOSID_MODELS_DIR) + "/" + name); }

Eigen::VectorXd frequencies(const prep::BodyModel& b, int n) {
  const auto sys = prep::assemble_system(b.space, b.dofs, b.elasticity);
  const format::Material& m = prep::fastest_material(b.spec);
  return prep::lowest_modes(sys.K, sys.M, n, prep::eigenvalue_scale(m.youngs_modulus, m.density, prep::body_size(b))).frequencies_hz();
}

/// Roots of g on (0, top] by scanning in `step` and bisecting each sign change.
std::vector<double> roots(const std::function<double(double)>& g, double step, int count) {
  std::vector<double> out;
  for (double a = step * 1e-3; int(out.size()) < count; a += step) {
    double lo = a, hi = a + step;
    if (g(lo) * g(hi) > 0) continue;
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (lo + hi);
      (g(lo) * g(mid) <= 0 ? hi : lo) = mid;
    }
    out.push_back(0.5 * (lo + hi));
  }
  return out;
}

prep::ModelSpec two_patch_spec(AnalysisType type, std::vector<prep::PatchSpec> patches) {
  prep::ModelSpec s;
  s.file = "test";
  s.body_name = "test";
  s.analysis = type;
  s.patches = std::move(patches);
  return s;
}

}  // namespace

TEST_CASE("two-material bar: axial frequencies solve the bar's frequency equation", "[multipatch]") {
  const prep::BodyModel b = prep::build_body(model("bar_two_materials.model.toml"));
  REQUIRE(b.interfaces.size() == 1);
  const format::Material &m1 = b.spec.patches[0].material, &m2 = b.spec.patches[1].material;
  const double c1 = std::sqrt(m1.youngs_modulus / m1.density), c2 = std::sqrt(m2.youngs_modulus / m2.density);
  const double Z1 = std::sqrt(m1.youngs_modulus * m1.density), Z2 = std::sqrt(m2.youngs_modulus * m2.density);
  const double L1 = 0.5, L2 = 0.5;
  // held at x = 0, free at x = L: u = sin(k1 x), then B cos(k2 (L - x)); displacement and force continuous
  const auto g = [&](double w) { return Z1 * std::cos(w / c1 * L1) * std::cos(w / c2 * L2) - Z2 * std::sin(w / c1 * L1) * std::sin(w / c2 * L2); };
  const std::vector<double> w = roots(g, 200.0, 4);
  const Eigen::VectorXd f = frequencies(b, 4);
  for (int k = 0; k < 4; ++k) {
    INFO("mode " << k + 1 << ": " << f(k) << " Hz against " << w[std::size_t(k)] / (2 * M_PI) << " Hz");
    // degree 4 with 16 elements per material: measured errors 1e-14 (modes 1, 2) to 6e-11
    // (mode 4), the discretization error of the shortest wave; 1e-6 is the bar required
    CHECK(f(k) == Approx(w[std::size_t(k)] / (2 * M_PI)).epsilon(1e-6));
  }
}

TEST_CASE("a box as two conforming patches has the frequencies of the same box as one patch", "[multipatch]") {
  const format::Material steel{2.1e11, 0.3, 7850};
  prep::RefinementSpec r;
  r.degrees = {2, 2, 2};
  r.subdivisions = {3, 2, 2};
  prep::NurbsPatch left = prep::primitives::box(0.1, 0.05, 0.04, Eigen::Vector3d::Zero());
  prep::NurbsPatch right = prep::primitives::box(0.1, 0.05, 0.04, Eigen::Vector3d(0.1, 0.0, 0.0));
  const prep::BodyModel two = prep::build_body(two_patch_spec(AnalysisType::Solid, {{"left", steel, left, r}, {"right", steel, right, r}}));
  REQUIRE(two.interfaces.size() == 1);
  // one patch with the same space: degree 2 and a double knot (C0) where the patches meet
  prep::NurbsPatch one = prep::primitives::box(0.2, 0.05, 0.04, Eigen::Vector3d::Zero());
  for (int d = 0; d < 3; ++d) prep::elevate_degree(one, d, 2);
  prep::insert_knots(one, 0, {0.5, 0.5});
  prep::RefinementSpec split = r;
  split.degrees.clear();
  const prep::BodyModel single = prep::build_body(two_patch_spec(AnalysisType::Solid, {{"", steel, one, split}}));
  REQUIRE(single.dofs.free_count() == two.dofs.free_count());
  const Eigen::VectorXd a = frequencies(two, 16), b = frequencies(single, 16);
  for (int k = 6; k < 16; ++k) {  // the six rigid-body modes are round-off around zero
    INFO("mode " << k + 1 << ": " << a(k) << " against " << b(k) << " Hz");
    // one space, two numberings: only the eigen solver's round-off differs
    CHECK(a(k) == Approx(b(k)).epsilon(1e-10));
  }
}

TEST_CASE("refinement of one patch is carried across its interfaces", "[multipatch]") {
  prep::ModelSpec finer_arm = model("l_bracket_plane.model.toml");
  finer_arm.patches[1].refinement.subdivisions = {4, 8};  // the arm's eta spans reach the corner ...
  prep::ModelSpec all_finer = finer_arm;
  all_finer.patches[0].refinement.subdivisions = {4, 8};  // ... as if the corner were refined the same
  const prep::BodyModel a = prep::build_body(finer_arm), b = prep::build_body(all_finer);
  CHECK(a.refined[0].knots[1].size() == b.refined[0].knots[1].size());
  REQUIRE(a.dofs.free_count() == b.dofs.free_count());
  const Eigen::VectorXd fa = frequencies(a, 6), fb = frequencies(b, 6);
  for (int k = 0; k < 6; ++k) CHECK(fa(k) == Approx(fb(k)).epsilon(1e-10));
}

TEST_CASE("mass and inertia of a multi-patch body are the sums of its patches'", "[multipatch][mass]") {
  const prep::ModelSpec spec = model("l_bracket_plane.model.toml");
  const prep::BodyModel body = prep::build_body(spec);
  REQUIRE(body.interfaces.size() == 2);
  auto integrals = [](const prep::BodyModel& b) {
    return prep::rigid_integrals(prep::assemble_scalar_mass(b.space, b.dofs, b.elasticity), b.dofs.node_points(), b.spec.analysis);
  };
  const prep::RigidIntegrals whole = integrals(body);
  double mass = 0;
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
  for (const prep::PatchSpec& p : spec.patches) {
    prep::ModelSpec alone = spec;
    alone.patches = {p};
    alone.fixed.clear();
    const prep::RigidIntegrals part = integrals(prep::build_body(alone));
    mass += part.mass;
    first += part.first_moment;
    inertia += part.inertia();
  }
  // the same integrals over the same elements, summed in another order: round-off only
  CHECK(whole.mass == Approx(mass).epsilon(1e-12));
  CHECK((whole.first_moment - first).norm() <= 1e-12 * first.norm());
  CHECK((whole.inertia() - inertia).norm() <= 1e-12 * inertia.norm());
  CHECK(whole.mass == Approx(2700.0 * 0.01 * 0.01 * 2 + 7850.0 * 0.01 * 0.01).epsilon(1e-12));
}

// Uniaxial stress sigma across a bi-material interface: with nu/E equal on both sides the
// lateral strains agree, so the exact displacement is linear in each material and continuous,
// which the C0 interface reproduces to round-off; the stress is sigma everywhere.
TEST_CASE("patch test across a bi-material interface, 2D and 3D", "[multipatch][patchtest]") {
  const format::Material soft{1e11, 0.2, 7000}, stiff{2e11, 0.4, 3000};  // nu / E = 2e-12 on both
  const double sigma = 1e6;
  for (const AnalysisType type : {AnalysisType::PlaneStress, AnalysisType::Solid}) {
    const bool solid = type == AnalysisType::Solid;
    prep::RefinementSpec r;
    r.degrees = solid ? std::vector<int>{2, 2, 2} : std::vector<int>{3, 2};
    r.subdivisions = solid ? std::vector<int>{2, 2, 2} : std::vector<int>{3, 2};
    auto block = [&](double x0) {
      return solid ? prep::primitives::box(0.1, 0.04, 0.03, Eigen::Vector3d(x0, 0, 0)) : prep::primitives::rectangle(0.1, 0.04, x0, 0.0);
    };
    prep::ModelSpec spec = two_patch_spec(type, {{"a", soft, block(0.0), r}, {"b", stiff, block(0.1), r}});
    // held axially at x = 0, on rollers at y = 0 (and z = 0): free to contract laterally
    spec.fixed = {{"xi0", {0}, 0}, {"eta0", {1}, 0}, {"eta0", {1}, 1}};
    if (solid) spec.fixed.insert(spec.fixed.end(), {{"zeta0", {2}, 0}, {"zeta0", {2}, 1}});
    const prep::BodyModel b = prep::build_body(spec);
    REQUIRE(b.interfaces.size() == 1);
    const auto sys = prep::assemble_system(b.space, b.dofs, b.elasticity);
    const Eigen::VectorXd f = prep::assemble_traction(b.space, b.dofs, b.elasticity, 1, {0, 1},
                                                      [&](const Eigen::VectorXd& x, const Eigen::VectorXd&) {
                                                        Eigen::VectorXd t = Eigen::VectorXd::Zero(x.size());
                                                        t(0) = sigma;
                                                        return t;
                                                      });
    const Eigen::VectorXd nodal = prep::expand_to_nodes(b.dofs, prep::SparseCholesky(sys.K).solve(f));
    const double lateral = -soft.poisson_ratio / soft.youngs_modulus * sigma;
    auto exact = [&](const Eigen::VectorXd& x) {
      Eigen::VectorXd u = lateral * x;
      u(0) = x(0) <= 0.1 ? sigma / soft.youngs_modulus * x(0)
                         : sigma / soft.youngs_modulus * 0.1 + sigma / stiff.youngs_modulus * (x(0) - 0.1);
      return u;
    };
    const prep::ReferenceRule rule = prep::reference_rule(b.space, 0);
    double u_error = 0, s_error = 0;
    for (const prep::Element& e : b.space.elements)
      for (int q = 0; q < rule.size(); ++q) {
        const auto op = prep::point_operator(b.space, b.dofs, b.elasticity, e, rule.points.col(q).data());
        u_error = std::max(u_error, (op.displacement(nodal) - exact(op.x)).norm());
        Eigen::VectorXd s = b.elasticity.of(e).D() * op.strain(nodal);
        s(0) -= sigma;
        s_error = std::max(s_error, s.cwiseAbs().maxCoeff());
      }
    INFO((solid ? "3D" : "2D") << ": displacement error " << u_error << " m, stress error " << s_error << " Pa");
    // relative to the largest displacement (1.5e-6 m) and to sigma: round-off of the solve
    CHECK(u_error <= 1e-10 * sigma / soft.youngs_modulus * 0.2);
    CHECK(s_error <= 1e-10 * sigma);
  }
}

TEST_CASE("the SID of a multi-patch body records its patches, and isosid-info shows them", "[multipatch][sid]") {
  const test::ScratchDir dir("multipatch-sid");
  const std::string sid_file = dir.path("bracket.sid.h5");
  const auto r = test::run_program(std::string(ISOSID_PREP_EXE) + " -q " + std::string(ISOSID_MODELS_DIR) +
                                   "/l_bracket_plane.model.toml -o " + sid_file);
  REQUIRE(r.exit_status == 0);
  const format::Sid sid = format::read_sid(sid_file);
  REQUIRE(sid.patches.size() == 3);
  CHECK(sid.patches[2].name == "upright");
  CHECK(sid.patches[2].material.youngs_modulus == 2.1e11);
  CHECK(sid.patches[0].interfaces == std::vector<std::string>{"xi1 arm.xi0", "eta1 upright.eta0"});
  CHECK(sid.contact_surfaces.at(0).patch == "upright");
  CHECK(sid.stress_recovery.at(0).patch == "arm");
  CHECK(sid.material.youngs_modulus == 2.1e11);  // the contact surface's patch
  const auto info = test::run_program(std::string(ISOSID_INFO_EXE) + " " + sid_file);
  CHECK_THAT(info.out, Catch::Matchers::Contains("patch         upright: E 2.1e+11 Pa, nu 0.3, rho 7850 kg/m^3; eta0 meets corner.eta1"));
  CHECK_THAT(info.out, Catch::Matchers::Contains("on side 'eta1' of patch upright"));
}

TEST_CASE("a contact surface over three patch sides: one surface, one joined master patch", "[multipatch][contact]") {
  const prep::BodyModel b = prep::build_body(model("beam_clamped_glued.model.toml"));
  const prep::ContactSurfaceSpec& spec = b.spec.contact_surfaces.at(0);
  REQUIRE(spec.continued.size() == 2);
  std::mt19937 gen(5);
  std::uniform_real_distribution<double> u(-1, 1);
  Eigen::MatrixXd Phi(b.dofs.total_dofs(), 2);
  for (Eigen::Index i = 0; i < Phi.size(); ++i) Phi(i) = u(gen);
  const prep::JoinedSurface j = prep::joined_contact_surface(b, spec, Phi);
  // the Gauss points of the three sides: the whole top face, 210 x 15 mm
  CHECK(j.surface.weight.sum() == Approx(0.210 * 0.015).epsilon(1e-12));
  // parameters laid end to end: xi runs over [0, 3], zeta stays at the side
  CHECK(j.surface.parameter.col(0).maxCoeff() < 3.0);
  CHECK(j.surface.parameter.col(0).maxCoeff() > 2.0);
  CHECK((j.surface.parameter.col(2).array() == 1.0).all());
  // the joined master patch: the face's geometry and the body's displacement at every point,
  // the joints between patches included (C0 knots there)
  prep::NurbsPatch face;
  face.degrees = j.master.degrees;
  face.knots = j.master.knots;
  face.weights = j.master.weights;
  face.points.resize(j.master.weights.size(), 3 + 3 * 2);
  face.points.leftCols(3) = j.master.control_points;
  for (Eigen::Index i = 0; i < j.master.weights.size(); ++i)
    for (int c = 0; c < 2; ++c) face.points.block(i, 3 + 3 * c, 1, 3) = j.master.Phi.block(3 * i, c, 3, 1).transpose();
  for (Eigen::Index g = 0; g < j.surface.points(); ++g) {
    const Eigen::Vector2d at_face(j.surface.parameter(g, 0), j.surface.parameter(g, 1));
    const Eigen::VectorXd on_face = face.point(at_face);
    CHECK((on_face.head(3) - j.surface.position.row(g).transpose()).norm() < 1e-12 * 0.21);
    // the contact rows Psi are the body's displacement at the point: the same field
    for (int c = 0; c < 2; ++c) CHECK((on_face.segment(3 + 3 * c, 3) - j.surface.Psi.block(3 * g, c, 3, 1)).norm() < 1e-10);
  }
}

/// The L-bracket model with a hierarchical refinement of its steel upright around `point`.
std::string bracket_with_thb(const std::string& point) {
  std::ifstream in(std::string(ISOSID_MODELS_DIR) + "/l_bracket_plane.model.toml");
  std::stringstream text;
  text << in.rdbuf();
  std::string model = text.str();
  const std::string anchor = "origin = [0.0, 0.1]\n[patch.refinement]\ndegrees = [2, 2]\nsubdivisions = [4, 4]\n";
  const std::size_t at = model.find(anchor);
  REQUIRE(at != std::string::npos);
  model.insert(at + anchor.size(), "[patch.refinement.hierarchical]\npoint = " + point + "\nwidth = 0.02\nsmallest = 0.002\n");
  return model;
}

TEST_CASE("hierarchical refinement inside one patch of a multi-patch body", "[multipatch][thb]") {
  const test::ScratchDir dir("multipatch-thb");
  SECTION("refined at the free top of the upright: coarse and fine models map onto each other") {
    const std::string model = dir.path("bracket_thb.model.toml"), sid_file = dir.path("bracket_thb.sid.h5");
    std::ofstream(model) << bracket_with_thb("[0.5, 1.0]");
    const prep::BodyModel b = prep::build_body(prep::read_model_file(model));
    REQUIRE(b.hierarchy);
    CHECK(b.hierarchy->functions_per_level.size() > 1);
    CHECK(b.hierarchy->prolongation.cols() == b.refined[0].count() + b.refined[1].count() + b.refined[2].count());
    // nodal: coarse fields are recovered exactly through the fine space and back
    const prep::PreparedBody coarse_body = prep::prepare(prep::coarse_model_spec(b.spec), {.build_sid = false, .output = ""});
    const prep::NodalTransfer nodal = prep::nodal_transfer(coarse_body.body, b);
    const Eigen::MatrixXd nodal_round = Eigen::MatrixXd(nodal.fine_to_coarse * nodal.coarse_to_fine);
    CHECK((nodal_round - Eigen::MatrixXd::Identity(nodal_round.rows(), nodal_round.cols())).cwiseAbs().maxCoeff() < 1e-10);
    const auto r = test::run_program(std::string(ISOSID_PREP_EXE) + " -q " + model + " -o " + sid_file);
    REQUIRE(r.exit_status == 0);
    const format::Sid sid = format::read_sid(sid_file);
    REQUIRE(sid.transfer);
    // reduced: the fine basis is its 8 modes plus the 8 prolongated coarse modes, nearly the
    // same fields; the K-M orthonormalization drops the near-duplicates, so the coarse modes
    // are kept to ~1e-6 rather than exactly (measured 5.8e-7; the nodal map above is exact)
    const Eigen::MatrixXd round_trip = sid.transfer->fine_to_coarse * sid.transfer->coarse_to_fine;
    CHECK((round_trip - Eigen::MatrixXd::Identity(round_trip.rows(), round_trip.cols())).cwiseAbs().maxCoeff() < 1e-5);
    // finer near the top, the same body: the lowest frequency moves by less than 0.1 %
    const Eigen::VectorXd coarse = frequencies(prep::build_body(prep::coarse_model_spec(prep::read_model_file(model))), 1);
    CHECK(sid.refmod.frequencies_hz(0) == Approx(coarse(0)).epsilon(1e-3));
  }
  SECTION("refined where the upright meets the corner: refused") {
    const std::string model = dir.path("bracket_bad.model.toml");
    std::ofstream(model) << bracket_with_thb("[0.5, 0.0]");
    CHECK_THROWS_WITH(prep::build_body(prep::read_model_file(model)),
                      Catch::Matchers::Contains("patch upright.refinement.hierarchical") &&
                          Catch::Matchers::Contains("along side eta0, an interface"));
  }
}

TEST_CASE("bad multi-patch models end with one line naming the patches", "[multipatch][input]") {
  const test::ScratchDir dir("multipatch-bad");
  auto write = [&](const std::string& name, const std::string& text) {
    const std::string path = dir.path(name);
    std::ofstream(path) << text;
    return path;
  };
  const std::string head = "[body]\nname = \"b\"\nanalysis = \"plane_stress\"\n";
  auto patch = [](const std::string& name, const std::string& geometry, const std::string& material = "") {
    return "[[patch]]\nname = \"" + name + "\"\n" + material + "[patch.geometry]\nprimitive = \"rectangle\"\n" + geometry + "\n";
  };
  const std::string steel = "[patch.material]\nyoungs_modulus = 2.1e11\npoisson_ratio = 0.3\ndensity = 7850.0\n";
  using Catch::Matchers::Contains;
  SECTION("overlapping patches") {
    const auto f = write("overlap.model.toml", head + patch("a", "size = [1.0, 1.0]", steel) + patch("b", "size = [1.0, 1.0]\norigin = [0.5, 0.0]", steel));
    CHECK_THROWS_WITH(prep::build_body(prep::read_model_file(f)), Contains("patches 'a' and 'b' overlap"));
  }
  SECTION("non-matching interface") {  // b's side touches half of a's
    const auto f = write("nonmatching.model.toml", head + patch("a", "size = [1.0, 2.0]", steel) + patch("b", "size = [1.0, 1.0]\norigin = [1.0, 0.0]", steel));
    CHECK_THROWS_WITH(prep::build_body(prep::read_model_file(f)), Contains("non-matching interface between a.xi1 and b.xi0"));
  }
  SECTION("patches that do not form one solid") {  // their relative motions would pass for elastic modes
    const auto apart = write("apart.model.toml", head + patch("a", "size = [1.0, 1.0]", steel) + patch("b", "size = [1.0, 1.0]\norigin = [1.1, 0.0]", steel));
    CHECK_THROWS_WITH(prep::build_body(prep::read_model_file(apart)),
                      Contains("patch: patches 'a' and 'b' share no side (a body must be one connected solid)"));
    const auto corner = write("corner.model.toml", head + patch("a", "size = [1.0, 1.0]", steel) + patch("b", "size = [1.0, 1.0]\norigin = [1.0, 1.0]", steel));
    CHECK_THROWS_WITH(prep::build_body(prep::read_model_file(corner)), Contains("patches 'a' and 'b' meet at a point or an edge only"));
    // a third patch beside a joined pair
    const auto third = write("third.model.toml", head + patch("a", "size = [1.0, 1.0]", steel) + patch("b", "size = [1.0, 1.0]\norigin = [1.0, 0.0]", steel) +
                                                     patch("c", "size = [1.0, 1.0]\norigin = [0.0, 3.0]", steel));
    CHECK_THROWS_WITH(prep::build_body(prep::read_model_file(third)), Contains("patches 'a' and 'c' share no side"));
  }
  SECTION("a patch without a material") {
    const auto f = write("nomaterial.model.toml", head + patch("a", "size = [1.0, 1.0]", steel) + patch("b", "size = [1.0, 1.0]\norigin = [1.0, 0.0]"));
    CHECK_THROWS_WITH(prep::read_model_file(f), Contains("patch 'b' has no material"));
  }
  SECTION("a side without its patch") {
    const auto f = write("side.model.toml", head + patch("a", "size = [1.0, 1.0]", steel) + patch("b", "size = [1.0, 1.0]\norigin = [1.0, 0.0]", steel) +
                                                "[boundary]\nclamped = [\"xi0\"]\n");
    CHECK_THROWS_WITH(prep::read_model_file(f), Contains("boundary.clamped") && Contains("name the patch too"));
  }
  SECTION("isosid-prep: exit 2 and one line") {
    const auto f = write("overlap2.model.toml", head + patch("a", "size = [1.0, 1.0]", steel) + patch("b", "size = [1.0, 1.0]\norigin = [0.5, 0.5]", steel));
    const auto r = test::run_program(std::string(ISOSID_PREP_EXE) + " -q --modes 3 " + f);
    test::check_one_line_exit(r, 2, "overlap");
  }
}

// THB spaces: the level rule of [R2] Alg. 3 (docs/references.md); partition of unity, exact
// geometry, reproduction of the coarse space and linear independence on 2D and 3D hierarchies;
// class-m admissibility; frequencies between the coarse and the uniformly refined space (nested
// spaces, Rayleigh-Ritz); the hierarchical sphere's size against the graded one; coarse <->
// fine transfer. Tolerances: 1e-12 for pointwise identities of exact arithmetic (round-off of
// sums of O(10) products of O(1) numbers), 1e-10 for solves and quadrature-based quantities.
#include "space/element_evaluator.hpp"
#include "assemble/point_operator.hpp"
#include "geometry/primitives.hpp"
#include "pipeline/prepare.hpp"
#include "reduce/body_reduction.hpp"
#include "reduce/modal_analysis.hpp"
#include "thb/level_factors.hpp"
#include "sid/sid_builder.hpp"
#include "sid/master_patch.hpp"
#include "sid/transfer.hpp"
#include "preprocess/body_fixtures.hpp"

#include <Eigen/Eigenvalues>
#include <catch2/catch.hpp>
#include <random>
#include <set>

using namespace isosid;
using format::AnalysisType;

namespace {

prep::ModelSpec model(const std::string& name) { return prep::read_model_file(std::string(ISOSID_MODELS_DIR) + "/" + name); }

prep::HierarchicalRequest box_request(std::vector<std::array<double, 2>> box, int across, int admissibility = 2) {
  prep::HierarchicalRequest r;
  r.box = std::move(box);
  r.elements_across = across;
  r.admissibility = admissibility;
  return r;
}

prep::BodyModel hierarchical_body(prep::NurbsPatch patch, AnalysisType type, prep::RefinementSpec refinement,
                                  const prep::HierarchicalRequest& request) {
  refinement.hierarchical = request;
  return prep::build_body(test::spec_for(std::move(patch), type, 2e11, 0.3, 7800, std::move(refinement)));
}

Eigen::VectorXd random_parameter(const prep::AnalysisSpace& s, std::mt19937& gen) {
  std::uniform_real_distribution<double> u(0, 1);
  Eigen::VectorXd xi(s.param_dim());
  for (int d = 0; d < s.param_dim(); ++d) xi(d) = s.patch_boxes[0].lo(d) + u(gen) * (s.patch_boxes[0].hi(d) - s.patch_boxes[0].lo(d));
  return xi;
}

/// Checks at random points: sum R = 1, x(xi) = patch(xi), and a random field on the patch's
/// functions equals its prolongation evaluated with the THB functions.
void check_space(const prep::BodyModel& b) {
  const prep::AnalysisSpace& s = b.space;
  const prep::ElementEvaluator ev(s);
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(-1, 1);
  Eigen::VectorXd coarse(b.refined[0].count());
  for (auto& c : coarse) c = u(gen);
  // a field in the patch's rational space: sum_i R_i c_i with R_i = w_i N_i / W
  const Eigen::VectorXd fine = b.hierarchy->prolongation * coarse;
  prep::NurbsPatch field = b.refined[0];
  field.points.conservativeResize(Eigen::NoChange, field.phys_dim() + 1);
  field.points.col(field.phys_dim() - 1) = coarse;
  const double size = prep::patch_size(b.refined[0]);
  for (int k = 0; k < 300; ++k) {
    const Eigen::VectorXd xi = random_parameter(s, gen);
    int e = -1;
    double t[3];
    REQUIRE(prep::locate(s, 0, xi, e, t));
    prep::PointValues v;
    ev.evaluate(s.elements[std::size_t(e)], t, v);
    CHECK(std::abs(v.R.sum() - 1.0) < 1e-12);
    const Eigen::VectorXd expected = field.point(xi);
    CHECK((v.x - expected.head(v.x.size())).norm() < 1e-12 * size);
    double value = 0;
    for (std::size_t f = 0; f < s.elements[std::size_t(e)].functions.size(); ++f)
      value += v.R(Eigen::Index(f)) * fine(s.elements[std::size_t(e)].functions[f]);
    CHECK(std::abs(value - expected(expected.size() - 1)) < 1e-12);
  }
}

/// Linear independence: the scalar mass (Gram) matrix of the functions is positive definite.
double gram_condition(const prep::BodyModel& b) {
  // one node per function here (no merged points in these patches)
  REQUIRE(b.dofs.node_count() == b.space.n_functions());
  const Eigen::MatrixXd G = Eigen::MatrixXd(prep::assemble_scalar_mass(b.space, b.dofs, b.elasticity));
  const Eigen::VectorXd lambda = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(G).eigenvalues();
  REQUIRE(lambda(0) > 0);
  return lambda(lambda.size() - 1) / lambda(0);
}

/// Largest number of levels whose functions live on one element.
int levels_on_an_element(const prep::AnalysisSpace& s) {
  int most = 0;
  for (const auto& e : s.elements) {
    std::set<int> levels;
    for (int f : e.functions) levels.insert(s.function_level[std::size_t(f)]);
    most = std::max(most, int(levels.size()));
  }
  return most;
}

}  // namespace

TEST_CASE("level factors follow [R2] Alg. 3", "[thb]") {
  const prep::LevelLimits seed{5, 10};
  CHECK(prep::level_factors(1, seed).empty());
  CHECK(prep::level_factors(4, seed) == std::vector<int>{2, 2});
  CHECK(prep::level_factors(3, seed) == std::vector<int>{3});
  // 13 is prime and above 11: the next admissible count is 14 = 2 x 7
  CHECK(prep::level_factors(13, seed) == std::vector<int>{2, 7});
  // 2^6: six factors merged down to four levels, smallest first
  CHECK(prep::level_factors(64, seed) == std::vector<int>{8, 2, 2, 2});
  // [R2] Fig. 6: three elements cannot be spread over two refined levels, but one level takes them
  CHECK(prep::level_factors(3, {3, 10}) == std::vector<int>{3});
  for (int wanted : {17, 97, 294, 400, 1000, 14641}) {
    const auto f = prep::level_factors(wanted, seed);
    long long product = 1;
    for (int x : f) {
      CHECK(x >= 2);
      CHECK(x <= 11);
      product *= x;
    }
    CHECK(product >= wanted);
    CHECK(f.size() <= 4);
  }
  CHECK_THROWS_WITH(prep::level_factors(14642, seed), Catch::Contains("needs more than 5 levels"));
}

TEST_CASE("THB space on a rational 2D patch: partition of unity, exact geometry, coarse space, independence", "[thb]") {
  const auto b = hierarchical_body(prep::primitives::quarter_annulus(0.5, 1.0), AnalysisType::PlaneStrain,
                                   test::uniform({3, 2}, {3, 2}), box_request({{0.3, 0.6}, {0.0, 0.4}}, 8));
  REQUIRE(b.hierarchy->mesh.levels() >= 3);
  check_space(b);
  CHECK(gram_condition(b) < 1e12);
  CHECK(levels_on_an_element(b.space) <= 2);
}

TEST_CASE("THB space on a 3D patch: partition of unity, exact geometry, coarse space, independence", "[thb]") {
  const auto b = hierarchical_body(prep::primitives::box(1.0, 0.6, 0.4), AnalysisType::Solid, test::uniform({2, 2, 2}, {2, 2, 2}),
                                   box_request({{0.25, 0.5}, {0.0, 0.5}, {0.5, 1.0}}, 4));
  REQUIRE(b.hierarchy->mesh.levels() >= 3);
  check_space(b);
  CHECK(gram_condition(b) < 1e12);
  CHECK(levels_on_an_element(b.space) <= 2);
}

TEST_CASE("admissibility class m bounds the levels on an element", "[thb]") {
  for (int m : {2, 3}) {
    const auto b = hierarchical_body(prep::primitives::rectangle(1.0, 1.0), AnalysisType::PlaneStress, test::uniform({3, 3}, {2, 2}),
                                     box_request({{0.0, 0.05}, {0.0, 0.05}}, 4, m));
    REQUIRE(b.hierarchy->mesh.levels() >= 4);
    CHECK(levels_on_an_element(b.space) <= m);
  }
}

TEST_CASE("THB frequencies lie between those of the coarse and the uniformly refined space", "[thb]") {
  // nested spaces coarse < THB < uniform (the finest level everywhere): Rayleigh-Ritz
  // eigenvalues decrease with the space, so every frequency is bracketed
  const auto coarse_ref = test::uniform({2, 2}, {2, 2});
  const auto thb = hierarchical_body(prep::primitives::quarter_annulus(0.5, 1.0), AnalysisType::PlaneStrain, coarse_ref,
                                     box_request({{0.0, 0.5}, {0.0, 0.5}}, 4));
  std::vector<int> total(2, 1);
  for (const auto& f : thb.hierarchy->mesh.factors)
    for (int d = 0; d < 2; ++d) total[std::size_t(d)] *= f[std::size_t(d)];
  const auto coarse = prep::build_body(test::spec_for(prep::primitives::quarter_annulus(0.5, 1.0), AnalysisType::PlaneStrain, 2e11, 0.3, 7800, coarse_ref));
  const auto uniform = prep::build_body(test::spec_for(prep::primitives::quarter_annulus(0.5, 1.0), AnalysisType::PlaneStrain, 2e11, 0.3,
                                                       7800, test::uniform({2, 2}, {2 * total[0], 2 * total[1]})));
  REQUIRE(coarse.dofs.free_count() < thb.dofs.free_count());
  REQUIRE(thb.dofs.free_count() < uniform.dofs.free_count());
  auto frequencies = [](const prep::BodyModel& b) {
    const auto sys = prep::assemble_system(b.space, b.dofs, b.elasticity, 2);
    return prep::lowest_modes(sys.K, sys.M, 13, prep::eigenvalue_scale(2e11, 7800, prep::body_size(b))).frequencies_hz();
  };
  const Eigen::VectorXd fc = frequencies(coarse), ft = frequencies(thb), fu = frequencies(uniform);
  for (int k = 3; k < 13; ++k) {  // the elastic modes (3 rigid-body modes first)
    INFO("mode " << k << ": " << fc(k) << " >= " << ft(k) << " >= " << fu(k));
    CHECK(ft(k) <= fc(k) * (1 + 1e-9));
    CHECK(ft(k) >= fu(k) * (1 - 1e-9));
  }
}

TEST_CASE("a box across the half-disk's collapsed point: nodes merge across levels, the space stays exact", "[thb]") {
  // documented behaviour (models/README.md): side xi1 of the half-disk collapses to one point;
  // functions of all levels there form one node, so the displacement stays single-valued
  prep::RefinementSpec ref = test::uniform({2, 2}, {2, 4});
  const auto b = hierarchical_body(prep::primitives::half_disk(0.01), AnalysisType::Axisymmetric, ref,
                                   box_request({{0.8, 1.0}, {0.3, 0.6}}, 4, 3));
  check_space(b);
  const Eigen::Vector2d point(0.01, 0.0);
  std::set<int> nodes;
  for (int f = 0; f < b.space.n_functions(); ++f)
    if ((b.space.control_points.row(f).transpose() - point).norm() < 1e-12) nodes.insert(b.dofs.node_of(f));
  CHECK(nodes.size() == 1);
  std::set<int> levels;
  for (int f = 0; f < b.space.n_functions(); ++f)
    if ((b.space.control_points.row(f).transpose() - point).norm() < 1e-12) levels.insert(b.space.function_level[std::size_t(f)]);
  CHECK(levels.size() >= 2);
}

TEST_CASE("the hierarchical sphere has at least 3x fewer DOFs than the graded one at the same smallest element", "[thb]") {
  // the graded sphere sized for a contact radius of 8 x 25 um: the THB sphere's 25 um elements
  auto graded_spec = model("sphere_axisym.model.toml");
  prep::set_contact_radius(graded_spec, 8 * 25e-6, "test");
  const auto graded = prep::build_body(graded_spec);
  const auto thb = prep::build_body(model("sphere_axisym_thb.model.toml"));
  CHECK(3 * thb.dofs.free_count() <= graded.dofs.free_count());
  // the smallest element along the contact side is the same 25 um in both
  auto smallest_on_contact = [](const prep::BodyModel& b) {
    double h = 1e9;
    for (const auto& e : b.space.elements)
      if (e.lo(1) == 0.0) h = std::min(h, (b.refined[0].point(Eigen::Vector2d(e.hi(0), 0)) - b.refined[0].point(Eigen::Vector2d(e.lo(0), 0))).norm());
    return h;
  };
  CHECK(smallest_on_contact(thb) <= 25e-6);
  CHECK(smallest_on_contact(thb) == Approx(smallest_on_contact(graded)).epsilon(0.1));
}

TEST_CASE("coarse -> refined -> coarse returns the state, nodal and reduced, and keeps its energy", "[thb]") {
  const auto fine = prep::build_body(model("sphere_axisym_thb.model.toml"));
  const prep::PreparedBody coarse = prep::prepare(prep::coarse_model_spec(fine.spec), {.build_sid = false, .output = ""});
  const prep::NodalTransfer nodal = prep::nodal_transfer(coarse.body, fine);
  // nodal: the local least squares of [R2] Sect. 4.4 recovers any coarse field exactly
  const Eigen::MatrixXd round = Eigen::MatrixXd(nodal.fine_to_coarse * nodal.coarse_to_fine);
  CHECK((round - Eigen::MatrixXd::Identity(round.rows(), round.cols())).cwiseAbs().maxCoeff() < 1e-10);
  // reduced: the refined basis holds the coarse modes
  const auto system = prep::assemble_system(fine.space, fine.dofs, fine.elasticity);
  const auto basis = prep::reduce_body(fine, system, prep::prolongated_modes({coarse.body, coarse.system, coarse.basis}, fine, nodal));
  const auto T = prep::reduced_transfer({coarse.body, coarse.system, coarse.basis}, {fine, system, basis}, nodal);
  const Eigen::MatrixXd I = T.fine_to_coarse * T.coarse_to_fine;
  CHECK((I - Eigen::MatrixXd::Identity(I.rows(), I.cols())).cwiseAbs().maxCoeff() < 1e-10);
  // energy of each coarse mode after transfer: the same field, integrated on finer elements
  // (the rational integrands make the two quadratures differ slightly; measured 1e-5)
  const Eigen::MatrixXd Kf = basis.Phi.transpose() * (system.K * basis.Phi);
  for (Eigen::Index k = 0; k < T.coarse_to_fine.cols(); ++k) {
    const double coarse_energy = coarse.basis.omega2(k), fine_energy = T.coarse_to_fine.col(k).dot(Kf * T.coarse_to_fine.col(k));
    CHECK(fine_energy == Approx(coarse_energy).epsilon(1e-3));
  }
}

TEST_CASE("a coarse state's energy reaches the refined model's integrated modes as the coarse mesh converges", "[thb]") {
  // The impact phase integrates the refined SID's low modes and solves the rest quasistatically
  // ([R2]): a coarse state q_c moves in as (T q_c) restricted to the low modes, and the
  // energy T q_c puts into the high ones is lost at the switch. That share is the coarse
  // mesh's error in its own modes; scene D asks a switch to keep the energy to 1e-6, so the
  // coarse model must resolve the modes it keeps. Measured for the sphere's 6 modes, worst
  // mode: 7.1e-3 (2 x 4 coarse elements), 1.7e-4 (4 x 8), 6.4e-9 (8 x 16).
  std::vector<double> lost;
  for (const int n : {2, 4, 8}) {
    prep::ModelSpec spec = model("sphere_axisym_thb.model.toml");
    spec.patches[0].refinement.subdivisions = {n, 2 * n};
    const format::Sid sid = prep::prepare(spec, {.build_sid = true, .output = ""}).sid;
    REQUIRE(sid.transfer.has_value());
    const Eigen::MatrixXd& T = sid.transfer->coarse_to_fine;
    const Eigen::ArrayXd omega2 = (2 * M_PI * sid.refmod.frequencies_hz).array().square();
    const Eigen::Index low = sid.refmod.n_low;
    double worst = 0;
    for (Eigen::Index k = 0; k < T.cols(); ++k) {
      const Eigen::ArrayXd energy = omega2 * T.col(k).array().square();
      worst = std::max(worst, energy.tail(energy.size() - low).sum() / energy.sum());
    }
    lost.push_back(worst);
  }
  INFO("lost shares " << lost[0] << " " << lost[1] << " " << lost[2]);
  CHECK(lost[1] < lost[0] / 10);  // converging: each halving of the coarse elements (measured 41x, 27000x)
  CHECK(lost[2] < lost[1] / 10);
  CHECK(lost[2] < 1e-6);          // scene D's switch tolerance, reached
}

TEST_CASE("the master patch of a hierarchical side reproduces the body's displacement on it", "[thb]") {
  // the side's THB space lies in the tensor space of all its element boundaries; knot
  // insertion (geometry) and collocation (mode rows) are exact, up to the collocation solve
  const auto b = prep::build_body(model("sphere_axisym_thb.model.toml"));
  const prep::PatchSide side = *b.refined[0].side("lower");
  std::mt19937 gen(3);
  std::uniform_real_distribution<double> u(-1, 1), t01(0, 1);
  Eigen::MatrixXd Phi(b.dofs.total_dofs(), 3);
  for (Eigen::Index i = 0; i < Phi.size(); ++i) Phi(i) = u(gen);
  const format::MasterPatch m = prep::master_patch(b, "contact", 0, side, Phi);
  REQUIRE(m.knots[0].size() > b.refined[0].knots[0].size());  // the fine knots were inserted
  const prep::ElementEvaluator ev(b.space);
  for (int k = 0; k < 200; ++k) {
    const double xi = t01(gen);
    // the master curve with the displacement of mode c (and the position) as its "points"
    prep::NurbsPatch curve;
    curve.degrees = m.degrees;
    curve.knots = m.knots;
    curve.weights = m.weights;
    curve.points.resize(m.weights.size(), 2 + 2 * 3);
    curve.points.leftCols(2) = m.control_points;
    for (Eigen::Index i = 0; i < m.weights.size(); ++i)
      for (int c = 0; c < 3; ++c) curve.points.block(i, 2 + 2 * c, 1, 2) = m.Phi.block(2 * i, c, 2, 1).transpose();
    const Eigen::VectorXd on_curve = curve.point(Eigen::VectorXd::Constant(1, xi));
    int e = -1;
    double t[3];
    REQUIRE(prep::locate(b.space, 0, Eigen::Vector2d(xi, 0.0), e, t));
    prep::PointValues v;
    ev.evaluate(b.space.elements[std::size_t(e)], t, v);
    CHECK((on_curve.head(2) - v.x).norm() < 1e-12 * 0.01);
    for (int c = 0; c < 3; ++c) {
      Eigen::Vector2d d = Eigen::Vector2d::Zero();
      const auto& el = b.space.elements[std::size_t(e)];
      for (std::size_t f = 0; f < el.functions.size(); ++f)
        d += v.R(Eigen::Index(f)) * Phi.block(b.dofs.node_of(el.functions[f]) * 2, c, 2, 1);
      CHECK((on_curve.segment(2 + 2 * c, 2) - d).norm() < 1e-10);
    }
  }
}

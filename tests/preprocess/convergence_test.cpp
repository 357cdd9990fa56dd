// Static elasticity against closed-form solutions: displacement and stress errors fall at the
// optimal rates h^(p+1) and h^p under uniform refinement (research notes section 4).
// Thick cylinder under internal pressure (Lame) in plane strain and axisymmetric, and the
// plate with a circular hole under remote tension (Kirsch, plane stress).
#include "space/reference_rule.hpp"
#include "assemble/point_operator.hpp"
#include "geometry/primitives.hpp"
#include "reduce/sparse_cholesky.hpp"
#include "preprocess/body_fixtures.hpp"

#include <catch2/catch.hpp>
#include <functional>

using namespace isosid;
using format::AnalysisType;
using Vec = Eigen::VectorXd;

namespace {

struct Exact {
  std::function<Vec(const Vec&)> displacement;
  std::function<Vec(const Vec&)> stress;  // in the order of Elasticity::stress_components()
};

struct Errors {
  double displacement, stress;  // relative L2 errors
};

struct Load {
  std::string side;
  std::function<Vec(const Vec&, const Vec&)> traction;
};

Errors solve_and_measure(prep::ModelSpec spec, const std::vector<Load>& loads, const Exact& exact) {
  const prep::BodyModel b = prep::build_body(spec);
  const auto sys = prep::assemble_system(b.space, b.dofs, b.elasticity);
  Vec f = Vec::Zero(b.dofs.free_count());
  for (const Load& l : loads) f += prep::assemble_traction(b.space, b.dofs, b.elasticity, 0, *b.refined[0].side(l.side), l.traction);
  const Vec nodal = prep::expand_to_nodes(b.dofs, prep::SparseCholesky(sys.K).solve(f));
  double eu = 0, nu = 0, es = 0, ns = 0;
  const prep::ReferenceRule rule = prep::reference_rule(b.space, 2);
  for (const auto& e : b.space.elements)
    for (int q = 0; q < rule.size(); ++q) {
      const auto op = prep::point_operator(b.space, b.dofs, b.elasticity, e, rule.points.col(q).data());
      const double w = rule.weights(q) * b.space.parametric_size(e) * std::abs(op.det_J) * b.elasticity.of(e).measure(op.x);
      const Vec u = op.displacement(nodal), s = b.elasticity.of(e).D() * op.strain(nodal);
      const Vec ue = exact.displacement(op.x), se = exact.stress(op.x);
      eu += w * (u - ue).squaredNorm();
      nu += w * ue.squaredNorm();
      es += w * (s - se).squaredNorm();
      ns += w * se.squaredNorm();
    }
  return {std::sqrt(eu / nu), std::sqrt(es / ns)};
}

/// Errors on meshes with 2, 4, 8, 16 elements per direction, and the observed rates.
template <class MakeSpec>
void check_rates(MakeSpec make, const std::vector<Load>& loads, const Exact& exact, int p) {
  std::vector<Errors> e;
  for (int n : {2, 4, 8, 16}) e.push_back(solve_and_measure(make(n), loads, exact));
  for (std::size_t k = 1; k < e.size(); ++k) {
    const double ru = std::log2(e[k - 1].displacement / e[k].displacement);
    const double rs = std::log2(e[k - 1].stress / e[k].stress);
    INFO("level " << k << ": displacement error " << e[k].displacement << " (rate " << ru << "), stress error "
                  << e[k].stress << " (rate " << rs << ")");
    if (k + 1 == e.size()) {
      // asymptotic rates: p+1 for displacements and p for stresses, within 0.3 (the finest
      // pair is in the asymptotic range for these smooth solutions)
      CHECK(ru > p + 1 - 0.3);
      CHECK(rs > p - 0.3);
    }
    CHECK(e[k].displacement < e[k - 1].displacement);
    CHECK(e[k].stress < e[k - 1].stress);
  }
}

// Lame: pressure P inside radius ri, free at ro.
const double E = 2.1e11, nu = 0.3, P = 1e8, ri = 0.1, ro = 0.2;
const double A = P * ri * ri / (ro * ro - ri * ri);
double ur(double r) { return (1 + nu) * A / E * ((1 - 2 * nu) * r + ro * ro / r); }
double srr(double r) { return A * (1 - ro * ro / (r * r)); }
double stt(double r) { return A * (1 + ro * ro / (r * r)); }

prep::RefinementSpec refinement(std::vector<int> degrees, int n) {
  prep::RefinementSpec r;
  r.degrees = std::move(degrees);
  r.subdivisions.assign(r.degrees.size(), n);
  return r;
}

}  // namespace

TEST_CASE("Lame cylinder in plane strain converges at the optimal rates", "[convergence]") {
  auto make = [](int n) {
    auto s = test::spec_for(prep::primitives::quarter_annulus(ri, ro), AnalysisType::PlaneStrain, E, nu, 7800,
                            refinement({2, 2}, n));
    s.fixed = {{"x_axis", {1}}, {"y_axis", {0}}};
    return s;
  };
  const Exact exact{[](const Vec& x) {
                      const double r = x.norm();
                      return Vec(ur(r) * x / r);
                    },
                    [](const Vec& x) {
                      const double r = x.norm(), c = x(0) / r, s = x(1) / r;
                      return Vec(Eigen::Vector3d(srr(r) * c * c + stt(r) * s * s, srr(r) * s * s + stt(r) * c * c,
                                                 (srr(r) - stt(r)) * s * c));
                    }};
  // pressure on the inner surface pushes into the body: t = -P n
  check_rates(make, {{"inner", [](const Vec&, const Vec& n) { return Vec(-P * n); }}}, exact, 2);
}

TEST_CASE("Lame cylinder as an axisymmetric section converges to the plane-strain solution", "[convergence]") {
  // the (r, z) section with u_z = 0 at both ends is the plane-strain problem
  auto make = [](int n) {
    auto s = test::spec_for(prep::primitives::rectangle(ro - ri, 0.1, ri, 0.0), AnalysisType::Axisymmetric, E, nu, 7800,
                            refinement({2, 2}, n));
    s.fixed = {{"bottom", {1}}, {"top", {1}}};
    return s;
  };
  const Exact exact{[](const Vec& x) { return Vec(Eigen::Vector2d(ur(x(0)), 0.0)); },
                    [](const Vec& x) {
                      const double r = x(0);
                      return Vec(Eigen::Vector4d(srr(r), nu * (srr(r) + stt(r)), stt(r), 0.0));
                    }};
  check_rates(make, {{"left", [](const Vec&, const Vec& n) { return Vec(-P * n); }}}, exact, 2);
}

TEST_CASE("plate with a hole (Kirsch) converges at the optimal rates", "[convergence]") {
  // Hughes, Cottrell & Bazilevs (2005): quarter plate L = 4 with a hole a = 1, E = 1e5,
  // nu = 0.3, remote tension T = 10 along x, plane stress; exact tractions on the outer edges.
  const double a = 1, T = 10, Ek = 1e5, nuk = 0.3, mu = Ek / (2 * (1 + nuk)), kappa = (3 - nuk) / (1 + nuk);
  const double w = (1 + 1 / std::sqrt(2.0)) / 2, t = std::sqrt(2.0) - 1;
  prep::NurbsPatch patch;
  patch.degrees = {2, 2};
  patch.knots = {(Vec(7) << 0, 0, 0, 0.5, 1, 1, 1).finished(), (Vec(6) << 0, 0, 0, 1, 1, 1).finished()};
  patch.points.resize(12, 2);
  patch.points << -1, 0, -1, t, -t, 1, 0, 1,             // hole (eta = 0)
      -2.5, 0, -2.5, 0.75, -0.75, 2.5, 0, 2.5,             // middle row
      -4, 0, -4, 4, -4, 4, 0, 4;                           // outer edges (eta = 1)
  patch.weights = Vec::Ones(12);
  patch.weights(1) = patch.weights(2) = w;
  patch.named_sides = {{"y0", {0, 0}}, {"x0", {0, 1}}, {"hole", {1, 0}}, {"outer", {1, 1}}};
  auto stress = [=](const Vec& x) {
    const double r = x.norm(), th = std::atan2(x(1), x(0)), q = a * a / (r * r), q2 = q * q;
    return Vec(Eigen::Vector3d(
        T * (1 - q * (1.5 * std::cos(2 * th) + std::cos(4 * th)) + 1.5 * q2 * std::cos(4 * th)),
        T * (-q * (0.5 * std::cos(2 * th) - std::cos(4 * th)) - 1.5 * q2 * std::cos(4 * th)),
        T * (-q * (0.5 * std::sin(2 * th) + std::sin(4 * th)) + 1.5 * q2 * std::sin(4 * th))));
  };
  auto displacement = [=](const Vec& x) {
    const double r = x.norm(), th = std::atan2(x(1), x(0)), ar = a / r;
    return Vec(Eigen::Vector2d(
        T * a / (8 * mu) * (r / a * (kappa + 1) * std::cos(th) + 2 * ar * ((1 + kappa) * std::cos(th) + std::cos(3 * th)) -
                            2 * std::pow(ar, 3) * std::cos(3 * th)),
        T * a / (8 * mu) * (r / a * (kappa - 3) * std::sin(th) + 2 * ar * ((1 - kappa) * std::sin(th) + std::sin(3 * th)) -
                            2 * std::pow(ar, 3) * std::sin(3 * th))));
  };
  auto make = [=](int n) {
    auto s = test::spec_for(patch, AnalysisType::PlaneStress, Ek, nuk, 1, refinement({2, 2}, n));
    s.fixed = {{"y0", {1}}, {"x0", {0}}};
    return s;
  };
  auto traction = [=](const Vec& x, const Vec& n) {
    const Vec s = stress(x);
    return Vec(Eigen::Vector2d(s(0) * n(0) + s(2) * n(1), s(2) * n(0) + s(1) * n(1)));
  };
  check_rates(make, {{"outer", traction}}, Exact{displacement, stress}, 2);
}

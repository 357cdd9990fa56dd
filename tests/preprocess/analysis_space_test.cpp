// Element extraction: the rational element functions reproduce the patch's geometry and
// basis, form a partition of unity, and their quadrature integrates areas and volumes.
#include "space/analysis_space.hpp"
#include "space/element_evaluator.hpp"
#include "space/gauss_quadrature.hpp"
#include "geometry/primitives.hpp"
#include "refine/patch_refinement.hpp"

#include <catch2/catch.hpp>
#include <random>

using namespace isosid::prep;

namespace {
/// integral of f(x) det J over the patch with `n` Gauss points per direction and element
template <class F>
double integrate(const AnalysisSpace& space, int n, F&& f) {
  const ElementEvaluator ev(space);
  const QuadratureRule rule = gauss_legendre(n);
  PointValues v;
  double sum = 0;
  const int pd = space.param_dim();
  for (const Element& e : space.elements) {
    int g[3] = {0, 0, 0};
    while (true) {
      double t[3] = {0, 0, 0}, w = 1;
      for (int d = 0; d < pd; ++d) {
        t[d] = rule.points(g[d]);
        w *= rule.weights(g[d]) * (e.hi(d) - e.lo(d));
      }
      ev.evaluate(e, t, v);
      sum += w * std::abs(v.J.determinant()) * f(v.x);
      int d = 0;
      while (d < pd && ++g[d] >= n) g[d++] = 0;
      if (d == pd) break;
    }
  }
  return sum;
}
}  // namespace

TEST_CASE("element functions reproduce the patch geometry and sum to one", "[assemble]") {
  NurbsPatch p = primitives::half_disk(0.01);
  elevate_degree(p, 0, 4);
  elevate_degree(p, 1, 3);
  subdivide_uniformly(p, 0, 3);
  subdivide_uniformly(p, 1, 2);
  const AnalysisSpace space = tensor_space(p);
  CHECK(space.elements.size() == 6);
  const ElementEvaluator ev(space);
  PointValues v;
  std::mt19937 gen(1);
  std::uniform_real_distribution<double> u01(0, 1);
  for (const Element& e : space.elements)
    for (int k = 0; k < 5; ++k) {
      const double t[3] = {u01(gen), u01(gen), 0};
      ev.evaluate(e, t, v);
      CHECK(v.R.sum() == Approx(1.0).epsilon(1e-13));
      CHECK(v.dR_dxi.colwise().sum().norm() < 1e-9);
      Eigen::VectorXd x;
      Eigen::MatrixXd J;
      p.evaluate(v.xi, x, &J);
      CHECK((v.x - x).norm() < 1e-15);
      CHECK((v.J - J).norm() < 1e-12 * J.norm());
    }
}

TEST_CASE("quadrature of the refined primitives gives exact areas and volumes", "[assemble]") {
  const double r = 0.01;
  NurbsPatch hd = primitives::half_disk(r);
  elevate_degree(hd, 0, 4);
  elevate_degree(hd, 1, 3);
  subdivide_uniformly(hd, 0, 8);
  subdivide_uniformly(hd, 1, 8);
  const AnalysisSpace s = tensor_space(hd);
  const double area = integrate(s, 6, [](const Eigen::VectorXd&) { return 1.0; });
  CHECK(area == Approx(M_PI * r * r / 2).epsilon(1e-12));
  const double volume = integrate(s, 6, [](const Eigen::VectorXd& x) { return 2 * M_PI * x(0); });
  CHECK(volume == Approx(4.0 / 3.0 * M_PI * r * r * r).epsilon(1e-12));
}

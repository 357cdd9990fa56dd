// Side quadrature; see boundary_quadrature.hpp.
#include "assemble/boundary_quadrature.hpp"

#include "space/element_evaluator.hpp"
#include "space/gauss_quadrature.hpp"
#include "geometry/multi_index.hpp"

#include <algorithm>

namespace isosid::prep {

std::vector<BoundaryPoint> boundary_points(const AnalysisSpace& space, const BodyElasticity& elasticity, int patch, PatchSide side,
                                           int points_per_direction, const SideInterval& interval) {
  const int pd = space.param_dim();
  std::vector<int> tangential;
  for (int d = 0; d < pd; ++d)
    if (d != side.direction) tangential.push_back(d);
  std::vector<QuadratureRule> rules;
  std::vector<int> rule_sizes;
  for (int d : tangential) {
    rules.push_back(gauss_legendre(points_per_direction > 0 ? points_per_direction : space.degrees[d] + 1));
    rule_sizes.push_back(int(rules.back().points.size()));
  }

  const ElementEvaluator evaluator(space);
  PointValues v;
  std::vector<BoundaryPoint> out;
  for (int e = 0; e < int(space.elements.size()); ++e) {
    const Element& el = space.elements[e];
    if (el.patch != patch || !space.on_side(el, side)) continue;
    // reference sub-range [t0, t1] of each tangential direction (the clipped interval)
    std::vector<double> t0(tangential.size(), 0.0), t1(tangential.size(), 1.0);
    bool empty = false;
    for (std::size_t k = 0; k < interval.size() && k < tangential.size(); ++k) {
      const int d = tangential[k];
      const double lo = std::max(el.lo(d), interval[k][0]), hi = std::min(el.hi(d), interval[k][1]);
      if (hi <= lo) empty = true;
      t0[k] = (lo - el.lo(d)) / (el.hi(d) - el.lo(d));
      t1[k] = (hi - el.lo(d)) / (el.hi(d) - el.lo(d));
    }
    if (empty) continue;
    MultiIndex g(int(tangential.size()), rule_sizes);
    do {
      double t[3] = {0, 0, 0};
      double w = 1;
      t[side.direction] = side.end;
      for (std::size_t k = 0; k < tangential.size(); ++k) {
        t[tangential[k]] = t0[k] + (t1[k] - t0[k]) * rules[k].points(g[int(k)]);
        w *= rules[k].weights(g[int(k)]) * (t1[k] - t0[k]) * (el.hi(tangential[k]) - el.lo(tangential[k]));
      }
      evaluator.evaluate(el, t, v);
      Eigen::VectorXd n;
      double jac = 0;
      if (pd == 2) {
        const Eigen::Vector2d tau = v.J.col(tangential[0]);
        n = Eigen::Vector2d(tau.y(), -tau.x());
        jac = tau.norm();
      } else {
        const Eigen::Vector3d a = v.J.col(tangential[0]), b = v.J.col(tangential[1]);
        n = a.cross(b);
        jac = n.norm();
      }
      // outward: against the direction into the body (increasing xi_d at end 0, decreasing at end 1)
      const double into = v.J.col(side.direction).dot(n);
      if ((side.end == 0 && into > 0) || (side.end == 1 && into < 0)) n = -n;
      if (jac > 0) {
        BoundaryPoint bp;
        bp.element = e;
        bp.t = Eigen::Vector3d(t[0], t[1], t[2]);
        bp.xi = v.xi;
        bp.x = v.x;
        bp.normal = n.normalized();
        bp.weight = w * jac * elasticity.of(el).measure(v.x);
        bp.R = v.R;
        out.push_back(std::move(bp));
      }
    } while (g.next());
  }
  return out;
}

}  // namespace isosid::prep

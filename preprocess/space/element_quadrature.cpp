// Tensor Gauss rules on elements; see element_quadrature.hpp.
#include "space/element_quadrature.hpp"

#include "space/gauss_quadrature.hpp"

namespace isosid::prep {

std::vector<QuadPoint> element_quadrature(const AnalysisSpace& space, const Element& e, int extra) {
  const int pd = space.param_dim();
  QuadratureRule rules[3];
  for (int d = 0; d < pd; ++d) rules[d] = gauss_legendre(space.degrees[std::size_t(d)] + 1 + extra);
  std::vector<QuadPoint> out;
  int g[3] = {0, 0, 0};
  while (true) {
    QuadPoint q;
    q.weight = 1;
    for (int d = 0; d < pd; ++d) {
      q.t[d] = rules[d].points(g[d]);
      q.weight *= rules[d].weights(g[d]) * (e.hi(d) - e.lo(d));
    }
    out.push_back(q);
    int d = 0;
    while (d < pd && ++g[d] >= int(rules[d].points.size())) g[d++] = 0;
    if (d == pd) break;
  }
  return out;
}

}  // namespace isosid::prep

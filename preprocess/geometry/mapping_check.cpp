// Fold-over check of a patch's mapping; see mapping_check.hpp.
#include "geometry/mapping_check.hpp"

#include "geometry/multi_index.hpp"
#include "isosid/format/error.hpp"

#include <cmath>
#include <vector>

namespace isosid::prep {

void check_mapping(const NurbsPatch& patch, const std::string& file, const std::string& field) {
  const int pd = patch.param_dim();
  if (pd != patch.phys_dim()) return;  // only square Jacobians have a determinant with a sign
  // sample parameters per direction: 2 (p + 1) interior points of every non-empty knot span
  std::vector<std::vector<double>> axes(static_cast<std::size_t>(pd));
  for (int d = 0; d < pd; ++d) {
    const Eigen::VectorXd& k = patch.knots[std::size_t(d)];
    const int m = 2 * (patch.degrees[std::size_t(d)] + 1);
    for (Eigen::Index s = 0; s + 1 < k.size(); ++s)
      if (k(s + 1) > k(s))
        for (int i = 0; i < m; ++i) axes[std::size_t(d)].push_back(k(s) + (i + 0.5) / m * (k(s + 1) - k(s)));
  }
  std::vector<int> counts;
  for (const auto& a : axes) counts.push_back(int(a.size()));
  double largest = 0, smallest = INFINITY;
  int positive = 0, negative = 0;
  Eigen::VectorXd xi(pd), x, worst_xi(pd);
  Eigen::MatrixXd J;
  MultiIndex ijk(pd, counts);
  do {
    for (int d = 0; d < pd; ++d) xi(d) = axes[std::size_t(d)][std::size_t(ijk[d])];
    patch.evaluate(xi, x, &J);
    const double det = J.determinant();
    (det > 0 ? positive : negative) += 1;
    largest = std::max(largest, std::abs(det));
    if (std::abs(det) < smallest) smallest = std::abs(det), worst_xi = xi;
  } while (ijk.next());
  auto at = [&] {
    std::string s = "(";
    for (int d = 0; d < pd; ++d) s += (d ? ", " : "") + std::to_string(worst_xi(d));
    return s + ")";
  };
  if (positive > 0 && negative > 0)
    throw format::InputError(file, field, "the patch folds over itself (its Jacobian changes sign inside, near parameter " + at() +
                                              "): a self-intersecting or partly inverted patch");
  if (!(smallest > 1e-10 * largest))
    throw format::InputError(file, field, "the patch's mapping is singular inside (Jacobian determinant 0 near parameter " + at() + ")");
}

}  // namespace isosid::prep

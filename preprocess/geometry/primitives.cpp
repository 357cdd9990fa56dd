// Control nets of the primitives; see primitives.hpp.
#include "geometry/primitives.hpp"

#include <cmath>

namespace isosid::prep::primitives {
namespace {

const double kS = 1.0 / std::sqrt(2.0);

Eigen::VectorXd knots(std::initializer_list<double> k) {
  Eigen::VectorXd v(Eigen::Index(k.size()));
  Eigen::Index i = 0;
  for (double x : k) v(i++) = x;
  return v;
}

/// Builds a 2D patch from tables in the style of [R1]'s eq. 35-41, indexed [i][j] (i along xi, j
/// along eta).
NurbsPatch from_tables(int p, int q, const Eigen::VectorXd& U, const Eigen::VectorXd& V,
                       const std::vector<std::vector<double>>& X, const std::vector<std::vector<double>>& Y,
                       const std::vector<std::vector<double>>& W) {
  NurbsPatch patch;
  patch.degrees = {p, q};
  patch.knots = {U, V};
  const int n = int(X.size()), m = int(X[0].size());
  patch.points.resize(n * m, 2);
  patch.weights.resize(n * m);
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i) {
      const int k = i + n * j;
      patch.points(k, 0) = X[std::size_t(i)][std::size_t(j)];
      patch.points(k, 1) = Y[std::size_t(i)][std::size_t(j)];
      patch.weights(k) = W[std::size_t(i)][std::size_t(j)];
    }
  return patch;
}

}  // namespace

NurbsPatch half_disk(double r) {
  NurbsPatch p = from_tables(2, 1, knots({0, 0, 0, 1, 1, 1}), knots({0, 0, 1, 1}),
                             {{0, 0}, {r, r}, {r, r}}, {{-r, r}, {-r, r}, {0, 0}}, {{1, 1}, {kS, kS}, {1, 1}});
  p.named_sides = {{"axis", {0, 0}}, {"lower", {1, 0}}, {"upper", {1, 1}}};
  return p;
}

NurbsPatch rod_with_spherical_end(double r, double l) {
  NurbsPatch p = from_tables(2, 1, knots({0, 0, 0, 1, 1, 1}), knots({0, 0, 1, 1}),
                             {{0, 0}, {r, r}, {r, r}}, {{0, l}, {0, l}, {r, l}}, {{1, 1}, {kS, 1}, {1, 1}});
  p.named_sides = {{"axis", {0, 0}}, {"lateral", {0, 1}}, {"cap", {1, 0}}, {"top", {1, 1}}};
  return p;
}

NurbsPatch disk(double r) {
  const double a = r * kS, b = 2 * r * kS;
  NurbsPatch p = from_tables(2, 2, knots({0, 0, 0, 1, 1, 1}), knots({0, 0, 0, 1, 1, 1}),
                             {{-a, 0, a}, {-b, 0, b}, {-a, 0, a}}, {{a, b, a}, {0, 0, 0}, {-a, -b, -a}},
                             {{1, kS, 1}, {kS, 1, kS}, {1, kS, 1}});
  p.named_sides = {{"top", {0, 0}}, {"bottom", {0, 1}}, {"left", {1, 0}}, {"right", {1, 1}}};
  return p;
}

NurbsPatch rectangle(double lx, double ly, double x0, double y0) {
  NurbsPatch p = from_tables(1, 1, knots({0, 0, 1, 1}), knots({0, 0, 1, 1}), {{x0, x0}, {x0 + lx, x0 + lx}},
                             {{y0, y0 + ly}, {y0, y0 + ly}}, {{1, 1}, {1, 1}});
  p.named_sides = {{"left", {0, 0}}, {"right", {0, 1}}, {"bottom", {1, 0}}, {"top", {1, 1}}};
  return p;
}

NurbsPatch box(double lx, double ly, double lz, const Eigen::Vector3d& origin) {
  NurbsPatch p;
  p.degrees = {1, 1, 1};
  p.knots = {knots({0, 0, 1, 1}), knots({0, 0, 1, 1}), knots({0, 0, 1, 1})};
  p.points.resize(8, 3);
  p.weights = Eigen::VectorXd::Ones(8);
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) p.points.row(i + 2 * j + 4 * k) = (origin + Eigen::Vector3d(i * lx, j * ly, k * lz)).transpose();
  p.named_sides = {{"left", {0, 0}}, {"right", {0, 1}}, {"bottom", {1, 0}},
                   {"top", {1, 1}},  {"back", {2, 0}},  {"front", {2, 1}}};
  return p;
}

NurbsPatch quarter_annulus(double ri, double ro) {
  NurbsPatch p = from_tables(2, 1, knots({0, 0, 0, 1, 1, 1}), knots({0, 0, 1, 1}), {{ri, ro}, {ri, ro}, {0, 0}},
                             {{0, 0}, {ri, ro}, {ri, ro}}, {{1, 1}, {kS, kS}, {1, 1}});
  p.named_sides = {{"x_axis", {0, 0}}, {"y_axis", {0, 1}}, {"inner", {1, 0}}, {"outer", {1, 1}}};
  return p;
}

NurbsPatch revolve_about_y(const NurbsPatch& profile) {
  // unit circle about y in the z-x plane: x = cos(t), z = sin(t), nine points, weights 1, 1/sqrt(2)
  const double cx[9] = {1, 1, 0, -1, -1, -1, 0, 1, 1};
  const double cz[9] = {0, 1, 1, 1, 0, -1, -1, -1, 0};
  NurbsPatch p;
  p.degrees = {profile.degrees[0], profile.degrees[1], 2};
  p.knots = {profile.knots[0], profile.knots[1], knots({0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1})};
  const int n = profile.count();
  p.points.resize(9 * n, 3);
  p.weights.resize(9 * n);
  for (int k = 0; k < 9; ++k)
    for (int i = 0; i < n; ++i) {
      const double rho = profile.points(i, 0), y = profile.points(i, 1);
      p.points.row(k * n + i) << rho * cx[k], y, rho * cz[k];
      p.weights(k * n + i) = profile.weights(i) * (k % 2 ? kS : 1.0);
    }
  p.named_sides = profile.named_sides;
  return p;
}

NurbsPatch ball(double r) { return revolve_about_y(half_disk(r)); }

NurbsPatch ball_spherical(double r) {
  // the profile: the radius eta times the semicircle xi, three rational arcs of 60 deg (middle
  // weights cos 30 deg), so that the equator lies inside the middle arc's span, where the basis
  // is smooth (two quarter arcs would put their C0 joint on it, under every in-plane impact);
  // the centre row collapses to the origin with the semicircle's weights
  const double c = std::sqrt(3.0) / 2, t = r / c;  // cos 30 deg; the arcs' middle points' distance
  const std::vector<double> lat = {-90, -60, -30, 0, 30, 60, 90};
  std::vector<std::vector<double>> X, Y, W;
  for (std::size_t i = 0; i < lat.size(); ++i) {
    const double a = lat[i] * M_PI / 180, d = i % 2 ? t : r, w = i % 2 ? c : 1.0;
    X.push_back({0, i == 0 || i == 6 ? 0.0 : d * std::cos(a)});
    Y.push_back({0, d * std::sin(a)});
    W.push_back({w, w});
  }
  NurbsPatch p = revolve_about_y(from_tables(2, 1, knots({0, 0, 0, 1.0 / 3, 1.0 / 3, 2.0 / 3, 2.0 / 3, 1, 1, 1}), knots({0, 0, 1, 1}), X, Y, W));
  p.named_sides = {{"surface", {1, 1}}};
  return p;
}

NurbsPatch cylinder_rod(double r, double l) {
  NurbsPatch p = revolve_about_y(rectangle(r, l));
  p.named_sides = {{"axis", {0, 0}}, {"lateral", {0, 1}}, {"bottom", {1, 0}}, {"top", {1, 1}}};
  return p;
}

}  // namespace isosid::prep::primitives

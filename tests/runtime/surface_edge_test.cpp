// Edge elements of contact surfaces (runtime/contact/surface_edge): where a surface really ends,
// against poles and seams where it does not. Synthetic surfaces of three Gauss points per
// element direction, placed on exact geometry.
#include "contact/surface_edge.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <functional>
#include <set>

using namespace isosid;

namespace {
constexpr double kGauss[3] = {0.1127, 0.5, 0.8873};  // 3-point Gauss abscissas on [0, 1]

/// A surface of nu x nv elements over parameters [0, u_max] x [0, 1] (nv = 0: a curve over
/// [0, u_max]); the side's fixed parameter is the last column, 0. `place` maps (u, v) to the
/// body-frame position.
format::ContactSurface grid(int nu, int nv, double u_max, const std::function<Eigen::VectorXd(double, double)>& place) {
  const bool curve = nv == 0;
  const int dim = int(place(0, 0).size());
  std::vector<Eigen::VectorXd> params, positions;
  std::vector<int> elements;
  for (int eu = 0; eu < nu; ++eu)
    for (int ev = 0; ev < std::max(nv, 1); ++ev)
      for (double gu : kGauss)
        for (int iv = 0; iv < (curve ? 1 : 3); ++iv) {
          const double u = (eu + gu) / nu * u_max, v = curve ? 0.0 : (ev + kGauss[iv]) / nv;
          Eigen::VectorXd p = Eigen::VectorXd::Zero(curve ? 2 : 3);
          p(0) = u;
          if (!curve) p(1) = v;
          params.push_back(p);
          positions.push_back(place(u, v));
          elements.push_back(eu * std::max(nv, 1) + ev);
        }
  format::ContactSurface s;
  s.name = "contact";
  const Eigen::Index n = Eigen::Index(params.size());
  s.parameter.resize(n, params[0].size());
  s.position.resize(n, dim);
  s.element.resize(n);
  s.weight = Eigen::VectorXd::Ones(n);
  for (Eigen::Index g = 0; g < n; ++g) {
    s.parameter.row(g) = params[std::size_t(g)].transpose();
    s.position.row(g) = positions[std::size_t(g)].transpose();
    s.element(g) = elements[std::size_t(g)];
  }
  return s;
}

/// The elements whose points are marked (all of an element's points must agree).
std::set<int> marked_elements(const format::ContactSurface& s, const std::vector<char>& edge) {
  std::set<int> out;
  for (Eigen::Index g = 0; g < s.points(); ++g)
    if (edge[std::size_t(g)]) out.insert(s.element(g));
  for (Eigen::Index g = 0; g < s.points(); ++g) CHECK(bool(edge[std::size_t(g)]) == bool(out.count(s.element(g))));
  return out;
}
}  // namespace

TEST_CASE("surface edges: an axisymmetric cap ends at its rim, not at the pole", "[runtime][unit]") {
  // the arc of a sphere r = 10 mm from the pole (u = 0, on the axis) to 0.2 rad
  const auto cap = grid(6, 0, 0.2, [](double u, double) { return Eigen::Vector2d(0.01 * std::sin(u), -0.01 * std::cos(u)); });
  CHECK(marked_elements(cap, run::edge_points(cap, format::AnalysisType::Axisymmetric)) == std::set<int>{5});
  // the same curve in a plane body has two ends
  CHECK(marked_elements(cap, run::edge_points(cap, format::AnalysisType::PlaneStrain)) == std::set<int>{0, 5});
  // moved off the axis, an axisymmetric curve has two ends too
  const auto ring = grid(6, 0, 0.2, [](double u, double) { return Eigen::Vector2d(0.05 + 0.01 * std::sin(u), -0.01 * std::cos(u)); });
  CHECK(marked_elements(ring, run::edge_points(ring, format::AnalysisType::Axisymmetric)) == std::set<int>{0, 5});
}

TEST_CASE("surface edges: a 3D cap of revolution ends at its rim only (pole and seam are no ends)", "[runtime][unit]") {
  // u: polar angle from the pole to 0.3 rad (4 elements), v: the full turn (8 elements)
  const auto cap = grid(4, 8, 0.3, [](double u, double v) {
    return Eigen::Vector3d(0.01 * std::sin(u) * std::cos(2 * M_PI * v), -0.01 * std::cos(u), 0.01 * std::sin(u) * std::sin(2 * M_PI * v));
  });
  std::set<int> rim;
  for (int ev = 0; ev < 8; ++ev) rim.insert(3 * 8 + ev);
  CHECK(marked_elements(cap, run::edge_points(cap, format::AnalysisType::Solid)) == rim);
  // half a turn: the cut at v = 0 and v = 1 is a real end now
  const auto half = grid(4, 8, 0.3, [](double u, double v) {
    return Eigen::Vector3d(0.01 * std::sin(u) * std::cos(M_PI * v), -0.01 * std::cos(u), 0.01 * std::sin(u) * std::sin(M_PI * v));
  });
  std::set<int> ends = rim;
  for (int eu = 0; eu < 4; ++eu) ends.insert({eu * 8, eu * 8 + 7});
  CHECK(marked_elements(half, run::edge_points(half, format::AnalysisType::Solid)) == ends);
}

TEST_CASE("surface edges: a flat 3D patch ends on all four sides", "[runtime][unit]") {
  const auto square = grid(5, 5, 1.0, [](double u, double v) { return Eigen::Vector3d(0.02 * u, 0.0, 0.02 * v); });
  const std::set<int> marked = marked_elements(square, run::edge_points(square, format::AnalysisType::Solid));
  CHECK(marked.size() == 16);  // the 5 x 5 elements less the 3 x 3 inside
  CHECK(marked.count(2 * 5 + 2) == 0);
}

TEST_CASE("surface edges: the end of a one-patch body's side is its corner, not an end of the surface", "[runtime][unit]") {
  // a plane bar's bottom side (eta0), x = 0.1 u over u in [0, 1], 6 elements
  format::MasterPatch side;
  side.knots = {(Eigen::VectorXd(7) << 0, 0, 0, 0.5, 1, 1, 1).finished()};
  auto whole = grid(6, 0, 1.0, [](double u, double) { return Eigen::Vector2d(0.1 * u, 0.0); });
  whole.side = "eta0";
  CHECK(marked_elements(whole, run::edge_points(whole, format::AnalysisType::PlaneStrain, &side)).empty());
  CHECK(marked_elements(whole, run::edge_points(whole, format::AnalysisType::PlaneStrain)) == std::set<int>{0, 5});  // side unknown
  // an interval of the side: its end inside the side is an end, its end at the corner is not
  auto part = grid(6, 0, 0.5, [](double u, double) { return Eigen::Vector2d(0.1 * u, 0.0); });
  part.side = "eta0";
  CHECK(marked_elements(part, run::edge_points(part, format::AnalysisType::PlaneStrain, &side)) == std::set<int>{5});
  // on one patch of several, the side may go on in the next patch: both ends stay ends
  whole.patch = "left";
  CHECK(marked_elements(whole, run::edge_points(whole, format::AnalysisType::PlaneStrain, &side)) == std::set<int>{0, 5});
}

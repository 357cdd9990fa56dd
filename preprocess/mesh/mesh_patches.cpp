// Mesh elements as Bezier patches; see mesh_patches.hpp.
#include "mesh/mesh_patches.hpp"

#include "isosid/format/error.hpp"

#include <algorithm>
#include <map>

namespace isosid::prep {

std::vector<ElementEdge> boundary_chain(const QuadMesh& mesh, const std::vector<std::array<int, 3>>& edges,
                                        const std::string& file, const std::string& field) {
  std::map<std::pair<int, int>, ElementEdge> by_corners;  // a boundary edge belongs to one element
  for (int e = 0; e < int(mesh.quads.size()); ++e)
    for (int k = 0; k < 4; ++k) {
      const int a = mesh.quads[std::size_t(e)][std::size_t(k)], b = mesh.quads[std::size_t(e)][std::size_t((k + 1) % 4)];
      by_corners[{std::min(a, b), std::max(a, b)}] = {e, k};
    }
  std::map<int, ElementEdge> starting_at;  // by the corner each edge starts from
  std::map<int, int> ends;
  for (const auto& line : edges) {
    const auto found = by_corners.find({std::min(line[0], line[1]), std::max(line[0], line[1])});
    if (found == by_corners.end()) throw format::InputError(file, field, "a boundary edge of the mesh belongs to no element");
    const ElementEdge ee = found->second;
    const int start = mesh.quads[std::size_t(ee.element)][std::size_t(ee.edge)];
    starting_at[start] = ee;
    ++ends[mesh.quads[std::size_t(ee.element)][std::size_t((ee.edge + 1) % 4)]];
  }
  int first = -1;
  for (const auto& [start, ee] : starting_at)
    if (!ends.count(start)) first = start;
  std::vector<ElementEdge> chain;
  for (int at = first; starting_at.count(at) && chain.size() < edges.size();) {
    const ElementEdge ee = starting_at.at(at);
    chain.push_back(ee);
    at = mesh.quads[std::size_t(ee.element)][std::size_t((ee.edge + 1) % 4)];
  }
  if (first < 0 || chain.size() != edges.size())
    throw format::InputError(file, field, "its " + std::to_string(edges.size()) + " boundary edges do not form one chain");
  return chain;
}

NurbsPatch bezier_patch(const QuadMesh& mesh, int element, int turn) {
  const std::array<int, 9>& q = mesh.quads[std::size_t(element)];
  auto corner = [&](int i) { return q[std::size_t((i + turn) % 4)]; };
  auto middle = [&](int i) { return q[std::size_t(4 + (i + turn) % 4)]; };
  // the nodes on the 3 x 3 grid (i along xi, j along eta): corners 0 1 2 3 counter-clockwise
  const int grid[3][3] = {{corner(0), middle(3), corner(3)}, {middle(0), q[8], middle(2)}, {corner(1), middle(1), corner(2)}};
  Eigen::Matrix3d T;  // Lagrange values at 0, 1/2, 1 -> Bezier control points
  T << 1, 0, 0, -0.5, 2, -0.5, 0, 0, 1;
  NurbsPatch p;
  p.degrees = {2, 2};
  const Eigen::VectorXd U = (Eigen::VectorXd(6) << 0, 0, 0, 1, 1, 1).finished();
  p.knots = {U, U};
  p.weights = Eigen::VectorXd::Ones(9);
  p.points.resize(9, 2);
  for (int c = 0; c < 2; ++c) {
    Eigen::Matrix3d X;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) X(i, j) = mesh.nodes(grid[i][j], c);
    const Eigen::Matrix3d B = T * X * T.transpose();
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) p.points(i + 3 * j, c) = B(i, j);
  }
  return p;
}

}  // namespace isosid::prep

// The viewing mesh; see visual_mesh.hpp.
#include "sid/visual_mesh.hpp"

#include "assemble/point_operator.hpp"
#include "isosid/format/error.hpp"

#include <array>
#include <cmath>
#include <map>

namespace isosid::prep {
namespace {

/// Corner offsets of a VTK quadrilateral / hexahedron in (i, j, k) steps.
constexpr int kQuad[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
constexpr int kHex[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};

/// The point operator at reference coordinates t of element e, whose Jacobian determinant at
/// its centre is `regular`. Where the mapping degenerates
/// (a patch side collapsed to a point: the pole of a ball, the centre of a disk; the axis of
/// an axisymmetric body), strains there are not defined: the stress is taken a thousandth of
/// the element inside, where its Jacobian is regular.
PointOperator operator_at(const BodyModel& body, const Element& e, double regular, double t[3]) {
  PointOperator op = point_operator(body.space, body.dofs, body.elasticity, e, t);
  if (std::abs(op.det_J) > 1e-6 * regular && op.B.allFinite()) return op;
  double inside[3];
  for (int d = 0; d < 3; ++d) inside[d] = t[d] + 1e-3 * (0.5 - t[d]);
  PointOperator shifted = point_operator(body.space, body.dofs, body.elasticity, e, inside);
  shifted.x = op.x;  // drawn where it is; only its strains come from inside
  shifted.N = op.N;
  return shifted;
}

}  // namespace

format::VisualMesh visual_mesh(const BodyModel& body, const VisualSpec& spec, const Eigen::MatrixXd& Phi_nodal) {
  const AnalysisSpace& space = body.space;
  const int pd = space.param_dim(), dim = body.dofs.dim(), s = spec.subdivisions;
  const auto comps = body.elasticity.stress_components();
  const auto nc = Eigen::Index(spec.stress ? comps.size() : 0);
  format::VisualMesh v;
  v.corners_per_cell = pd == 3 ? 8 : 4;
  if (spec.stress) v.stress_components = comps;

  // points keyed by patch and grid position in the patch's parameter box, shared by neighbours
  std::map<std::array<long long, 4>, int> index_of;
  std::vector<Eigen::VectorXd> position;
  std::vector<Eigen::MatrixXd> displacement_rows, stress_rows;
  double regular = 0;  // |det J| at the centre of the element being cut
  auto point = [&](const Element& e, const std::array<int, 3>& ijk) {
    double t[3] = {0, 0, 0};
    std::array<long long, 4> key{e.patch, 0, 0, 0};
    const PatchRange& box = space.patch_boxes[std::size_t(e.patch)];
    for (int d = 0; d < pd; ++d) {
      t[d] = double(ijk[std::size_t(d)]) / s;
      const double xi = e.lo(d) + t[d] * (e.hi(d) - e.lo(d));
      key[std::size_t(d) + 1] = std::llround((xi - box.lo(d)) / (box.hi(d) - box.lo(d)) * 0x1p40);
    }
    const auto [it, added] = index_of.emplace(key, int(position.size()));
    if (!added) return it->second;
    const PointOperator op = operator_at(body, e, regular, t);
    const Eigen::MatrixXd local = op.gather(Phi_nodal);
    position.push_back(op.x);
    displacement_rows.push_back(op.N * local);
    if (nc) stress_rows.push_back(body.elasticity.of(e).D() * op.B * local);
    return it->second;
  };

  std::vector<int> cells;
  const int nk = pd == 3 ? s : 1;
  for (const Element& e : space.elements) {
    double centre[3] = {0.5, 0.5, 0.5};
    regular = std::abs(point_operator(body.space, body.dofs, body.elasticity, e, centre).det_J);
    for (int k = 0; k < nk; ++k)
      for (int j = 0; j < s; ++j)
        for (int i = 0; i < s; ++i)
          for (int c = 0; c < v.corners_per_cell; ++c) {
            const int* corner = pd == 3 ? kHex[c] : kQuad[c];
            cells.push_back(point(e, {i + corner[0], j + corner[1], pd == 3 ? k + corner[2] : 0}));
          }
  }

  const auto n = Eigen::Index(position.size()), nq = Phi_nodal.cols();
  v.position.resize(n, dim);
  v.Phi.resize(n * dim, nq);
  v.S.resize(n * nc, nq);
  for (Eigen::Index p = 0; p < n; ++p) {
    v.position.row(p) = position[std::size_t(p)].transpose();
    v.Phi.middleRows(p * dim, dim) = displacement_rows[std::size_t(p)];
    if (nc) v.S.middleRows(p * nc, nc) = stress_rows[std::size_t(p)];
  }
  v.cells = Eigen::Map<const Eigen::VectorXi>(cells.data(), Eigen::Index(cells.size()));
  return v;
}

}  // namespace isosid::prep

// SID viewing meshes as VTK grids; see visual_grid.hpp.
#include "isosid/format/visual_grid.hpp"

#include "isosid/format/error.hpp"

#include <cstdio>

namespace isosid::format {

vtk::UnstructuredGrid visual_grid(const VisualMesh& visual) {
  vtk::UnstructuredGrid grid;
  grid.points.setZero(visual.points(), 3);
  grid.points.leftCols(visual.position.cols()) = visual.position;
  grid.add_cells(visual.cells, visual.corners_per_cell, visual.corners_per_cell == 8 ? vtk::Hexahedron : vtk::Quad);
  return grid;
}

vtk::UnstructuredGrid mode_shape_grid(const Sid& sid) {
  if (!sid.visual) throw ComputationError("the SID of " + sid.body_name + " has no viewing mesh (/visual)");
  const VisualMesh& v = *sid.visual;
  vtk::UnstructuredGrid grid = visual_grid(v);
  const int dim = sid.dim();
  char name[32];
  for (Eigen::Index k = 0; k < sid.nq(); ++k) {
    std::snprintf(name, sizeof name, "mode_%03d", int(k + 1));
    vtk::PointArray shape{name, 3, std::vector<double>(std::size_t(3 * v.points()), 0.0)};
    for (Eigen::Index p = 0; p < v.points(); ++p)
      for (int a = 0; a < dim; ++a) shape.values[std::size_t(3 * p + a)] = v.Phi(p * dim + a, k);
    grid.point_data.push_back(std::move(shape));
  }
  const Eigen::VectorXd& f = sid.refmod.frequencies_hz;
  grid.field_data.push_back({"frequency_hz", 1, std::vector<double>(f.data(), f.data() + f.size())});
  return grid;
}

}  // namespace isosid::format

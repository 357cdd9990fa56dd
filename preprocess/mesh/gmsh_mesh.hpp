// The gmsh side of meshed bodies: the primitive's 2D section built with the OpenCASCADE
// kernel, meshed with quadratic quadrilaterals (9 nodes, curved edges on the geometry) whose
// size grows from contact_element_size at the contact point to element_size away from it.
#pragma once
#include "model/model_file.hpp"

#include <Eigen/Dense>
#include <array>
#include <map>
#include <string>
#include <vector>

namespace isosid::prep {

struct QuadMesh {
  Eigen::MatrixXd nodes;                  ///< n x 2, m
  /// gmsh's 9-node order: corners counter-clockwise, then the midpoints of edges 01 12 23 30,
  /// then the centre
  std::vector<std::array<int, 9>> quads;
  /// the primitive's named sides: their 3-node edges (end, end, middle), as gmsh lists them
  std::map<std::string, std::vector<std::array<int, 3>>> sides;
};

/// Meshes the spec's primitive; InputError(file, "mesh...") if gmsh cannot (bad sizes, a
/// geometry it refuses, a mesh that is not all quadrilaterals).
QuadMesh gmsh_quad_mesh(const MeshSpec& spec, const std::string& file);

}  // namespace isosid::prep

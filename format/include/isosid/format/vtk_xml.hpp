// ParaView's file formats, written without VTK: an unstructured grid (.vtu, XML with base64
// binary arrays, VTK's "binary" format) and a time collection of them (.pvd). Used by
// isosid-run for the deformed bodies and contact points over time and by isosid-info for
// mode shapes. Every file is written atomically.
#pragma once
#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

namespace isosid::format::vtk {

/// VTK cell type numbers (vtkCellType.h).
enum CellType : std::uint8_t { Vertex = 1, Quad = 9, Hexahedron = 12 };

/// One named point array: `components` values per point, point after point.
struct PointArray {
  std::string name;
  int components = 1;
  std::vector<double> values;
};

struct UnstructuredGrid {
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> points;  ///< npts x 3, m
  std::vector<std::int64_t> connectivity;  ///< the points of every cell, cell after cell
  std::vector<std::int64_t> offsets;       ///< per cell: the end of its points in connectivity
  std::vector<std::uint8_t> types;         ///< per cell: CellType
  std::vector<PointArray> point_data;
  std::vector<PointArray> field_data;      ///< whole-grid values (e.g. time, mode frequencies)

  /// Cells of `corners` points each from a flat list of point indices.
  void add_cells(const Eigen::VectorXi& flat, int corners, CellType type);
};

/// Writes `grid` to `path` (.vtu).
void write_vtu(const std::string& path, const UnstructuredGrid& grid);

/// One entry of a .pvd collection: the file (relative to the .pvd) of one part at one time.
struct CollectionEntry {
  double time = 0;
  int part = 0;
  std::string name;  ///< the part's name (ParaView shows it as the block name)
  std::string file;
};

/// A name usable in a file name: letters, digits, '-', '_' and '.' kept, every other
/// character (a '/', a space) becomes '_'; never empty, never "." or "..".
std::string file_safe(const std::string& name);

/// Writes a .pvd collection listing `entries`.
void write_pvd(const std::string& path, const std::vector<CollectionEntry>& entries);

}  // namespace isosid::format::vtk

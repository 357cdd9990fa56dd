// ParaView's XML files; see vtk_xml.hpp. Layout from VTK's "VTK File Formats" (XML, version
// 0.1): a binary DataArray is base64 of a UInt32 byte count followed by the raw
// little-endian values.
#include "isosid/format/vtk_xml.hpp"

#include "isosid/format/atomic_output.hpp"
#include "isosid/format/error.hpp"

#include <cctype>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>

namespace isosid::format::vtk {
namespace {

std::string base64(const std::vector<unsigned char>& bytes) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = (unsigned(bytes[i]) << 16) | (unsigned(bytes[i + 1]) << 8) | bytes[i + 2];
    for (int s : {18, 12, 6, 0}) out += table[(v >> s) & 63];
  }
  if (const std::size_t rest = bytes.size() - i; rest > 0) {
    const unsigned v = (unsigned(bytes[i]) << 16) | (rest == 2 ? unsigned(bytes[i + 1]) << 8 : 0u);
    out += table[(v >> 18) & 63];
    out += table[(v >> 12) & 63];
    out += rest == 2 ? table[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

/// One binary DataArray element (x86 and ARM are little-endian, as the header declares).
template <class T>
std::string data_array(const char* type, const std::string& name, int components, const T* values, std::size_t count,
                       const std::string& attributes = {}) {
  const std::size_t bytes = count * sizeof(T);
  if (bytes > std::numeric_limits<std::uint32_t>::max()) throw ComputationError("a VTK array '" + name + "' exceeds 4 GiB");
  std::vector<unsigned char> raw(sizeof(std::uint32_t) + bytes);
  const auto header = std::uint32_t(bytes);
  std::memcpy(raw.data(), &header, sizeof header);
  if (bytes) std::memcpy(raw.data() + sizeof header, values, bytes);
  std::string out = std::string("<DataArray type=\"") + type + "\"";
  if (!name.empty()) out += " Name=\"" + name + "\"";
  if (components > 1) out += " NumberOfComponents=\"" + std::to_string(components) + "\"";
  return out + attributes + " format=\"binary\">" + base64(raw) + "</DataArray>\n";
}

void check_array(const PointArray& a, std::size_t entries, const std::string& where) {
  if (a.components < 1 || a.values.size() != entries * std::size_t(a.components))
    throw ComputationError(where + " array '" + a.name + "' has " + std::to_string(a.values.size()) + " values, expected " +
                           std::to_string(entries) + " x " + std::to_string(a.components));
}

std::string escaped(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace

void UnstructuredGrid::add_cells(const Eigen::VectorXi& flat, int corners, CellType type) {
  for (Eigen::Index c = 0; c + corners <= flat.size(); c += corners) {
    for (int k = 0; k < corners; ++k) connectivity.push_back(flat(c + k));
    offsets.push_back(std::int64_t(connectivity.size()));
    types.push_back(type);
  }
}

void write_vtu(const std::string& path, const UnstructuredGrid& grid) {
  const auto n = std::size_t(grid.points.rows());
  if (grid.offsets.size() != grid.types.size()) throw ComputationError(path + ": cell offsets and types differ in number");
  std::string xml =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\" header_type=\"UInt32\">\n"
      "<UnstructuredGrid>\n";
  if (!grid.field_data.empty()) {
    xml += "<FieldData>\n";
    for (const PointArray& a : grid.field_data) {
      const std::size_t tuples = a.values.size() / std::size_t(std::max(a.components, 1));
      check_array(a, tuples, path + ": field");
      xml += data_array("Float64", escaped(a.name), a.components, a.values.data(), a.values.size(),
                        " NumberOfTuples=\"" + std::to_string(tuples) + "\"");
    }
    xml += "</FieldData>\n";
  }
  xml += "<Piece NumberOfPoints=\"" + std::to_string(n) + "\" NumberOfCells=\"" + std::to_string(grid.types.size()) + "\">\n";
  xml += "<PointData>\n";
  for (const PointArray& a : grid.point_data) {
    check_array(a, n, path + ": point");
    xml += data_array("Float64", escaped(a.name), a.components, a.values.data(), a.values.size());
  }
  xml += "</PointData>\n<Points>\n";
  xml += data_array("Float64", "", 3, grid.points.data(), std::size_t(grid.points.size()));
  xml += "</Points>\n<Cells>\n";
  xml += data_array("Int64", "connectivity", 1, grid.connectivity.data(), grid.connectivity.size());
  xml += data_array("Int64", "offsets", 1, grid.offsets.data(), grid.offsets.size());
  xml += data_array("UInt8", "types", 1, grid.types.data(), grid.types.size());
  xml += "</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  write_text_atomically(path, xml);
}

std::string file_safe(const std::string& name) {
  std::string out = name;
  for (char& c : out)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.') c = '_';
  if (out.empty() || out.find_first_not_of('.') == std::string::npos) out = "_" + out;
  return out;
}

void write_pvd(const std::string& path, const std::vector<CollectionEntry>& entries) {
  std::string xml = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n<Collection>\n";
  char time[32];
  for (const CollectionEntry& e : entries) {
    std::snprintf(time, sizeof time, "%.17g", e.time);
    xml += std::string("<DataSet timestep=\"") + time + "\" part=\"" + std::to_string(e.part) + "\" name=\"" + escaped(e.name) +
           "\" file=\"" + escaped(e.file) + "\"/>\n";
  }
  xml += "</Collection>\n</VTKFile>\n";
  write_text_atomically(path, xml);
}

}  // namespace isosid::format::vtk

// Quadrilateral meshes from gmsh; see gmsh_mesh.hpp.
#include "mesh/gmsh_mesh.hpp"

#include "isosid/format/error.hpp"

#include <gmsh.h>

#include <cmath>
#include <stdexcept>
#include <unordered_map>

namespace isosid::prep {
namespace {

/// gmsh is one global model: initialized for one mesh (without the user's configuration
/// files, so the mesh depends on the model file alone), finalized however the meshing ends.
class GmshSession {
public:
  GmshSession() {
    gmsh::initialize(0, nullptr, false);
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("General.NumThreads", 1);
  }
  ~GmshSession() {
    try {
      gmsh::finalize();
    } catch (...) {  // nothing to report: the mesh is taken or the error already thrown
    }
  }
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;
};

/// gmsh's message on one line.
std::string one_line(std::string message) {
  for (char& c : message)
    if (c == '\n' || c == '\r') c = ' ';
  return message;
}

namespace occ = gmsh::model::occ;

/// The section's boundary curves by side name (the primitive's names) and the tag of its surface.
struct Section {
  std::map<std::string, std::vector<int>> curves;
  int surface = 0;
};

Section half_disk(double r) {
  Section s;
  const int centre = occ::addPoint(0, 0, 0), pole = occ::addPoint(0, -r, 0), equator = occ::addPoint(r, 0, 0),
            top = occ::addPoint(0, r, 0);
  s.curves["lower"] = {occ::addCircleArc(pole, centre, equator)};
  s.curves["upper"] = {occ::addCircleArc(equator, centre, top)};
  s.curves["axis"] = {occ::addLine(top, centre), occ::addLine(centre, pole)};  // the centre is a node (SID nodes sit there)
  const int loop = occ::addCurveLoop({s.curves["lower"][0], s.curves["upper"][0], s.curves["axis"][0], s.curves["axis"][1]});
  s.surface = occ::addPlaneSurface({loop});
  return s;
}

Section rod_with_spherical_end(double r, double l) {
  Section s;
  const int pole = occ::addPoint(0, 0, 0), centre = occ::addPoint(0, r, 0), shoulder = occ::addPoint(r, r, 0),
            corner = occ::addPoint(r, l, 0), top = occ::addPoint(0, l, 0);
  s.curves["cap"] = {occ::addCircleArc(pole, centre, shoulder)};
  s.curves["lateral"] = {occ::addLine(shoulder, corner)};
  s.curves["top"] = {occ::addLine(corner, top)};
  s.curves["axis"] = {occ::addLine(top, pole)};
  const int loop = occ::addCurveLoop({s.curves["cap"][0], s.curves["lateral"][0], s.curves["top"][0], s.curves["axis"][0]});
  s.surface = occ::addPlaneSurface({loop});
  return s;
}

}  // namespace

QuadMesh gmsh_quad_mesh(const MeshSpec& spec, const std::string& file) {
  try {
    const GmshSession session;
    gmsh::model::add("isosid");
    Section section;
    if (spec.primitive == "half_disk")
      section = half_disk(spec.radius);
    else if (spec.primitive == "rod_with_spherical_end")
      section = rod_with_spherical_end(spec.radius, spec.length);
    else
      throw format::InputError(file, "mesh.primitive", "unknown primitive '" + spec.primitive + "' (half_disk, rod_with_spherical_end)");
    const int pole = occ::addPoint(spec.contact_point(0), spec.contact_point(1), 0);
    occ::synchronize();
    // the size: contact_element_size within two elements of the contact point, then growing
    // by `growth` per element up to element_size. gmsh meshes at twice the size and splits
    // every quadrilateral into four (its only way to all-quadrilateral meshes)
    const double h0 = 2 * spec.contact_element_size, h1 = 2 * spec.element_size;
    const int distance = gmsh::model::mesh::field::add("Distance");
    gmsh::model::mesh::field::setNumbers(distance, "PointsList", {double(pole)});
    const int threshold = gmsh::model::mesh::field::add("Threshold");
    gmsh::model::mesh::field::setNumber(threshold, "InField", distance);
    gmsh::model::mesh::field::setNumber(threshold, "SizeMin", h0);
    gmsh::model::mesh::field::setNumber(threshold, "SizeMax", h1);
    gmsh::model::mesh::field::setNumber(threshold, "DistMin", 2 * h0);
    gmsh::model::mesh::field::setNumber(threshold, "DistMax", 2 * h0 + (h1 - h0) / (spec.growth - 1));
    gmsh::model::mesh::field::setAsBackgroundMesh(threshold);
    gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
    gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
    gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
    gmsh::option::setNumber("Mesh.Algorithm", 6);  // Frontal-Delaunay (8, the quad-oriented one, crashes with a size field in 4.8)
    gmsh::option::setNumber("Mesh.RecombineAll", 1);
    gmsh::option::setNumber("Mesh.SubdivisionAlgorithm", 1);
    gmsh::option::setNumber("Mesh.ElementOrder", 2);
    gmsh::option::setNumber("Mesh.SecondOrderIncomplete", 0);
    gmsh::model::mesh::generate(2);

    QuadMesh mesh;
    std::vector<std::size_t> tags;
    std::vector<double> xyz, parametric;
    gmsh::model::mesh::getNodes(tags, xyz, parametric);
    std::unordered_map<std::size_t, int> index;
    mesh.nodes.resize(Eigen::Index(tags.size()), 2);
    for (std::size_t i = 0; i < tags.size(); ++i) {
      index[tags[i]] = int(i);
      mesh.nodes.row(Eigen::Index(i)) << xyz[3 * i], xyz[3 * i + 1];
    }
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> element_tags, element_nodes;
    gmsh::model::mesh::getElements(types, element_tags, element_nodes, 2, section.surface);
    for (std::size_t t = 0; t < types.size(); ++t) {
      if (types[t] != 10)  // 10: the 9-node quadrilateral
        throw format::InputError(file, "mesh", "gmsh made elements other than 9-node quadrilaterals (type " + std::to_string(types[t]) + ")");
      for (std::size_t e = 0; e < element_tags[t].size(); ++e) {
        std::array<int, 9> q{};
        for (int k = 0; k < 9; ++k) q[std::size_t(k)] = index.at(element_nodes[t][9 * e + std::size_t(k)]);
        mesh.quads.push_back(q);
      }
    }
    for (const auto& [name, curves] : section.curves)
      for (int curve : curves) {
        gmsh::model::mesh::getElements(types, element_tags, element_nodes, 1, curve);
        for (std::size_t t = 0; t < types.size(); ++t)
          for (std::size_t e = 0; e < element_tags[t].size(); ++e)  // type 8: 3-node line
            mesh.sides[name].push_back({index.at(element_nodes[t][3 * e]), index.at(element_nodes[t][3 * e + 1]),
                                        index.at(element_nodes[t][3 * e + 2])});
      }
    if (mesh.quads.empty()) throw format::InputError(file, "mesh", "gmsh made no elements");
    return mesh;
  } catch (const format::InputError&) {
    throw;
  } catch (const std::string& error) {  // gmsh 4.8 throws its last error as a string
    throw format::InputError(file, "mesh", "gmsh could not mesh the section: " + one_line(error));
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception& e) {
    throw format::InputError(file, "mesh", "gmsh could not mesh the section: " + one_line(e.what()));
  } catch (...) {
    throw format::InputError(file, "mesh", "gmsh could not mesh the section (it reported no reason)");
  }
}

}  // namespace isosid::prep

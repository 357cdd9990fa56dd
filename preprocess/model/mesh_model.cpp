// Meshed-body model files; see mesh_model.hpp.
#include "model/mesh_model.hpp"

#include "mesh/gmsh_mesh.hpp"
#include "mesh/mesh_patches.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace isosid::prep {
namespace {

/// About how many elements the size field asks for: the section's area at element_size, plus
/// the graded zone as a half-disk around the contact point with the threshold's sizes.
double estimated_elements(const MeshSpec& s) {
  const double area = s.primitive == "half_disk" ? M_PI * s.radius * s.radius / 2 : s.radius * s.length;
  const double h0 = s.contact_element_size, h1 = s.element_size, d0 = 2 * h0, d1 = d0 + (h1 - h0) / (s.growth - 1);
  double graded = 0;
  const int n = 2000;
  for (int i = 0; i < n; ++i) {
    const double d = (i + 0.5) * d1 / n, h = d < d0 ? h0 : h0 + (d - d0) * (s.growth - 1);
    graded += M_PI * d * (d1 / n) / (h * h);
  }
  return graded + area / (h1 * h1);
}

MeshSpec read_mesh(const TomlView& t) {
  t.allow_only({"generator", "primitive", "radius", "length", "element_size", "contact_element_size", "growth", "contact_point"});
  if (t.string("generator", "gmsh") != "gmsh") t.fail("generator", "only \"gmsh\" meshes bodies");
  MeshSpec s;
  s.primitive = t.string("primitive");
  s.radius = t.positive("radius");
  if (s.primitive == "rod_with_spherical_end") {
    s.length = t.positive("length");
    if (s.length <= s.radius) t.fail("length", "must exceed the radius (the spherical end)");
  } else if (s.primitive != "half_disk") {
    t.fail("primitive", "unknown primitive '" + s.primitive + "' (half_disk, rod_with_spherical_end)");
  }
  s.element_size = t.positive("element_size");
  s.contact_element_size = t.positive("contact_element_size", s.element_size);
  if (s.contact_element_size > s.element_size) t.fail("contact_element_size", "exceeds element_size");
  const double size = s.primitive == "half_disk" ? 2 * s.radius : s.length;
  if (s.element_size > size) t.fail("element_size", "exceeds the body");
  if (s.contact_element_size < 1e-5 * size) t.fail("contact_element_size", "below 1e-5 of the body's size");
  s.growth = t.positive("growth", s.growth);
  if (s.growth <= 1.05 || s.growth > 3) t.fail("growth", "must lie in (1.05, 3]");
  // refused before gmsh runs: 2e5 nodes (4e5 DOFs) is far beyond the comparison bodies of the
  // validation scenes (the 2 mm rod has 14 000) and meshes in seconds; more would take minutes and
  // gigabytes
  constexpr double kMaxMeshNodes = 2e5;
  if (const double nodes = 4 * estimated_elements(s); nodes > kMaxMeshNodes) {
    char text[200];
    std::snprintf(text, sizeof text, "asks for about %.2g nodes, more than the %.0g a meshed body may have: give larger element sizes",
                  nodes, kMaxMeshNodes);
    t.fail("element_size", text);
  }
  s.contact_point = s.primitive == "half_disk" ? Eigen::Vector2d(0, -s.radius) : Eigen::Vector2d(0, 0);  // the pole
  if (t.has("contact_point")) {
    const std::vector<double> p = t.numbers("contact_point");
    if (p.size() != 2) t.fail("contact_point", "needs 2 coordinates (m)");
    s.contact_point << p[0], p[1];
  }
  return s;
}

/// The element that holds the physical point `at` (to the placement tolerance of its
/// patch), the nearest of those whose control net's box contains it; t.fail if none does.
int element_holding(const std::vector<PatchSpec>& elements, const GivenPoint& at, const TomlView& t) {
  int best = -1;
  double nearest = INFINITY;
  for (int e = 0; e < int(elements.size()); ++e) {
    const NurbsPatch& p = elements[std::size_t(e)].patch;
    const double margin = placement_tolerance(p);
    const Eigen::ArrayXd lo = p.points.colwise().minCoeff().transpose().array() - margin,
                         hi = p.points.colwise().maxCoeff().transpose().array() + margin;
    if ((at.value.array() < lo).any() || (at.value.array() > hi).any()) continue;
    const BodyPoint placed = place(p, at);
    if (placed.distance <= margin && placed.distance < nearest) nearest = placed.distance, best = e;
  }
  if (best < 0) t.fail("point", "lies outside the body");
  return best;
}

}  // namespace

void read_mesh_model(const TomlView& top, ModelSpec& m, const format::Material& material) {
  for (const char* key : {"geometry", "patch", "refinement", "boundary", "stress_line", "contact_resolution"})
    if (top.has(key)) top.fail(key, "not used by a meshed body ([mesh]): its geometry, size and contact resolution are in [mesh]");
  if (m.analysis != format::AnalysisType::Axisymmetric && m.analysis != format::AnalysisType::PlaneStrain &&
      m.analysis != format::AnalysisType::PlaneStress)
    top.table("body").fail("analysis", "meshed bodies are 2D sections (axisymmetric, plane_strain, plane_stress)");
  MeshSpec& spec = m.mesh.emplace(read_mesh(top.table("mesh")));
  const QuadMesh mesh = gmsh_quad_mesh(spec, m.file);

  // contact surfaces: boundary chains along a primitive side near the contact point; their
  // elements are turned so that the chain runs along their eta0 sides
  std::map<int, int> turn;  // element -> quarter turns
  struct Surface {
    ContactSurfaceSpec spec;
    std::vector<ElementEdge> chain;
  };
  std::vector<Surface> surfaces;
  std::vector<std::string> surface_names, node_names;
  for (const TomlView& c : top.tables("contact_surface")) {
    c.allow_only({"name", "side", "within"});
    Surface s;
    s.spec.name = unique_name(c, surface_names);
    const std::string side = c.string("side");
    const auto edges = mesh.sides.find(side);
    if (edges == mesh.sides.end()) c.fail("side", "the primitive has no side '" + side + "'");
    const double within = c.positive("within");
    std::vector<std::array<int, 3>> near;
    for (const auto& line : edges->second)
      if ((mesh.nodes.row(line[0]).transpose() - spec.contact_point).norm() <= within &&
          (mesh.nodes.row(line[1]).transpose() - spec.contact_point).norm() <= within)
        near.push_back(line);
    if (near.empty()) c.fail("within", "no edge of side '" + side + "' lies that close to the contact point");
    s.chain = boundary_chain(mesh, near, m.file, c.field("within"));
    for (const ElementEdge& ee : s.chain) {
      const auto [it, added] = turn.emplace(ee.element, ee.edge);
      if (!added && it->second != ee.edge) c.fail("side", "an element has two edges on contact surfaces (refine the mesh)");
    }
    surfaces.push_back(std::move(s));
  }
  for (int e = 0; e < int(mesh.quads.size()); ++e) {
    PatchSpec& p = m.patches.emplace_back();
    p.name = "element" + std::to_string(e);
    p.material = material;
    const auto t = turn.find(e);
    p.patch = bezier_patch(mesh, e, t == turn.end() ? 0 : t->second);
  }
  for (Surface& s : surfaces) {
    s.spec.side = "eta0";
    s.spec.patch = s.chain.front().element;
    for (std::size_t k = 1; k < s.chain.size(); ++k) s.spec.continued.push_back({s.chain[k].element, "eta0"});
    m.contact_surfaces.push_back(s.spec);
  }

  for (const TomlView& t : top.tables("node")) {
    t.allow_only({"name", "point"});
    NodeSpec n;
    n.name = unique_name(t, node_names);
    const std::vector<double> p = t.numbers("point");
    if (p.size() != 2) t.fail("point", "needs 2 coordinates (m)");
    n.at = {Eigen::Vector2d(p[0], p[1]), true};
    n.patch = element_holding(m.patches, n.at, t);
    m.nodes.push_back(n);
  }

  if (auto r = top.optional_table("reduction")) {
    r->allow_only({"method", "normal_modes", "interface_surface", "interface_points", "interface_point"});
    ReductionSpec& red = m.reduction;
    const std::optional<format::ReductionMethod> named = format::reduction_method_named(r->string("method"));
    const std::string offered = format::reduction_method_names([](const auto& t) { return t.meshed_bodies; });
    if (!named || !format::traits(*named).meshed_bodies) r->fail("method", "a meshed body is reduced by " + offered + " reduction");
    red.method = *named;
    red.normal_modes = r->integer_in("normal_modes", 1, 100000, 10);
    const bool interface_nodes = format::traits(red.method).interface_nodes;
    if (!interface_nodes)
      for (const char* key : {"interface_surface", "interface_points", "interface_point"})
        if (r->has(key))
          r->fail(key, "only used by method = " + format::reduction_method_names([](const auto& t) { return t.interface_nodes && t.meshed_bodies; }, "\""));
    if (interface_nodes) {
      red.interface_surface = r->string("interface_surface");
      if (std::none_of(m.contact_surfaces.begin(), m.contact_surfaces.end(), [&](const ContactSurfaceSpec& c) { return c.name == red.interface_surface; }))
        r->fail("interface_surface", "no contact_surface named '" + red.interface_surface + "'");
      red.interface_points = r->integer_in("interface_points", 1, int(kMaxControlPoints));
      red.interface_point = spec.contact_point;
      if (r->has("interface_point")) {
        const std::vector<double> p = r->numbers("interface_point");
        if (p.size() != 2) r->fail("interface_point", "needs 2 coordinates (m)");
        red.interface_point = Eigen::Vector2d(p[0], p[1]);
      }
    }
  }
  read_quadrature(top, m);
  read_visual(top, m);
  read_damping(top, m);
}

}  // namespace isosid::prep

// Model file parsing and validation; see model_file.hpp.
#include "model/model_file.hpp"

#include "geometry/mapping_check.hpp"
#include "model/body_model.hpp"
#include "model/mesh_model.hpp"
#include "model/model_tables.hpp"
#include "geometry/primitives.hpp"
#include "isosid/common/number_text.hpp"
#include "isosid/common/toml_fields.hpp"

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace isosid::prep {
namespace {

using common::TomlView;

const char* kComponents[3] = {"x", "y", "z"};

int direction_index(const TomlView& t, const std::string& key, int param_dim) {
  const std::string name = t.string(key);
  for (int d = 0; d < param_dim; ++d)
    if (name == direction_name(d)) return d;
  t.fail(key, "unknown direction '" + name + "' (use xi, eta" + (param_dim == 3 ? ", zeta)" : ")"));
}

NurbsPatch read_explicit_patch(const TomlView& g) {
  NurbsPatch p;
  p.degrees = g.integers_in("degrees", 1, kMaxDegree);
  for (const auto& k : g.number_rows("knots")) p.knots.push_back(Eigen::Map<const Eigen::VectorXd>(k.data(), Eigen::Index(k.size())));
  const auto cps = g.number_rows("control_points");
  const std::vector<double> w = g.numbers("weights");
  if (cps.empty()) g.fail("control_points", "no control points");
  p.points.resize(Eigen::Index(cps.size()), Eigen::Index(cps[0].size()));
  for (std::size_t i = 0; i < cps.size(); ++i) {
    if (cps[i].size() != cps[0].size()) g.fail("control_points", "rows of different length at " + std::to_string(i));
    for (std::size_t j = 0; j < cps[i].size(); ++j) p.points(Eigen::Index(i), Eigen::Index(j)) = cps[i][j];
  }
  p.weights = Eigen::Map<const Eigen::VectorXd>(w.data(), Eigen::Index(w.size()));
  if (p.degrees.empty()) g.fail("degrees", "needs 1 to 3 entries");
  if (p.knots.size() != p.degrees.size()) g.fail("knots", "one knot vector per degree required");
  validate_patch(p, g.file(), g.field("patch"));
  return p;
}

/// The primitives a [geometry] table names: each reads its own keys and builds its patch.
struct PrimitiveReader {
  const char* name;
  NurbsPatch (*read)(const TomlView& g);
};

/// The lengths of `key`, one positive entry per axis of a `dim`-dimensional box.
std::vector<double> box_lengths(const TomlView& g, const char* key, std::size_t dim) {
  const auto s = g.numbers(key);
  if (s.size() != dim || *std::min_element(s.begin(), s.end()) <= 0)
    g.fail(key, dim == 2 ? "needs two positive lengths [lx, ly]" : "needs three positive lengths [lx, ly, lz]");
  return s;
}

/// The box's `origin`: dim coordinates, zero if not given.
std::vector<double> box_origin(const TomlView& g, std::size_t dim) {
  const auto o = g.has("origin") ? g.numbers("origin") : std::vector<double>(dim, 0.0);
  if (o.size() != dim) g.fail("origin", dim == 2 ? "needs two coordinates" : "needs three coordinates");
  return o;
}

/// The two lengths of a primitive given by them alone, the second beyond the first.
std::pair<double, double> ordered_lengths(const TomlView& g, const char* shorter, const char* longer) {
  g.allow_only({"primitive", shorter, longer});
  const double a = g.positive(shorter), b = g.positive(longer);
  if (b <= a) g.fail(longer, std::string("must exceed ") + shorter);
  return {a, b};
}

/// A primitive given by its radius alone.
template <NurbsPatch (*build)(double)>
NurbsPatch of_radius(const TomlView& g) {
  g.allow_only({"primitive", "radius"});
  return build(g.positive("radius"));
}

constexpr PrimitiveReader kPrimitives[] = {
    {"half_disk", of_radius<primitives::half_disk>},
    {"rod_with_spherical_end",
     [](const TomlView& g) {
       const auto [radius, length] = ordered_lengths(g, "radius", "length");
       return primitives::rod_with_spherical_end(radius, length);
     }},
    {"disk", of_radius<primitives::disk>},
    {"quarter_annulus",
     [](const TomlView& g) {
       const auto [inner, outer] = ordered_lengths(g, "inner_radius", "outer_radius");
       return primitives::quarter_annulus(inner, outer);
     }},
    {"rectangle",
     [](const TomlView& g) {
       g.allow_only({"primitive", "size", "origin"});
       const auto s = box_lengths(g, "size", 2), o = box_origin(g, 2);
       return primitives::rectangle(s[0], s[1], o[0], o[1]);
     }},
    {"box",
     [](const TomlView& g) {
       g.allow_only({"primitive", "size", "origin"});
       const auto s = box_lengths(g, "size", 3), o = box_origin(g, 3);
       return primitives::box(s[0], s[1], s[2], Eigen::Vector3d(o[0], o[1], o[2]));
     }},
    {"ball", of_radius<primitives::ball>},
    {"ball_spherical", of_radius<primitives::ball_spherical>},
    {"cylinder_rod",
     [](const TomlView& g) {
       g.allow_only({"primitive", "radius", "length"});
       return primitives::cylinder_rod(g.positive("radius"), g.positive("length"));
     }},
    {"patch",
     [](const TomlView& g) {
       g.allow_only({"primitive", "degrees", "knots", "control_points", "weights"});
       return read_explicit_patch(g);
     }},
};

NurbsPatch read_geometry(const TomlView& g, format::AnalysisType analysis) {
  const std::string primitive = g.string("primitive");
  const auto reader = std::find_if(std::begin(kPrimitives), std::end(kPrimitives), [&](const PrimitiveReader& r) { return primitive == r.name; });
  if (reader == std::end(kPrimitives)) {
    std::string names;
    for (const PrimitiveReader& r : kPrimitives) names += std::string(names.empty() ? "" : ", ") + r.name;
    g.fail("primitive", "unknown primitive '" + primitive + "' (" + names + ")");
  }
  const NurbsPatch p = reader->read(g);
  const int dim = format::spatial_dim(analysis);
  if (p.param_dim() != dim || p.phys_dim() != dim)
    g.fail("primitive", "'" + primitive + "' is a " + std::to_string(p.param_dim()) + "D patch in " +
                            std::to_string(p.phys_dim()) + "D, but the analysis '" + format::to_string(analysis) +
                            "' needs " + std::to_string(dim) + "D");
  if (analysis == format::AnalysisType::Axisymmetric && p.points.col(0).minCoeff() < -1e-12 * p.points.cwiseAbs().maxCoeff())
    g.fail("primitive", "an axisymmetric body must lie at x >= 0 (x is the radius)");
  return p;
}

/// A `smallest` given as "contact": the element size of [contact_resolution].
double contact_sized(const TomlView& t, const std::string& key, const ContactResolutionSpec* resolution) {
  if (t.string(key) != "contact") t.fail(key, "must be a length in metres or \"contact\"");
  if (!resolution) t.fail(key, "\"contact\" needs a [contact_resolution] table (the expected contact radius)");
  return resolution->element_size();
}

/// What is wrong with a refined region `width` metres wide on `patch`, or "": wider than the
/// patch it would refine all of it, the global refinement THB is there to avoid (a 1 km
/// width on a 10 mm sphere asked for the whole sphere at the contact's element size).
std::string width_problem(double width, const NurbsPatch& patch) {
  const double size = patch_size(patch);
  if (width <= size) return "";
  return "a refined region " + common::number_text(width) + " m wide exceeds the patch it refines (" + common::number_text(size) +
         " m across its control net): refine the whole patch with subdivisions instead";
}

/// [refinement.hierarchical]: a parameter box, or a point with a physical width; how fine
/// (smallest element in metres, "contact", or elements across the box) and the level limits of [R2]
/// (docs/references.md).
HierarchicalRequest read_hierarchical(const TomlView& h, const NurbsPatch& patch, ContactResolutionSpec* resolution) {
  h.allow_only({"box", "point", "width", "smallest", "elements_across", "admissibility", "max_levels", "max_knots_per_level"});
  HierarchicalRequest q;
  const int pd = patch.param_dim();
  if (h.has("box") == h.has("point")) h.fail("box", "give either a parameter box or a point with a width");
  if (h.has("box")) {
    const auto rows = h.number_rows("box");
    if (int(rows.size()) != pd) h.fail("box", "needs one [lo, hi] per parametric direction (" + std::to_string(pd) + ")");
    for (int d = 0; d < pd; ++d) {
      const auto& b = rows[std::size_t(d)];
      if (b.size() != 2) h.fail("box", "each entry must be [lo, hi]");
      if (!(b[0] < b[1])) h.fail("box", std::string("zero or negative width along ") + direction_name(d));
      if (b[0] < patch.lower(d) || b[1] > patch.upper(d))
        h.fail("box", std::string("outside the parameter range of ") + direction_name(d));
      q.box.push_back({b[0], b[1]});
    }
    if (h.has("width")) h.fail("width", "only with a point");
  } else {
    q.point = h.numbers("point");
    if (int(q.point.size()) != pd) h.fail("point", "needs " + std::to_string(pd) + " parameters");
    for (int d = 0; d < pd; ++d)
      if (q.point[std::size_t(d)] < patch.lower(d) || q.point[std::size_t(d)] > patch.upper(d))
        h.fail("point", std::string("outside the parameter range of ") + direction_name(d));
    q.width = h.positive("width");
    if (const std::string problem = width_problem(q.width, patch); !problem.empty()) h.fail("width", problem);
  }
  if (h.has("smallest") && h.has("elements_across")) h.fail("smallest", "give smallest or elements_across, not both");
  if (h.holds_string("smallest")) {
    q.smallest = contact_sized(h, "smallest", resolution);
    resolution->hierarchical = true;
  } else if (h.has("smallest")) {
    q.smallest = h.positive("smallest");
  }
  q.elements_across = h.integer_in("elements_across", 1, 1000, 16);
  // [R2]: more levels make every basis evaluation dearer, more knots per level approach
  // global refinement; max_levels counts the coarse level
  const int levels = h.integer_in("max_levels", 2, 5, 5), knots = h.integer_in("max_knots_per_level", 1, 10, 10);
  q.limits = {levels, knots};
  // class m: at most m levels on an element
  q.admissibility = h.integer_in("admissibility", 2, levels, 2);
  return q;
}

RefinementSpec read_refinement(const TomlView& r, const NurbsPatch& patch, std::size_t patch_index, ContactResolutionSpec* resolution) {
  r.allow_only({"degrees", "subdivisions", "graded", "hierarchical"});
  RefinementSpec spec;
  const int pd = patch.param_dim();
  if (r.has("degrees")) {
    spec.degrees = r.integers_in("degrees", 1, kMaxDegree);
    if (int(spec.degrees.size()) != pd) r.fail("degrees", "needs " + std::to_string(pd) + " entries");
    for (int d = 0; d < pd; ++d) {
      if (spec.degrees[std::size_t(d)] < patch.degrees[std::size_t(d)])
        r.fail("degrees", "cannot lower the degree of " + std::string(direction_name(d)) + " below " +
                              std::to_string(patch.degrees[std::size_t(d)]));
    }
  }
  if (r.has("subdivisions")) {
    spec.subdivisions = r.integers_in("subdivisions", 1, 1000);
    if (int(spec.subdivisions.size()) != pd) r.fail("subdivisions", "needs " + std::to_string(pd) + " entries");
  }
  for (const TomlView& g : r.tables("graded")) {
    g.allow_only({"direction", "toward", "smallest", "growth"});
    GradingRequest q;
    q.direction = direction_index(g, "direction", pd);
    q.toward = g.number("toward");
    if (q.toward < patch.lower(q.direction) || q.toward > patch.upper(q.direction))
      g.fail("toward", "outside the parameter range of " + std::string(direction_name(q.direction)));
    if (g.holds_string("smallest")) {
      q.smallest = contact_sized(g, "smallest", resolution);
      resolution->graded.push_back({patch_index, spec.graded.size()});
    } else {
      q.smallest = g.positive("smallest");
    }
    q.growth = g.number("growth", 1.3);
    if (q.growth <= 1.0 || q.growth > 3.0) g.fail("growth", "must lie in (1, 3]");
    spec.graded.push_back(q);
  }
  if (auto h = r.optional_table("hierarchical")) spec.hierarchical = read_hierarchical(*h, patch, resolution);
  return spec;
}

/// A side as the model names it: `side` in a body of one patch, `patch.side` in one of several.
struct SideRef {
  int patch = 0;
  std::string side;      ///< the side's name within its patch
  PatchSide resolved;
};

/// The index of the patch called `name`; refused at `key` if there is none.
int patch_named(const TomlView& t, const std::string& key, const std::string& name, const std::vector<PatchSpec>& patches) {
  const auto it = std::find_if(patches.begin(), patches.end(), [&](const PatchSpec& p) { return p.name == name; });
  if (it == patches.end()) t.fail(key, "no patch named '" + name + "'");
  return int(it - patches.begin());
}

SideRef side_ref(const TomlView& t, const std::string& key, const std::string& text, const std::vector<PatchSpec>& patches) {
  SideRef ref{0, text, {}};
  if (patches.size() > 1) {
    const std::size_t dot = text.find('.');
    if (dot == std::string::npos)
      t.fail(key, "'" + text + "': name the patch too, as patch.side (e.g. " + patches[0].name + ".xi0)");
    ref.patch = patch_named(t, key, text.substr(0, dot), patches);
    ref.side = text.substr(dot + 1);
  }
  const auto side = patches[std::size_t(ref.patch)].patch.side(ref.side);
  if (!side) t.fail(key, "unknown side '" + ref.side + "'" + (patches.size() > 1 ? " of patch '" + patches[std::size_t(ref.patch)].name + "'" : ""));
  ref.resolved = *side;
  return ref;
}

/// The patch a node or stress line lies in: the `patch` key in a body of several patches.
int patch_key(const TomlView& t, const std::vector<PatchSpec>& patches) {
  return patches.size() == 1 ? 0 : patch_named(t, "patch", t.string("patch"), patches);
}

std::vector<FixedComponents> read_boundary(const TomlView& b, const std::vector<PatchSpec>& patches, int dim) {
  b.allow_only({"clamped", "fixed"});
  std::vector<FixedComponents> out;
  if (b.has("clamped"))
    for (const std::string& text : b.strings("clamped")) {
      const SideRef ref = side_ref(b, "clamped", text, patches);
      FixedComponents f{ref.side, {}, ref.patch};
      for (int a = 0; a < dim; ++a) f.components.push_back(a);
      out.push_back(f);
    }
  for (const TomlView& t : b.tables("fixed")) {
    t.allow_only({"side", "components"});
    const SideRef ref = side_ref(t, "side", t.string("side"), patches);
    FixedComponents f{ref.side, {}, ref.patch};
    for (const std::string& c : t.strings("components")) {
      int a = -1;
      for (int k = 0; k < dim; ++k)
        if (c == kComponents[k]) a = k;
      if (a < 0) t.fail("components", "unknown component '" + c + "'");
      f.components.push_back(a);
    }
    out.push_back(f);
  }
  return out;
}

Eigen::VectorXd parameter_point(const TomlView& t, const std::string& key, const NurbsPatch& patch) {
  const std::vector<double> v = t.numbers(key);
  if (int(v.size()) != patch.param_dim()) t.fail(key, "needs " + std::to_string(patch.param_dim()) + " parameters");
  for (int d = 0; d < patch.param_dim(); ++d)
    if (v[std::size_t(d)] < patch.lower(d) || v[std::size_t(d)] > patch.upper(d)) t.fail(key, "outside the patch's parameter range");
  return Eigen::Map<const Eigen::VectorXd>(v.data(), Eigen::Index(v.size()));
}

/// A point given by its patch parameter (`parameter_key`) or physically (`point_key`, in
/// metres), exactly one of the two.
GivenPoint given_point(const TomlView& t, const std::string& parameter_key, const std::string& point_key, const NurbsPatch& patch) {
  if (t.has(parameter_key) == t.has(point_key))
    t.fail(parameter_key, "give exactly one of " + parameter_key + " (patch parameter) and " + point_key + " (m)");
  if (t.has(parameter_key)) return {parameter_point(t, parameter_key, patch), false};
  const std::vector<double> v = t.numbers(point_key);
  if (int(v.size()) != patch.phys_dim()) t.fail(point_key, "needs " + std::to_string(patch.phys_dim()) + " coordinates (m)");
  return {Eigen::Map<const Eigen::VectorXd>(v.data(), Eigen::Index(v.size())), true};
}

std::string short_number(double x) {
  std::ostringstream s;
  s << std::setprecision(3) << x;
  return s.str();
}

/// Refuses a physical point farther from the body than placement_tolerance.
void require_on_body(const TomlView& t, const std::string& key, const NurbsPatch& patch, const BodyPoint& placed,
                     const std::string& which) {
  if (placed.distance <= placement_tolerance(patch)) return;
  t.fail(key, which + " lies " + short_number(placed.distance) + " m outside the body (tolerance " +
                  short_number(placement_tolerance(patch)) + " m)");
}

void read_sid_content(const TomlView& top, ModelSpec& m) {
  const bool several = m.patches.size() > 1;
  std::vector<std::string> surfaces, nodes, lines;
  for (const TomlView& c : top.tables("contact_surface")) {
    c.allow_only({"name", "side", "interval", "points_per_direction"});
    ContactSurfaceSpec s;
    s.name = unique_name(c, surfaces);
    // one side, or several patch sides that continue each other (a surface over several patches)
    const std::vector<std::string> sides = c.holds_string("side") ? std::vector<std::string>{c.string("side")} : c.strings("side");
    if (sides.empty()) c.fail("side", "names no side");
    const SideRef ref = side_ref(c, "side", sides[0], m.patches);
    s.patch = ref.patch;
    s.side = ref.side;
    for (std::size_t k = 1; k < sides.size(); ++k) {
      const SideRef more = side_ref(c, "side", sides[k], m.patches);
      if (more.resolved.direction != ref.resolved.direction || more.resolved.end != ref.resolved.end)
        c.fail("side", "'" + sides[k] + "' is not the same side as '" + sides[0] + "' (a surface over several patches joins like sides)");
      s.continued.push_back({more.patch, more.side});
    }
    if (!s.continued.empty() && c.has("interval")) c.fail("interval", "only on a surface of one patch side");
    const NurbsPatch& patch = m.patches[std::size_t(s.patch)].patch;
    const PatchSide* side = &ref.resolved;
    if (c.has("interval")) {
      const auto rows = c.number_rows("interval");
      if (int(rows.size()) != patch.param_dim() - 1) c.fail("interval", "needs one [lo, hi] per tangential direction");
      int k = 0;
      for (int d = 0; d < patch.param_dim(); ++d) {
        if (d == side->direction) continue;
        const auto& r = rows[std::size_t(k++)];
        if (r.size() != 2 || r[0] >= r[1] || r[0] < patch.lower(d) || r[1] > patch.upper(d))
          c.fail("interval", "each entry must be [lo, hi] with lo < hi inside the parameter range");
        if (r[1] - r[0] < 1e-9 * (patch.upper(d) - patch.lower(d)))
          c.fail("interval", "narrower than 1e-9 of the parameter range: its Gauss points would carry no area");
        s.interval.push_back({r[0], r[1]});
      }
    }
    s.points_per_direction = c.integer_in("points_per_direction", 0, 20, 0);  // 0: p+1
    m.contact_surfaces.push_back(s);
  }
  const std::vector<TomlView> node_tables = top.tables("node");
  if (node_tables.size() > kMaxNodes)
    node_tables[kMaxNodes].fail("name", "more than " + std::to_string(kMaxNodes) + " nodes: each costs two rows per mode in the SID");
  for (const TomlView& t : node_tables) {
    if (several) t.allow_only({"name", "patch", "parameter", "point"});
    else t.allow_only({"name", "parameter", "point"});
    NodeSpec n;
    n.name = unique_name(t, nodes);
    n.patch = patch_key(t, m.patches);
    const NurbsPatch& patch = m.patches[std::size_t(n.patch)].patch;
    n.at = given_point(t, "parameter", "point", patch);
    if (n.at.physical) require_on_body(t, "point", patch, place(patch, n.at), "the point");
    m.nodes.push_back(n);
  }
  long long stress_points = 0;
  for (const TomlView& t : top.tables("stress_line")) {
    if (several) t.allow_only({"name", "patch", "from", "to", "from_point", "to_point", "points"});
    else t.allow_only({"name", "from", "to", "from_point", "to_point", "points"});
    StressLineSpec l;
    l.name = unique_name(t, lines);
    l.patch = patch_key(t, m.patches);
    const NurbsPatch& patch = m.patches[std::size_t(l.patch)].patch;
    l.from = given_point(t, "from", "from_point", patch);
    l.to = given_point(t, "to", "to_point", patch);
    if (l.from.physical != l.to.physical) t.fail(l.from.physical ? "to" : "from", "give both ends as parameters or both in metres");
    const int n = t.integer_in("points", 1, 10000, 10);
    l.points = n;
    stress_points += n;
    if (stress_points > kMaxStressPoints)
      t.fail("points", "the stress lines together have more than " + std::to_string(kMaxStressPoints) + " points");
    if (l.from.physical) {  // the ends first, then the segment between them must lie in the body
      const std::vector<BodyPoint> on_body = line_points(patch, l.from, l.to, l.points);
      require_on_body(t, "from_point", patch, on_body.front(), "the point");
      require_on_body(t, "to_point", patch, on_body.back(), "the point");
      for (int i = 1; i + 1 < l.points; ++i)
        require_on_body(t, "to_point", patch, on_body[std::size_t(i)], "the line's point " + std::to_string(i + 1));
    }
    m.stress_lines.push_back(l);
  }
  if (auto r = top.optional_table("reduction")) {
    r->allow_only({"method", "normal_modes", "interface_surface", "interface_points", "interface_center", "boundary_surface"});
    ReductionSpec& red = m.reduction;
    const std::string method = r->string("method");
    const std::optional<format::ReductionMethod> named = format::reduction_method_named(method);
    if (!named) r->fail("method", "unknown method '" + method + "' (" + format::reduction_method_names() + ")");
    red.method = *named;
    const format::ReductionMethodTraits& kind = format::traits(red.method);
    const int n = r->integer_in("normal_modes", 0, 100000, red.method == format::ReductionMethod::Full ? 0 : 10);
    if (kind.needs_normal_modes && n < 1) r->fail("normal_modes", "must be a positive count");
    if (kind.massless_boundary) {
      red.boundary_surface = r->string("boundary_surface");
      const auto surface = std::find_if(m.contact_surfaces.begin(), m.contact_surfaces.end(),
                                        [&](const ContactSurfaceSpec& s) { return s.name == red.boundary_surface; });
      if (surface == m.contact_surfaces.end()) r->fail("boundary_surface", "no contact_surface named '" + red.boundary_surface + "'");
      if (!surface->continued.empty()) r->fail("boundary_surface", "must lie on one patch side (a surface over several is not supported)");
    } else if (r->has("boundary_surface")) {
      r->fail("boundary_surface", "only used by the massless-boundary methods (" +
                                      format::reduction_method_names([](const auto& t) { return t.massless_boundary; }) + ")");
    }
    red.normal_modes = n;
    if (kind.interface_nodes) {
      red.interface_surface = r->string("interface_surface");
      if (std::find(surfaces.begin(), surfaces.end(), red.interface_surface) == surfaces.end())
        r->fail("interface_surface", "no contact_surface named '" + red.interface_surface + "'");
      // bounded by the model size here, by the interface side's nodes once they are known
      red.interface_points = r->integer_in("interface_points", 1, int(kMaxControlPoints));
      // inside the parameter range of the interface surface's side
      const auto surface = std::find_if(m.contact_surfaces.begin(), m.contact_surfaces.end(),
                                        [&](const ContactSurfaceSpec& s) { return s.name == red.interface_surface; });
      if (!surface->continued.empty()) r->fail("interface_surface", "must lie on one patch side (its interface_center is a parameter there)");
      const NurbsPatch& patch = m.patches[std::size_t(surface->patch)].patch;
      const std::vector<double> c = r->numbers("interface_center");
      if (int(c.size()) != patch.param_dim() - 1) r->fail("interface_center", "needs one parameter per tangential direction");
      const int fixed = patch.side(surface->side)->direction;
      for (int d = 0, k = 0; d < patch.param_dim(); ++d) {
        if (d == fixed) continue;
        const double x = c[std::size_t(k++)];
        if (!(x >= patch.lower(d) && x <= patch.upper(d)))
          r->fail("interface_center", "parameter " + std::to_string(x) + " lies outside the side's range [" +
                                          std::to_string(patch.lower(d)) + ", " + std::to_string(patch.upper(d)) + "]");
      }
      red.interface_center = Eigen::Map<const Eigen::VectorXd>(c.data(), Eigen::Index(c.size()));
    } else {
      for (const char* key : {"interface_surface", "interface_points", "interface_center"})
        if (r->has(key)) r->fail(key, "only used by method = " + format::reduction_method_names([](const auto& t) { return t.interface_nodes; }, "\""));
    }
  }
  read_visual(top, m);
  read_damping(top, m);
}

}  // namespace

format::Material read_material(const TomlView& mat) {
  mat.allow_only({"youngs_modulus", "poisson_ratio", "density"});
  format::Material m;
  m.youngs_modulus = mat.positive("youngs_modulus");
  m.poisson_ratio = mat.number("poisson_ratio");
  if (m.poisson_ratio <= -1 || m.poisson_ratio >= 0.5)
    mat.fail("poisson_ratio", "must lie in (-1, 0.5), is " + std::to_string(m.poisson_ratio));
  m.density = mat.positive("density");
  return m;
}

std::string unique_name(const TomlView& t, std::vector<std::string>& seen) {
  const std::string name = t.name("name");
  if (std::find(seen.begin(), seen.end(), name) != seen.end()) t.fail("name", "duplicate name '" + name + "'");
  seen.push_back(name);
  return name;
}

void read_quadrature(const TomlView& top, ModelSpec& m) {
  if (auto q = top.optional_table("quadrature")) {
    q->allow_only({"extra_points"});
    m.extra_quadrature_points = q->integer_in("extra_points", 0, 10, 0);
  }
}

void read_visual(const TomlView& top, ModelSpec& m) {
  if (auto v = top.optional_table("visual")) {
    v->allow_only({"subdivisions", "stress"});
    VisualSpec& visual = m.visual.emplace();
    visual.subdivisions = v->integer_in("subdivisions", 1, 8, visual.subdivisions);  // cells per element and direction
    visual.stress = v->boolean("stress", visual.stress);
  }
}

void read_damping(const TomlView& top, ModelSpec& m) {
  if (auto d = top.optional_table("damping")) {
    d->allow_only({"kappa", "f1", "f2"});
    m.damping.kappa = d->number("kappa", m.damping.kappa);
    // a damping ratio: above 1 every mode is overdamped, and 1e300 overflowed De in the SID
    if (!(m.damping.kappa >= 0 && m.damping.kappa <= 1)) d->fail("kappa", "is a damping ratio: must lie in [0, 1]");
    if (d->has("f1") != d->has("f2")) d->fail(d->has("f1") ? "f2" : "f1", "give both f1 and f2, or neither");
    if (d->has("f1")) {
      m.damping.f1_hz = d->positive("f1");
      m.damping.f2_hz = d->positive("f2");
      if (m.damping.f2_hz <= m.damping.f1_hz) d->fail("f2", "must exceed f1");
    }
  }
}

ModelSpec read_model_file(const std::string& path) {
  const toml::table root = common::parse_toml_file(path);
  const TomlView top(root, path);
  top.allow_only({"body", "material", "geometry", "patch", "contact_resolution", "refinement", "boundary", "quadrature",
                  "reduction", "damping", "contact_surface", "node", "stress_line", "visual", "mesh"});
  ModelSpec m;
  m.file = path;

  const TomlView body = top.table("body");
  body.allow_only({"name", "analysis", "thickness"});
  m.body_name = body.name("name");
  const std::string analysis = body.string("analysis");
  const auto type = format::analysis_type_from_string(analysis);
  if (!type) body.fail("analysis", "unknown analysis '" + analysis + "' (plane_strain, plane_stress, axisymmetric, solid)");
  m.analysis = *type;
  const bool planar = m.analysis == format::AnalysisType::PlaneStrain || m.analysis == format::AnalysisType::PlaneStress;
  if (body.has("thickness") && !planar) body.fail("thickness", "only planar bodies have a thickness");
  m.thickness = body.positive("thickness", 1.0);

  // [material] is the body's, or the default of patches without their own
  const std::optional<format::Material> body_material =
      top.has("material") ? std::optional<format::Material>(read_material(top.table("material"))) : std::nullopt;
  if (top.has("mesh")) {  // an isoparametric body meshed by gmsh: model/mesh_model.cpp
    if (!body_material) top.table("material");
    read_mesh_model(top, m, *body_material);
    return m;
  }
  const std::vector<TomlView> patch_tables = top.tables("patch");
  if (patch_tables.empty()) {
    if (!body_material) top.table("material");  // the one-line "missing" message
    PatchSpec& p = m.patches.emplace_back();
    p.material = *body_material;
    p.patch = read_geometry(top.table("geometry"), m.analysis);
    check_mapping(p.patch, path, "geometry");
  } else {
    if (top.has("geometry")) top.table("geometry").fail("primitive", "give [geometry] for a body of one patch or [[patch]] tables, not both");
    if (top.has("refinement")) top.table("refinement").fail("degrees", "a body of several patches refines each in its [patch.refinement]");
    if (patch_tables.size() > kMaxPatches) patch_tables[kMaxPatches].fail("name", "more than " + std::to_string(kMaxPatches) + " patches");
    for (const TomlView& t : patch_tables) {
      t.allow_only({"name", "material", "geometry", "refinement"});
      PatchSpec& p = m.patches.emplace_back();
      p.name = t.string("name");
      if (p.name.empty() || p.name.find_first_of("./") != std::string::npos) t.fail("name", "must be a non-empty name without '.' or '/'");
      for (std::size_t k = 0; k + 1 < m.patches.size(); ++k)
        if (m.patches[k].name == p.name) t.fail("name", "duplicate patch name '" + p.name + "'");
      if (t.has("material")) {
        p.material = read_material(t.table("material"));
      } else if (body_material) {
        p.material = *body_material;
      } else {
        t.fail("material", "patch '" + p.name + "' has no material (give [patch.material] or a body [material])");
      }
      p.patch = read_geometry(t.table("geometry"), m.analysis);
      check_mapping(p.patch, path, t.field("geometry"));
    }
  }
  if (auto c = top.optional_table("contact_resolution")) {
    c->allow_only({"contact_radius", "elements_per_radius"});
    ContactResolutionSpec& resolution = m.contact_resolution.emplace();
    resolution.contact_radius = c->positive("contact_radius");
    resolution.elements_per_radius = c->positive("elements_per_radius", resolution.elements_per_radius);
    if (resolution.elements_per_radius < 1 || resolution.elements_per_radius > 100)
      c->fail("elements_per_radius", "must lie in 1..100");
  }
  ContactResolutionSpec* resolution = m.contact_resolution ? &*m.contact_resolution : nullptr;
  if (patch_tables.empty()) {
    if (auto r = top.optional_table("refinement")) m.patches[0].refinement = read_refinement(*r, m.patches[0].patch, 0, resolution);
  } else {
    for (std::size_t k = 0; k < patch_tables.size(); ++k)
      if (auto r = patch_tables[k].optional_table("refinement")) {
        m.patches[k].refinement = read_refinement(*r, m.patches[k].patch, k, resolution);
        if (m.patches[k].refinement.hierarchical &&
            std::any_of(m.patches.begin(), m.patches.begin() + std::ptrdiff_t(k), [](const PatchSpec& p) { return p.refinement.hierarchical.has_value(); }))
          r->table("hierarchical").fail("box", "only one patch of a body may be refined hierarchically");
      }
  }
  if (m.contact_resolution && m.contact_resolution->graded.empty() && !m.contact_resolution->hierarchical)
    top.table("contact_resolution").fail("contact_radius", "no refinement uses it (give a refinement smallest = \"contact\")");
  if (auto b = top.optional_table("boundary")) m.fixed = read_boundary(*b, m.patches, format::spatial_dim(m.analysis));
  read_quadrature(top, m);
  read_sid_content(top, m);
  return m;
}

const format::Material& fastest_material(const ModelSpec& spec) {
  auto speed = [](const PatchSpec& p) { return p.material.youngs_modulus / p.material.density; };
  return std::max_element(spec.patches.begin(), spec.patches.end(),
                          [&](const PatchSpec& a, const PatchSpec& b) { return speed(a) < speed(b); })->material;
}

void set_contact_radius(ModelSpec& model, double radius, const std::string& source) {
  if (!model.contact_resolution)
    throw format::InputError(model.file, source, "the model sizes no elements from a contact radius (it has no [contact_resolution])");
  if (!(radius > 0) || !std::isfinite(radius)) throw format::InputError(model.file, source, "must be a positive length in metres");
  ContactResolutionSpec& resolution = *model.contact_resolution;
  resolution.contact_radius = radius;
  for (const auto& [patch, k] : resolution.graded) model.patches[patch].refinement.graded[k].smallest = resolution.element_size();
  for (PatchSpec& p : model.patches)
    if (resolution.hierarchical && p.refinement.hierarchical) p.refinement.hierarchical->smallest = resolution.element_size();
}

void set_refinement_point(ModelSpec& model, const std::string& surface, const std::vector<double>& at, double width,
                          const std::string& source) {
  const auto s = std::find_if(model.contact_surfaces.begin(), model.contact_surfaces.end(),
                              [&](const ContactSurfaceSpec& c) { return c.name == surface; });
  if (s == model.contact_surfaces.end()) throw format::InputError(model.file, source, "no contact_surface named '" + surface + "'");
  if (!s->continued.empty())
    throw format::InputError(model.file, source, "contact surface '" + surface + "' spans several patches; a refinement point lies on one");
  PatchSpec& patch = model.patches[std::size_t(s->patch)];
  if (!patch.refinement.hierarchical)
    throw format::InputError(model.file, source,
                             "the patch of contact surface '" + surface + "' has no [refinement.hierarchical] to place");
  if (!(width > 0) || !std::isfinite(width)) throw format::InputError(model.file, source, "the width must be a positive length in metres");
  const NurbsPatch& geometry = patch.patch;
  if (const std::string problem = width_problem(width, geometry); !problem.empty()) throw format::InputError(model.file, source, problem);
  const PatchSide side = *geometry.side(s->side);  // the model reader resolved it
  if (int(at.size()) != geometry.param_dim() - 1)
    throw format::InputError(model.file, source,
                             "needs " + std::to_string(geometry.param_dim() - 1) + " tangential parameter(s) of surface '" + surface + "'");
  std::vector<double> point;
  for (int d = 0, t = 0; d < geometry.param_dim(); ++d) {
    if (d == side.direction) {
      point.push_back(side.end == 0 ? geometry.lower(d) : geometry.upper(d));
      continue;
    }
    const double u = at[std::size_t(t++)];
    if (!(u >= geometry.lower(d) && u <= geometry.upper(d)))
      throw format::InputError(model.file, source, std::string("outside the parameter range of ") + direction_name(d));
    point.push_back(u);
  }
  HierarchicalRequest& request = *patch.refinement.hierarchical;
  request.box.clear();
  request.point = point;
  request.width = width;
  // a Craig-Bampton interface goes where the contact is (on another surface it would stiffen
  // nothing), and spans the refined region: a fixed number of nodes shrinks with the elements
  // and would leave part of the contact on fixed-interface modes
  if (!model.reduction.interface_surface.empty()) {
    model.reduction.interface_surface = surface;
    model.reduction.interface_center = Eigen::Map<const Eigen::VectorXd>(at.data(), Eigen::Index(at.size()));
    model.reduction.interface_radius = width / 2;
  }
}

}  // namespace isosid::prep

// isosid-prep's reports; see prep_report.hpp.
#include "pipeline/prep_report.hpp"

#include "isosid/common/number_text.hpp"
#include "model/placement.hpp"

#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

namespace isosid::prep {
namespace {
using common::list_text;
using common::number_text;
using common::number_text;

std::vector<double> as_vector(const Eigen::VectorXd& v) { return {v.data(), v.data() + v.size()}; }

nlohmann::json timings_json(const StageTimings& timings) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [stage, seconds] : timings) j[stage] = seconds;
  return j;
}

/// Size, mass and THB levels: the keys and text both reports start with.
nlohmann::json body_json(const BodyModel& body, double mass, std::string& levels_text) {
  nlohmann::json j;
  j["body"] = body.spec.body_name;
  j["analysis"] = format::to_string(body.spec.analysis);
  j["degrees"] = body.space.degrees;
  j["elements"] = body.space.elements.size();
  j["control_points"] = body.space.n_functions();
  j["nodes"] = body.dofs.node_count();
  j["dofs"] = body.dofs.free_count();
  j["mass_kg"] = mass;
  if (const auto& m = body.spec.mesh) {  // a meshed body: gmsh's elements, not patches to list
    j["mesh"] = {{"generator", "gmsh"}, {"primitive", m->primitive}, {"element_size_m", m->element_size},
                 {"contact_element_size_m", m->contact_element_size}, {"growth", m->growth}, {"elements", body.space.elements.size()}};
    levels_text += "  gmsh mesh of " + m->primitive + ": " + std::to_string(body.space.elements.size()) +
                   " quadratic quadrilaterals, " + number_text(m->contact_element_size) + " m at the contact point to " +
                   number_text(m->element_size) + " m\n";
  } else if (body.spec.patches.size() > 1) {  // the patches, their materials and where they meet
    for (std::size_t k = 0; k < body.spec.patches.size(); ++k) {
      const PatchSpec& p = body.spec.patches[k];
      j["patches"].push_back({{"name", p.name}, {"youngs_modulus_pa", p.material.youngs_modulus},
                              {"poisson_ratio", p.material.poisson_ratio}, {"density_kg_m3", p.material.density}});
      levels_text += "  patch " + p.name + ": E " + number_text(p.material.youngs_modulus) + " Pa, nu " +
                     number_text(p.material.poisson_ratio) + ", rho " + number_text(p.material.density) + " kg/m^3\n";
    }
    for (const PatchInterface& i : body.interfaces) {
      const std::string a = body.spec.patches[std::size_t(i.a)].name + "." + side_name(i.side_a),
                        b = body.spec.patches[std::size_t(i.b)].name + "." + side_name(i.side_b);
      j["interfaces"].push_back({a, b});
      levels_text += "  interface " + a + " = " + b + "\n";
    }
  }
  if (!body.hierarchy) return j;
  const Hierarchy& h = *body.hierarchy;
  j["levels"] = nlohmann::json::array();
  for (int l = 0; l < h.mesh.levels(); ++l) {
    const auto level = std::size_t(l);
    const ParameterBox& d = h.mesh.domains[level];
    nlohmann::json box = nlohmann::json::array();
    for (std::size_t k = 0; k < d.lo.size(); ++k) box.push_back({d.lo[k], d.hi[k]});
    j["levels"].push_back({{"level", l}, {"functions", h.functions_per_level[level]}, {"elements", h.elements_per_level[level]},
                           {"split", h.mesh.factors[level]}, {"domain", box}});
    levels_text += "  level " + std::to_string(l) + ": " + std::to_string(h.elements_per_level[level]) + " elements, " +
                   std::to_string(h.functions_per_level[level]) + " functions, split";
    for (int f : h.mesh.factors[level]) levels_text += " " + std::to_string(f);
    levels_text += ", domain";
    for (std::size_t k = 0; k < d.lo.size(); ++k) levels_text += " [" + number_text(d.lo[k]) + ", " + number_text(d.hi[k]) + "]";
    levels_text += "\n";
  }
  return j;
}

/// Where each node and stress line lies, by parameter and in metres, and which of the two
/// the model file gave.
nlohmann::json placement_json(const ModelSpec& spec, std::string& text) {
  auto located = [](const BodyPoint& p) { return nlohmann::json{{"parameter", as_vector(p.parameter)}, {"point_m", as_vector(p.x)}}; };
  auto described = [](const BodyPoint& p) { return "parameter " + list_text(p.parameter) + " = " + list_text(p.x) + " m"; };
  auto given = [](const GivenPoint& g) { return std::string(g.physical ? "point" : "parameter"); };
  nlohmann::json j = {{"nodes", nlohmann::json::array()}, {"stress_lines", nlohmann::json::array()}};
  for (const NodeSpec& n : spec.nodes) {
    const BodyPoint p = place(spec.patches[std::size_t(n.patch)].patch, n.at);
    nlohmann::json node = located(p);
    node["name"] = n.name;
    node["given"] = given(n.at);
    j["nodes"].push_back(node);
    text += "  node " + n.name + " at " + described(p) + " (given by " + given(n.at) + ")\n";
  }
  for (const StressLineSpec& l : spec.stress_lines) {
    const std::vector<BodyPoint> points = line_points(spec.patches[std::size_t(l.patch)].patch, l.from, l.to, l.points);
    j["stress_lines"].push_back({{"name", l.name}, {"given", given(l.from)}, {"points", l.points},
                                 {"from", located(points.front())}, {"to", located(points.back())}});
    text += "  stress line " + l.name + ", " + std::to_string(l.points) + " points from " + described(points.front()) + " to " +
            described(points.back()) + " (given by " + given(l.from) + "s)\n";
  }
  return j;
}

}  // namespace

namespace {

nlohmann::json modal_report(const ModalAnalysis& analysis, std::string& levels_text) {
  nlohmann::json j = body_json(analysis.body, analysis.mass, levels_text);
  j["rigid_body_modes"] = analysis.modes.rigid_body_modes;
  j["frequencies_hz"] = as_vector(analysis.modes.frequencies_hz());
  j["timings_s"] = timings_json(analysis.timings);
  return j;
}

nlohmann::json sid_report(const PreparedBody& prepared, const std::string& output, std::string& levels_text, std::string& placement_text) {
  const format::Sid& sid = prepared.sid;
  nlohmann::json j = body_json(prepared.body, prepared.scalar_mass.sum(), levels_text);
  j["nq"] = sid.nq();
  j["n_low"] = sid.refmod.n_low;
  j["n_high"] = sid.refmod.n_high();
  j["reduction"] = format::name(prepared.basis.method);
  j["removed_rigid_directions"] = prepared.basis.removed_rigid;
  j["frequencies_hz"] = as_vector(sid.refmod.frequencies_hz);
  j["contact_points"] = nlohmann::json::object();
  for (const auto& c : sid.contact_surfaces) j["contact_points"][c.name] = c.points();
  j["placement"] = placement_json(prepared.body.spec, placement_text);
  j["output"] = output;
  j["timings_s"] = timings_json(prepared.timings);
  return j;
}

}  // namespace

nlohmann::json modal_report(const ModalAnalysis& analysis) {
  std::string levels_text;
  return modal_report(analysis, levels_text);
}

nlohmann::json sid_report(const PreparedBody& prepared, const std::string& output) {
  std::string levels_text, placement_text;
  return sid_report(prepared, output, levels_text, placement_text);
}

void print_modal_report(const ModalAnalysis& analysis, bool as_json) {
  const BodyModel& body = analysis.body;
  std::string levels_text;
  const nlohmann::json j = modal_report(analysis, levels_text);
  if (as_json) {
    std::cout << j.dump(2) << "\n";
    return;
  }
  const Eigen::VectorXd f = analysis.modes.frequencies_hz();
  std::printf("%s (%s): %zu elements, degrees", body.spec.body_name.c_str(), format::to_string(body.spec.analysis).c_str(),
              body.space.elements.size());
  for (int p : body.space.degrees) std::printf(" %d", p);
  std::printf(", %d free DOFs, mass %.6g kg\n%s", body.dofs.free_count(), analysis.mass, levels_text.c_str());
  std::printf("%d rigid-body modes; frequencies [Hz]:", analysis.modes.rigid_body_modes);
  for (Eigen::Index i = 0; i < f.size(); ++i) std::printf("%s%.6g", i % 6 ? "  " : "\n  ", f(i));
  std::printf("\n");
}

void print_sid_report(const PreparedBody& prepared, const std::string& output, bool as_json) {
  const BodyModel& body = prepared.body;
  const format::Sid& sid = prepared.sid;
  std::string levels_text, placement_text;
  const nlohmann::json j = sid_report(prepared, output, levels_text, placement_text);
  if (as_json) {
    std::cout << j.dump(2) << "\n";
    return;
  }
  std::printf("%s: %s reduction, nq = %lld (%d low + %d high), %d free DOFs -> %s\n", body.spec.body_name.c_str(),
              format::name(prepared.basis.method).c_str(), static_cast<long long>(sid.nq()), sid.refmod.n_low, sid.refmod.n_high(),
              body.dofs.free_count(), output.c_str());
  std::printf("%s%s", levels_text.c_str(), placement_text.c_str());
}

}  // namespace isosid::prep

// isosid-info: what a SID file holds (body, invariants, modes, contact data, provenance),
// or with --layout the SID layout table that format/README.md shows.
#include "isosid/common/cli_parse.hpp"
#include "isosid/common/number_text.hpp"
#include "isosid/format/rigid_invariants.hpp"
#include "isosid/format/sid_io.hpp"
#include "isosid/format/sid_layout.hpp"
#include "isosid/format/visual_grid.hpp"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

namespace {
using namespace isosid::format;
using isosid::common::list_text;
using isosid::common::number_text;
using nlohmann::json;

json matrix_json(const Eigen::MatrixXd& m) {
  json rows = json::array();
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    json row = json::array();
    for (Eigen::Index j = 0; j < m.cols(); ++j) row.push_back(m(i, j));
    rows.push_back(row);
  }
  return rows;
}

json vector_json(const Eigen::VectorXd& v) { return std::vector<double>(v.data(), v.data() + v.size()); }

json describe(const Sid& sid) {
  const RigidInvariants inv = rigid_invariants(sid);
  json j;
  j["body"] = sid.body_name;
  j["analysis_type"] = to_string(sid.analysis);
  j["material"] = {{"youngs_modulus_pa", sid.material.youngs_modulus},
                   {"poisson_ratio", sid.material.poisson_ratio},
                   {"density_kg_m3", sid.material.density}};
  if (sid.dim() == 2 && sid.analysis != AnalysisType::Axisymmetric) j["thickness_m"] = sid.thickness;
  j["mass"] = inv.mass;
  j["center_of_mass"] = vector_json(inv.center_of_mass);
  j["inertia"] = matrix_json(inv.inertia_origin);
  j["inertia_at_center_of_mass"] = matrix_json(inv.inertia_center);
  j["nq"] = sid.nq();
  j["n_low"] = sid.refmod.n_low;
  j["n_high"] = sid.refmod.n_high();
  j["reduction_method"] = sid.refmod.reduction_method;
  j["interface"] = sid.refmod.interface_description;
  j["frequencies_hz"] = vector_json(sid.refmod.frequencies_hz);
  if (sid.refmod.section_translation.size()) {
    j["long_axis"] = vector_json(sid.refmod.long_axis);
    j["section_translation"] = matrix_json(sid.refmod.section_translation);
  }
  j["damping"] = {{"kappa", sid.damping.kappa}, {"f1_hz", sid.damping.f1_hz}, {"f2_hz", sid.damping.f2_hz},
                  {"alpha1", sid.damping.alpha1}, {"alpha2", sid.damping.alpha2}};
  j["nodes"] = json::array();
  for (const Node& n : sid.nodes) j["nodes"].push_back({{"name", n.name}, {"position", vector_json(n.origin.M0.col(0))}});
  j["contact_surfaces"] = json::array();
  for (const ContactSurface& c : sid.contact_surfaces)  // points_in_interface: Craig-Bampton SIDs only (else null)
    j["contact_surfaces"].push_back({{"name", c.name}, {"patch", c.patch}, {"side", c.side}, {"points", c.points()},
                                     {"master_patch", c.master_patch}, {"area_m2", c.weight.sum()},
                                     {"points_in_interface", c.in_interface.size() > 0 ? json(c.in_interface.sum()) : json(nullptr)}});
  j["patches"] = json::array();
  for (const PatchInfo& p : sid.patches)
    j["patches"].push_back({{"name", p.name}, {"youngs_modulus_pa", p.material.youngs_modulus},
                            {"poisson_ratio", p.material.poisson_ratio}, {"density_kg_m3", p.material.density},
                            {"interfaces", p.interfaces}});
  j["master_patches"] = json::array();
  for (const MasterPatch& m : sid.master_patches)
    j["master_patches"].push_back({{"name", m.name}, {"degrees", m.degrees}, {"control_points", m.weights.size()}});
  j["stress_recovery"] = json::array();
  for (const StressRecovery& s : sid.stress_recovery)
    j["stress_recovery"].push_back({{"name", s.name}, {"patch", s.patch}, {"points", s.position.rows()}, {"components", s.components}});
  if (const auto& d = sid.discretization)
    j["mesh"] = json{{"elements_per_level", std::vector<int>(d->elements_per_level.begin(), d->elements_per_level.end())},
                     {"functions_per_level", std::vector<int>(d->functions_per_level.begin(), d->functions_per_level.end())},
                     {"free_dofs", d->free_dofs},
                     {"contact_radius_m", d->contact_radius > 0 ? json(d->contact_radius) : json(nullptr)}};
  j["transfer"] = sid.transfer ? json{{"coarse_nq", sid.transfer->coarse_to_fine.cols()},
                                      {"coarse_model_sha256", sid.transfer->coarse_model_sha256}}
                               : json(nullptr);
  j["visual"] = sid.visual ? json{{"points", sid.visual->points()}, {"cells", sid.visual->cell_count()},
                                  {"corners_per_cell", sid.visual->corners_per_cell},
                                  {"stress_components", sid.visual->stress_components}}
                           : json(nullptr);
  json timings = json::object();
  for (const auto& [name, s] : sid.provenance.timings_s) timings[name] = s;
  j["provenance"] = {{"model_file", sid.provenance.model_file}, {"model_sha256", sid.provenance.model_sha256},
                     {"program_version", sid.provenance.program_version},
                     {"created_utc", sid.provenance.created_utc}, {"command_line", sid.provenance.command_line},
                     {"timings_s", timings}};
  return j;
}

std::string vec3(const Eigen::VectorXd& v) { return list_text(v, "(", ")"); }

void print_text(const Sid& sid, std::ostream& out) {
  const RigidInvariants inv = rigid_invariants(sid);
  out << "body          " << sid.body_name << " (" << to_string(sid.analysis) << ")\n"
      << "material      E = " << number_text(sid.material.youngs_modulus) << " Pa, nu = " << number_text(sid.material.poisson_ratio)
      << ", rho = " << number_text(sid.material.density) << " kg/m^3\n"
      << "mass          " << number_text(inv.mass) << " kg\n"
      << "centre of mass " << vec3(inv.center_of_mass) << " m\n"
      << "inertia (about the centre of mass) [kg m^2]\n";
  for (int i = 0; i < 3; ++i) out << "              " << vec3(inv.inertia_center.row(i).transpose()) << "\n";
  out << "nq            " << sid.nq() << " (" << sid.refmod.n_low << " low + " << sid.refmod.n_high() << " high), "
      << sid.refmod.reduction_method;
  if (!sid.refmod.interface_description.empty()) out << ", interface: " << sid.refmod.interface_description;
  out << "\nfrequencies   [Hz]";
  for (Eigen::Index i = 0; i < sid.nq(); ++i) out << (i % 6 == 0 ? "\n              " : "  ") << number_text(sid.refmod.frequencies_hz(i));
  if (sid.refmod.section_translation.size()) {
    // modes whose cross-sections translate along an axis with most of their kinetic energy:
    // bending across the long axis, axial along it
    out << "\nsection motion long axis " << vec3(sid.refmod.long_axis) << "; coordinates whose sections translate with at least half their kinetic energy:";
    for (int a = 0; a < 3; ++a) {
      out << "\n              along " << "xyz"[a] << ":";
      for (Eigen::Index k = 0; k < sid.nq(); ++k)
        if (sid.refmod.section_translation(k, a) >= 0.5) out << " " << k;
    }
  }
  out << "\ndamping       kappa = " << number_text(sid.damping.kappa) << ", band " << number_text(sid.damping.f1_hz) << "-"
      << number_text(sid.damping.f2_hz) << " Hz: alpha1 = " << number_text(sid.damping.alpha1) << " 1/s, alpha2 = "
      << number_text(sid.damping.alpha2) << " s\n";
  for (const Node& n : sid.nodes) out << "node          " << n.name << " at " << vec3(n.origin.M0.col(0)) << " m\n";
  for (const PatchInfo& p : sid.patches) {
    out << "patch         " << p.name << ": E " << number_text(p.material.youngs_modulus) << " Pa, nu "
        << number_text(p.material.poisson_ratio) << ", rho " << number_text(p.material.density) << " kg/m^3";
    for (const std::string& i : p.interfaces) out << "; " << i.substr(0, i.find(' ')) << " meets " << i.substr(i.find(' ') + 1);
    out << "\n";
  }
  for (const ContactSurface& c : sid.contact_surfaces)
    out << "contact       " << c.name << ": " << c.points() << " Gauss points on side '" << c.side << "'"
        << (c.patch.empty() ? "" : c.patch.find(' ') == std::string::npos ? " of patch " + c.patch : " of patches " + c.patch) << ", area "
        << number_text(c.weight.sum()) << " m^2, master patch '" << c.master_patch << "'"
        << (c.in_interface.size() > 0 ? ", " + std::to_string(c.in_interface.sum()) + " points within the interface" : std::string()) << "\n";
  for (const MasterPatch& m : sid.master_patches) {
    out << "master patch  " << m.name << ": degrees";
    for (int d : m.degrees) out << " " << d;
    out << ", " << m.weights.size() << " control points\n";
  }
  for (const StressRecovery& s : sid.stress_recovery)
    out << "stress        " << s.name << ": " << s.position.rows() << " points, " << s.components.size() << " components\n";
  if (sid.transfer)
    out << "transfer      from a coarse model with nq = " << sid.transfer->coarse_to_fine.cols() << "\n";
  if (const auto& d = sid.discretization) {
    out << "mesh          " << d->elements_per_level.sum() << " elements, " << d->functions_per_level.sum() << " functions, "
        << d->free_dofs << " free DOFs";
    if (d->contact_radius > 0) out << ", contact elements sized for a contact radius of " << d->contact_radius << " m";
    if (d->elements_per_level.size() > 1)
      for (Eigen::Index l = 0; l < d->elements_per_level.size(); ++l)
        out << "\n  level " << l << "     " << d->elements_per_level(l) << " elements, " << d->functions_per_level(l) << " functions";
    out << "\n";
  }
  if (const auto& v = sid.visual)
    out << "visual        " << v->points() << " points, " << v->cell_count() << (v->corners_per_cell == 8 ? " hexahedra" : " quadrilaterals")
        << (v->stress_components.empty() ? ", no stress rows" : ", stress rows") << "\n";
  out << "provenance    " << sid.provenance.model_file << " (sha256 " << sid.provenance.model_sha256.substr(0, 12)
      << "...), isosid " << sid.provenance.program_version << ", " << sid.provenance.created_utc << "\n";
  for (const auto& [name, s] : sid.provenance.timings_s) out << "  time        " << name << ": " << number_text(s) << " s\n";
}

}  // namespace

int main(int argc, char** argv) {
  return isosid::common::run_guarded("isosid-info", [&] {
    CLI::App app{"Shows what a SID file holds: body, mass, centre of mass, inertia, modes, contact data.", "isosid-info"};
    std::string file;
    std::string paraview_dir;
    bool as_json = false, print_layout = false;
    auto* what = app.add_option_group("what", "a SID file, or --layout");
    what->add_option("file", file, "SID file (.sid.h5)");
    what->add_flag("--layout", print_layout, "print the SID file layout as a markdown table (as in format/README.md)");
    what->require_option(1);
    app.add_flag("--json", as_json, "print JSON instead of text");
    app.add_option("--paraview", paraview_dir,
                   "also write the mode shapes on the SID's viewing mesh to DIR/<body>_modes.vtu (needs [visual] in the model)");
    if (auto status = isosid::common::parse_command_line(app, argc, argv)) return *status;
    if (print_layout) {
      std::cout << layout::markdown_table();
      return 0;
    }
    const Sid sid = read_sid(file);
    if (!paraview_dir.empty()) {
      if (!sid.visual) throw InputError(file, "/visual", "the SID has no viewing mesh: add [visual] to its model file and rebuild it");
      if (!std::filesystem::is_directory(paraview_dir)) throw InputError(paraview_dir, "--paraview", "not a folder");
      const std::string path = (std::filesystem::path(paraview_dir) / (vtk::file_safe(sid.body_name) + "_modes.vtu")).string();
      vtk::write_vtu(path, mode_shape_grid(sid));
      std::cerr << "isosid-info: mode shapes of " << sid.nq() << " coordinates -> " << path << "\n";
    }
    if (as_json)
      std::cout << describe(sid).dump(2) << "\n";
    else
      print_text(sid, std::cout);
    return 0;
  });
}

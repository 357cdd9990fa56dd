// Writes a SID to HDF5 through an atomic temporary file; paths and units from the layout table.
#include "isosid/format/hdf5_file.hpp"
#include "isosid/format/sid_layout.hpp"
#include "isosid/format/atomic_output.hpp"
#include "isosid/format/sid_io.hpp"
#include "isosid/format/sid_validate.hpp"

namespace isosid::format {
namespace {

using namespace layout;

// Each item's path and units come from the layout table; `name` fills a list member's "<name>".
void put_group(h5::Writer& w, const Item& item, std::string_view name = {}) { w.group(item.at(name)); }
void put(h5::Writer& w, const Item& item, double value) { w.scalar(item.at(), value, item.units_text()); }
void put(h5::Writer& w, const Item& item, std::string_view name, double value) { w.scalar(item.at(name), value, item.units_text()); }
void put_integer(h5::Writer& w, const Item& item, long long value) { w.integer(item.at(), value); }
void put(h5::Writer& w, const Item& item, const std::string& value) { w.string(item.at(), value); }
void put(h5::Writer& w, const Item& item, std::string_view name, const std::vector<std::string>& value) {
  w.strings(item.at(name), value);
}
void put(h5::Writer& w, const Item& item, std::string_view name, const Eigen::MatrixXd& value) {
  w.matrix(item.at(name), value, item.units_text());
}
void put(h5::Writer& w, const Item& item, std::string_view name, const Eigen::VectorXd& value) {
  w.vector(item.at(name), value, item.units_text());
}
void put(h5::Writer& w, const Item& item, std::string_view name, const Eigen::VectorXi& value) {
  w.integers(item.at(name), value);
}
void put_attribute(h5::Writer& w, const Item& item, std::string_view name, const std::string& value) {
  w.attribute(item.at(name), std::string(item.attribute), value);
}

void put_taylor(h5::Writer& w, const Item& item, std::string_view name, const Taylor& t) {
  const std::string path = item.at(name);
  w.group(path);
  w.attribute(path, "order", double(t.order()));
  w.attribute(path, "units", item.units_text());
  w.matrix(path + "/M0", t.M0, item.units_text());
  if (t.order() == 1) w.tensor(path + "/M1", t.M1, item.units_text());
}

void write_body(h5::Writer& w, const Sid& sid) {
  put_group(w, body::group);
  put(w, body::name, sid.body_name);
  put(w, body::analysis_type, to_string(sid.analysis));
  put(w, body::youngs_modulus, sid.material.youngs_modulus);
  put(w, body::poisson_ratio, sid.material.poisson_ratio);
  put(w, body::density, sid.material.density);
  put(w, body::thickness, sid.thickness);
}

void write_refmod(h5::Writer& w, const Sid& sid) {
  const RefMod& r = sid.refmod;
  put_group(w, refmod::group);
  put_attribute(w, refmod::q_units, {}, "sqrt(kg)*m for mass-normalized modes ([q])");
  put(w, refmod::mass, r.mass);
  put_integer(w, refmod::nq, r.nq());
  put(w, refmod::mode_names, {}, r.mode_names);
  put(w, refmod::frequencies_hz, {}, r.frequencies_hz);
  put_integer(w, refmod::n_low, r.n_low);
  put_integer(w, refmod::n_high, r.n_high());
  put(w, refmod::reduction_method, r.reduction_method);
  put(w, refmod::interface, r.interface_description);
  if (r.section_translation.size()) {
    put(w, refmod::section_translation, {}, r.section_translation);
    put(w, refmod::long_axis, {}, Eigen::VectorXd(r.long_axis));
  }
  const Damping& d = sid.damping;
  put_group(w, damping::group);
  for (const auto& [item, value] : {std::pair{&damping::kappa, d.kappa}, {&damping::f1_hz, d.f1_hz}, {&damping::f2_hz, d.f2_hz},
                                     {&damping::alpha1, d.alpha1}, {&damping::alpha2, d.alpha2}})
    put(w, *item, value);
}

/// Writes a list group and, for each member, its group and then its content.
template <class Member, class WriteMember>
void write_list(h5::Writer& w, const Item& list, const Item& member_group, const std::vector<Member>& members,
                WriteMember write_member) {
  put_group(w, list);
  for (const Member& m : members) {
    put_group(w, member_group, m.name);
    write_member(m);
  }
}

void write_nodes(h5::Writer& w, const Sid& sid) {
  write_list(w, node::list, node::group, sid.nodes, [&](const Node& n) {
    put_taylor(w, node::origin, n.name, n.origin);
    put(w, node::phi, n.name, n.phi);
    put(w, node::psi, n.name, n.psi);
    put_taylor(w, node::AP, n.name, n.AP);
  });
}

void write_master_patches(h5::Writer& w, const Sid& sid) {
  write_list(w, master::list, master::group, sid.master_patches, [&](const MasterPatch& m) {
    const Eigen::VectorXi degrees = Eigen::Map<const Eigen::VectorXi>(m.degrees.data(), Eigen::Index(m.degrees.size()));
    put(w, master::degrees, m.name, degrees);
    for (std::size_t d = 0; d < m.knots.size(); ++d)
      w.vector(master::knots.at(m.name, std::to_string(d)), m.knots[d], master::knots.units_text());
    put(w, master::weights, m.name, m.weights);
    put(w, master::control_points, m.name, m.control_points);
    put(w, master::Phi, m.name, m.Phi);
  });
}

void write_contact(h5::Writer& w, const Sid& sid) {
  write_list(w, contact::list, contact::group, sid.contact_surfaces, [&](const ContactSurface& s) {
    if (!s.patch.empty()) put_attribute(w, contact::patch, s.name, s.patch);
    put_attribute(w, contact::side, s.name, s.side);
    put_attribute(w, contact::master_patch, s.name, s.master_patch);
    put(w, contact::parameter, s.name, s.parameter);
    put(w, contact::element, s.name, s.element);
    put(w, contact::position, s.name, s.position);
    put(w, contact::normal, s.name, s.normal);
    put(w, contact::weight, s.name, s.weight);
    put(w, contact::Psi, s.name, s.Psi);
    if (s.in_interface.size() > 0) put(w, contact::in_interface, s.name, s.in_interface);
  });
}

void write_stress(h5::Writer& w, const Sid& sid) {
  write_list(w, stress::list, stress::group, sid.stress_recovery, [&](const StressRecovery& s) {
    if (!s.patch.empty()) put_attribute(w, stress::patch, s.name, s.patch);
    put(w, stress::components, s.name, s.components);
    put(w, stress::position, s.name, s.position);
    put(w, stress::S, s.name, s.S);
  });
}

void write_patches(h5::Writer& w, const Sid& sid) {
  if (sid.patches.empty()) return;
  write_list(w, patches::list, patches::group, sid.patches, [&](const PatchInfo& p) {
    put(w, patches::youngs_modulus, p.name, p.material.youngs_modulus);
    put(w, patches::poisson_ratio, p.name, p.material.poisson_ratio);
    put(w, patches::density, p.name, p.material.density);
    if (!p.interfaces.empty()) put(w, patches::interfaces, p.name, p.interfaces);
  });
}

void write_transfer(h5::Writer& w, const Sid& sid) {
  if (!sid.transfer) return;
  put_group(w, transfer::group);
  put(w, transfer::coarse_model_sha256, sid.transfer->coarse_model_sha256);
  put(w, transfer::coarse_to_fine, {}, sid.transfer->coarse_to_fine);
  put(w, transfer::fine_to_coarse, {}, sid.transfer->fine_to_coarse);
}

void write_discretization(h5::Writer& w, const Sid& sid) {
  if (!sid.discretization) return;
  put_group(w, discretization::group);
  put(w, discretization::elements_per_level, {}, sid.discretization->elements_per_level);
  put(w, discretization::functions_per_level, {}, sid.discretization->functions_per_level);
  put_integer(w, discretization::free_dofs, sid.discretization->free_dofs);
  if (sid.discretization->contact_radius > 0) put(w, discretization::contact_radius, sid.discretization->contact_radius);
}

void write_visual(h5::Writer& w, const Sid& sid) {
  if (!sid.visual) return;
  const VisualMesh& v = *sid.visual;
  put_group(w, visual::group);
  put_integer(w, visual::corners_per_cell, v.corners_per_cell);
  put(w, visual::position, {}, v.position);
  put(w, visual::cells, {}, v.cells);
  put(w, visual::Phi, {}, v.Phi);
  if (v.stress_components.empty()) return;
  put(w, visual::stress_components, {}, v.stress_components);
  put(w, visual::S, {}, v.S);
}

void write_provenance(h5::Writer& w, const Sid& sid) {
  const Provenance& p = sid.provenance;
  put_group(w, provenance::group);
  put(w, provenance::model_file, p.model_file);
  put(w, provenance::model_sha256, p.model_sha256);
  put(w, provenance::program_version, p.program_version);
  put(w, provenance::created_utc, p.created_utc);
  if (!p.command_line.empty()) put(w, provenance::command_line, p.command_line);
  std::vector<std::string> names;
  Eigen::VectorXd seconds(Eigen::Index(p.timings_s.size()));
  for (std::size_t i = 0; i < p.timings_s.size(); ++i) {
    names.push_back(p.timings_s[i].first);
    seconds(Eigen::Index(i)) = p.timings_s[i].second;
  }
  put(w, provenance::timing_names, {}, names);
  put(w, provenance::timings_s, {}, seconds);
}

}  // namespace

void write_sid(const Sid& sid, const std::string& path, const WriteOptions& options) {
  validate_sid(sid, path);
  AtomicOutput out(path);
  {
    h5::Writer w(out.temp_path());
    auto part = [&](const char* name, auto&& write) {
      if (options.on_part) options.on_part(name);
      write();
    };
    part("header", [&] {
      put_group(w, header::group);
      put_integer(w, header::version, kSchemaVersion);
      put(w, header::program_version, sid.provenance.program_version);
    });
    part("body", [&] { write_body(w, sid); });
    part("refmod", [&] { write_refmod(w, sid); });
    part("terms", [&] {
      put_group(w, terms_group);
      for (const Term& term : terms()) put_taylor(w, term.item, {}, sid.*(term.member));
    });
    part("nodes", [&] { write_nodes(w, sid); });
    part("master", [&] { write_master_patches(w, sid); });
    part("contact", [&] { write_contact(w, sid); });
    part("stress", [&] { write_stress(w, sid); });
    part("patches", [&] { write_patches(w, sid); });
    part("transfer", [&] { write_transfer(w, sid); });
    part("discretization", [&] { write_discretization(w, sid); });
    part("visual", [&] { write_visual(w, sid); });
    part("provenance", [&] { write_provenance(w, sid); });
    w.close();
  }
  out.commit();
}

}  // namespace isosid::format

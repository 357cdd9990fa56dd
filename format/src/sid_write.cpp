// Writes a SID to HDF5 (layout in format/README.md) through an atomic temporary file.
#include "isosid/format/hdf5_file.hpp"
#include "isosid/format/atomic_output.hpp"
#include "isosid/format/sid_io.hpp"
#include "isosid/format/sid_validate.hpp"
#include "sid_layout.hpp"

namespace isosid::format {
namespace {

void write_taylor(h5::Writer& w, const std::string& path, const Taylor& t, const std::string& units) {
  w.group(path);
  w.attribute(path, "order", double(t.order()));
  w.attribute(path, "units", units);
  w.matrix(path + "/M0", t.M0, units);
  if (t.order() == 1) w.tensor(path + "/M1", t.M1, units);
}

void write_body(h5::Writer& w, const Sid& sid) {
  w.group("/body");
  w.string("/body/name", sid.body_name);
  w.string("/body/analysis_type", to_string(sid.analysis));
  w.scalar("/body/youngs_modulus", sid.material.youngs_modulus, "Pa");
  w.scalar("/body/poisson_ratio", sid.material.poisson_ratio, "1");
  w.scalar("/body/density", sid.material.density, "kg/m^3");
  w.scalar("/body/thickness", sid.thickness, "m");
}

void write_refmod(h5::Writer& w, const Sid& sid) {
  const RefMod& r = sid.refmod;
  w.group("/refmod");
  w.attribute("/refmod", "q_units", "sqrt(kg)*m for mass-normalized modes ([q])");
  w.scalar("/refmod/mass", r.mass, "kg");
  w.integer("/refmod/nq", r.nq());
  w.strings("/refmod/mode_names", r.mode_names);
  w.vector("/refmod/frequencies_hz", r.frequencies_hz, "Hz");
  w.integer("/refmod/n_low", r.n_low);
  w.integer("/refmod/n_high", r.n_high());
  w.string("/refmod/reduction_method", r.reduction_method);
  w.string("/refmod/interface", r.interface_description);
  const Damping& d = sid.damping;
  w.group("/damping");
  w.scalar("/damping/kappa", d.kappa, "1");
  w.scalar("/damping/f1_hz", d.f1_hz, "Hz");
  w.scalar("/damping/f2_hz", d.f2_hz, "Hz");
  w.scalar("/damping/alpha1", d.alpha1, "1/s");
  w.scalar("/damping/alpha2", d.alpha2, "s");
}

void write_nodes(h5::Writer& w, const Sid& sid) {
  w.group("/nodes");
  for (const Node& n : sid.nodes) {
    const std::string p = layout::node_path(n.name);
    w.group(p);
    write_taylor(w, p + "/origin", n.origin, "m");
    w.matrix(p + "/phi", n.phi, "m/[q]");
    w.matrix(p + "/psi", n.psi, "rad/[q]");
    write_taylor(w, p + "/AP", n.AP, "1");
  }
}

void write_master_patches(h5::Writer& w, const Sid& sid) {
  w.group("/master");
  for (const MasterPatch& m : sid.master_patches) {
    const std::string p = layout::master_path(m.name);
    w.group(p);
    w.integers(p + "/degrees", Eigen::Map<const Eigen::VectorXi>(m.degrees.data(), Eigen::Index(m.degrees.size())));
    for (std::size_t d = 0; d < m.knots.size(); ++d) w.vector(p + "/knots_" + std::to_string(d), m.knots[d], "1");
    w.vector(p + "/weights", m.weights, "1");
    w.matrix(p + "/control_points", m.control_points, "m");
    w.matrix(p + "/Phi", m.Phi, "m/[q]");
  }
}

void write_contact(h5::Writer& w, const Sid& sid) {
  w.group("/contact");
  for (const ContactSurface& s : sid.contact_surfaces) {
    const std::string p = layout::contact_path(s.name);
    w.group(p);
    w.attribute(p, "side", s.side);
    w.attribute(p, "master_patch", s.master_patch);
    w.matrix(p + "/parameter", s.parameter, "1");
    w.integers(p + "/element", s.element);
    w.matrix(p + "/position", s.position, "m");
    w.matrix(p + "/normal", s.normal, "1");
    w.vector(p + "/weight", s.weight, "m^2");
    w.matrix(p + "/Psi", s.Psi, "m/[q]");
  }
}

void write_stress(h5::Writer& w, const Sid& sid) {
  w.group("/stress");
  for (const StressRecovery& s : sid.stress_recovery) {
    const std::string p = layout::stress_path(s.name);
    w.group(p);
    w.strings(p + "/components", s.components);
    w.matrix(p + "/position", s.position, "m");
    w.matrix(p + "/S", s.S, "Pa/[q]");
  }
}

void write_transfer(h5::Writer& w, const Sid& sid) {
  if (!sid.transfer) return;
  w.group("/transfer");
  w.string("/transfer/coarse_model_sha256", sid.transfer->coarse_model_sha256);
  w.matrix("/transfer/coarse_to_fine", sid.transfer->coarse_to_fine, "1");
  w.matrix("/transfer/fine_to_coarse", sid.transfer->fine_to_coarse, "1");
}

void write_discretization(h5::Writer& w, const Sid& sid) {
  if (!sid.discretization) return;
  w.group("/discretization");
  w.integers("/discretization/elements_per_level", sid.discretization->elements_per_level);
  w.integers("/discretization/functions_per_level", sid.discretization->functions_per_level);
  w.integer("/discretization/free_dofs", sid.discretization->free_dofs);
}

void write_provenance(h5::Writer& w, const Sid& sid) {
  const Provenance& p = sid.provenance;
  w.group("/provenance");
  w.string("/provenance/model_file", p.model_file);
  w.string("/provenance/model_sha256", p.model_sha256);
  w.string("/provenance/program_version", p.program_version);
  w.string("/provenance/created_utc", p.created_utc);
  std::vector<std::string> names;
  Eigen::VectorXd seconds(Eigen::Index(p.timings_s.size()));
  for (std::size_t i = 0; i < p.timings_s.size(); ++i) {
    names.push_back(p.timings_s[i].first);
    seconds(Eigen::Index(i)) = p.timings_s[i].second;
  }
  w.strings("/provenance/timing_names", names);
  w.vector("/provenance/timings_s", seconds, "s");
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
      w.group("/isosid");
      w.integer("/isosid/version", kSchemaVersion);
      w.string("/isosid/program_version", sid.provenance.program_version);
    });
    part("body", [&] { write_body(w, sid); });
    part("refmod", [&] { write_refmod(w, sid); });
    part("terms", [&] {
      w.group("/terms");
      for (const auto& spec : layout::terms()) write_taylor(w, layout::term_path(spec.name), sid.*(spec.member), spec.units);
    });
    part("nodes", [&] { write_nodes(w, sid); });
    part("master", [&] { write_master_patches(w, sid); });
    part("contact", [&] { write_contact(w, sid); });
    part("stress", [&] { write_stress(w, sid); });
    part("transfer", [&] { write_transfer(w, sid); });
    part("discretization", [&] { write_discretization(w, sid); });
    part("provenance", [&] { write_provenance(w, sid); });
    w.close();
  }
  out.commit();
}

}  // namespace isosid::format

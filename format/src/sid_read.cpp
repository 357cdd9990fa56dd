// Reads and validates a SID from HDF5; paths from the layout table.
#include "isosid/format/hdf5_file.hpp"
#include "isosid/format/error.hpp"
#include "isosid/format/file_kind.hpp"
#include "isosid/format/isolated_probe.hpp"
#include "isosid/format/sid_io.hpp"
#include "isosid/format/sid_layout.hpp"
#include "isosid/format/sid_validate.hpp"

namespace isosid::format {
namespace {

using namespace layout;

Taylor read_taylor(const h5::Reader& r, const Item& item, std::string_view name = {}) {
  const std::string path = item.at(name);
  Taylor t;
  t.M0 = r.matrix(path + "/M0");
  if (r.exists(path + "/M1")) t.M1 = r.tensor(path + "/M1");
  // the order the writer declared must be the order stored
  const double order = r.double_attribute(path, "order");
  if (order != 0 && order != 1) r.fail(path, "attribute 'order' must be 0 or 1");
  if ((order == 1) != !t.M1.empty())
    r.fail(path, std::string("attribute 'order' is ") + (order == 1 ? "1 but there is no M1" : "0 but there is an M1"));
  return t;
}

void read_body(const h5::Reader& r, Sid& sid) {
  sid.body_name = r.string(body::name.at());
  const std::string type = r.string(body::analysis_type.at());
  const auto analysis = analysis_type_from_string(type);
  if (!analysis) r.fail(body::analysis_type.at(), "unknown analysis type '" + type + "'");
  sid.analysis = *analysis;
  sid.material.youngs_modulus = r.scalar(body::youngs_modulus.at());
  sid.material.poisson_ratio = r.scalar(body::poisson_ratio.at());
  sid.material.density = r.scalar(body::density.at());
  sid.thickness = r.scalar(body::thickness.at());
}

void read_refmod(const h5::Reader& r, Sid& sid) {
  RefMod& m = sid.refmod;
  m.mass = r.scalar(refmod::mass.at());
  m.frequencies_hz = r.vector(refmod::frequencies_hz.at());
  const long long nq = r.integer(refmod::nq.at());
  if (nq != m.frequencies_hz.size())
    r.fail(refmod::nq.at(), "is " + std::to_string(nq) + " but " + refmod::frequencies_hz.at() + " has " +
                                std::to_string(m.frequencies_hz.size()) + " entries");
  m.mode_names = r.strings(refmod::mode_names.at());
  m.n_low = static_cast<int>(r.integer(refmod::n_low.at()));
  if (r.exists(refmod::n_high.at()) && r.integer(refmod::n_high.at()) != nq - m.n_low)
    r.fail(refmod::n_high.at(), "is " + std::to_string(r.integer(refmod::n_high.at())) + " but nq - n_low = " +
                                    std::to_string(nq - m.n_low));
  m.reduction_method = r.string(refmod::reduction_method.at());
  m.interface_description = r.string(refmod::interface.at());
  if (r.exists(refmod::section_translation.at())) {
    m.section_translation = r.matrix(refmod::section_translation.at());
    const Eigen::VectorXd axis = r.vector(refmod::long_axis.at());
    if (axis.size() != 3) r.fail(refmod::long_axis.at(), "has " + std::to_string(axis.size()) + " entries, expected 3");
    m.long_axis = axis;
  }
  Damping& d = sid.damping;
  d.kappa = r.scalar(damping::kappa.at());
  d.f1_hz = r.scalar(damping::f1_hz.at());
  d.f2_hz = r.scalar(damping::f2_hz.at());
  d.alpha1 = r.scalar(damping::alpha1.at());
  d.alpha2 = r.scalar(damping::alpha2.at());
}

/// Reads every member of a list group (nodes, contact surfaces, ...) in the order written.
template <class Member, class ReadMember>
void read_list(const h5::Reader& r, const Item& list, std::vector<Member>& out, ReadMember read_member) {
  for (const std::string& name : r.children(list.at())) {
    Member m;
    m.name = name;
    read_member(m);
    out.push_back(std::move(m));
  }
}

void read_nodes(const h5::Reader& r, Sid& sid) {
  read_list(r, node::list, sid.nodes, [&](Node& n) {
    n.origin = read_taylor(r, node::origin, n.name);
    n.phi = r.matrix(node::phi.at(n.name));
    n.psi = r.matrix(node::psi.at(n.name));
    n.AP = read_taylor(r, node::AP, n.name);
  });
}

void read_master_patches(const h5::Reader& r, Sid& sid) {
  read_list(r, master::list, sid.master_patches, [&](MasterPatch& m) {
    const Eigen::VectorXi degrees = r.integers(master::degrees.at(m.name));
    if (degrees.size() < 1 || degrees.size() > 3) r.fail(master::degrees.at(m.name), "needs 1 to 3 entries");
    m.degrees.assign(degrees.data(), degrees.data() + degrees.size());
    for (std::size_t d = 0; d < m.degrees.size(); ++d) m.knots.push_back(r.vector(master::knots.at(m.name, std::to_string(d))));
    m.weights = r.vector(master::weights.at(m.name));
    m.control_points = r.matrix(master::control_points.at(m.name));
    m.Phi = r.matrix(master::Phi.at(m.name));
  });
}

void read_contact(const h5::Reader& r, Sid& sid) {
  read_list(r, contact::list, sid.contact_surfaces, [&](ContactSurface& s) {
    if (r.has_attribute(contact::patch.at(s.name), std::string(contact::patch.attribute)))
      s.patch = r.string_attribute(contact::patch.at(s.name), std::string(contact::patch.attribute));
    s.side = r.string_attribute(contact::side.at(s.name), std::string(contact::side.attribute));
    s.master_patch = r.string_attribute(contact::master_patch.at(s.name), std::string(contact::master_patch.attribute));
    s.parameter = r.matrix(contact::parameter.at(s.name));
    s.element = r.integers(contact::element.at(s.name));
    s.position = r.matrix(contact::position.at(s.name));
    s.normal = r.matrix(contact::normal.at(s.name));
    s.weight = r.vector(contact::weight.at(s.name));
    s.Psi = r.matrix(contact::Psi.at(s.name));
    if (r.exists(contact::in_interface.at(s.name))) {
      s.in_interface = r.integers(contact::in_interface.at(s.name));
      // present but empty would read as absent, which the validator does not check
      if (s.in_interface.size() != s.points()) r.fail(contact::in_interface.at(s.name), "one entry per point expected");
    }
  });
}

void read_stress(const h5::Reader& r, Sid& sid) {
  read_list(r, stress::list, sid.stress_recovery, [&](StressRecovery& s) {
    if (r.has_attribute(stress::patch.at(s.name), std::string(stress::patch.attribute)))
      s.patch = r.string_attribute(stress::patch.at(s.name), std::string(stress::patch.attribute));
    s.components = r.strings(stress::components.at(s.name));
    s.position = r.matrix(stress::position.at(s.name));
    s.S = r.matrix(stress::S.at(s.name));
  });
}

void read_transfer(const h5::Reader& r, Sid& sid) {
  if (!r.exists(transfer::group.at())) return;
  TransferOperator t;
  t.coarse_model_sha256 = r.string(transfer::coarse_model_sha256.at());
  t.coarse_to_fine = r.matrix(transfer::coarse_to_fine.at());
  t.fine_to_coarse = r.matrix(transfer::fine_to_coarse.at());
  sid.transfer = std::move(t);
}

void read_patches(const h5::Reader& r, Sid& sid) {
  if (!r.exists(patches::list.at())) return;
  read_list(r, patches::list, sid.patches, [&](PatchInfo& p) {
    p.material.youngs_modulus = r.scalar(patches::youngs_modulus.at(p.name));
    p.material.poisson_ratio = r.scalar(patches::poisson_ratio.at(p.name));
    p.material.density = r.scalar(patches::density.at(p.name));
    if (r.exists(patches::interfaces.at(p.name))) p.interfaces = r.strings(patches::interfaces.at(p.name));
  });
}

void read_discretization(const h5::Reader& r, Sid& sid) {
  if (!r.exists(discretization::group.at())) return;
  Discretization d;
  d.elements_per_level = r.integers(discretization::elements_per_level.at());
  d.functions_per_level = r.integers(discretization::functions_per_level.at());
  d.free_dofs = int(r.integer(discretization::free_dofs.at()));
  if (r.exists(discretization::contact_radius.at())) d.contact_radius = r.scalar(discretization::contact_radius.at());
  sid.discretization = std::move(d);
}

void read_provenance(const h5::Reader& r, Sid& sid) {
  Provenance& p = sid.provenance;
  p.model_file = r.string(provenance::model_file.at());
  p.model_sha256 = r.string(provenance::model_sha256.at());
  p.program_version = r.string(provenance::program_version.at());
  p.created_utc = r.string(provenance::created_utc.at());
  if (r.exists(provenance::command_line.at())) p.command_line = r.string(provenance::command_line.at());
  const std::vector<std::string> names = r.strings(provenance::timing_names.at());
  const Eigen::VectorXd seconds = r.vector(provenance::timings_s.at(), Eigen::Index(names.size()));
  for (std::size_t i = 0; i < names.size(); ++i) p.timings_s.emplace_back(names[i], seconds(Eigen::Index(i)));
}

void read_visual(const h5::Reader& r, Sid& sid) {
  if (!r.exists(visual::group.at())) return;
  VisualMesh v;
  v.corners_per_cell = int(r.integer(visual::corners_per_cell.at()));
  v.position = r.matrix(visual::position.at());
  v.cells = r.integers(visual::cells.at());
  v.Phi = r.matrix(visual::Phi.at());
  if (r.exists(visual::stress_components.at())) {
    v.stress_components = r.strings(visual::stress_components.at());
    v.S = r.matrix(visual::S.at());
  }
  sid.visual = std::move(v);
}

Sid read_sid_unprobed(const std::string& path, const ReadOptions& options) {
  const h5::Reader r(path);
  const std::string version_path = header::version.at();
  if (!r.exists(version_path)) r.fail(version_path, "missing: not an isosid SID file");
  const long long version = r.integer(version_path);
  if (version != kSchemaVersion)
    r.fail(version_path, "unsupported schema version " + std::to_string(version) + " (this program reads " +
                             std::to_string(kSchemaVersion) + ")");
  Sid sid;
  read_body(r, sid);
  read_refmod(r, sid);
  for (const Term& term : terms()) sid.*(term.member) = read_taylor(r, term.item);
  read_nodes(r, sid);
  read_master_patches(r, sid);
  read_contact(r, sid);
  read_stress(r, sid);
  read_transfer(r, sid);
  read_patches(r, sid);
  read_discretization(r, sid);
  if (options.visual) read_visual(r, sid);
  read_provenance(r, sid);
  validate_sid(sid, path);
  return sid;
}

}  // namespace

Sid read_sid(const std::string& path, const ReadOptions& options) {
  // a corrupt file may crash libhdf5 or make it allocate without bound: a child reads it first,
  // and its verdict on bad input is final; a FIFO or a directory is refused before, at once
  require_input_file(path);
  if (options.probe) probe_in_child(path, [&] { read_sid_unprobed(path, options); });
  return read_sid_unprobed(path, options);
}

}  // namespace isosid::format

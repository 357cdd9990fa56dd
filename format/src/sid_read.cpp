// Reads and validates a SID from HDF5 (layout in format/README.md).
#include "isosid/format/hdf5_file.hpp"
#include "isosid/format/error.hpp"
#include "isosid/format/sid_io.hpp"
#include "isosid/format/sid_validate.hpp"
#include "sid_layout.hpp"

namespace isosid::format {
namespace {

Taylor read_taylor(const h5::Reader& r, const std::string& path) {
  Taylor t;
  t.M0 = r.matrix(path + "/M0");
  if (r.exists(path + "/M1")) t.M1 = r.tensor(path + "/M1");
  return t;
}

void read_body(const h5::Reader& r, Sid& sid) {
  sid.body_name = r.string("/body/name");
  const std::string type = r.string("/body/analysis_type");
  const auto analysis = analysis_type_from_string(type);
  if (!analysis) r.fail("/body/analysis_type", "unknown analysis type '" + type + "'");
  sid.analysis = *analysis;
  sid.material.youngs_modulus = r.scalar("/body/youngs_modulus");
  sid.material.poisson_ratio = r.scalar("/body/poisson_ratio");
  sid.material.density = r.scalar("/body/density");
  sid.thickness = r.scalar("/body/thickness");
}

void read_refmod(const h5::Reader& r, Sid& sid) {
  RefMod& m = sid.refmod;
  m.mass = r.scalar("/refmod/mass");
  m.frequencies_hz = r.vector("/refmod/frequencies_hz");
  const long long nq = r.integer("/refmod/nq");
  if (nq != m.frequencies_hz.size())
    r.fail("/refmod/nq", "is " + std::to_string(nq) + " but /refmod/frequencies_hz has " +
                             std::to_string(m.frequencies_hz.size()) + " entries");
  m.mode_names = r.strings("/refmod/mode_names");
  m.n_low = static_cast<int>(r.integer("/refmod/n_low"));
  m.reduction_method = r.string("/refmod/reduction_method");
  m.interface_description = r.string("/refmod/interface");
  Damping& d = sid.damping;
  d.kappa = r.scalar("/damping/kappa");
  d.f1_hz = r.scalar("/damping/f1_hz");
  d.f2_hz = r.scalar("/damping/f2_hz");
  d.alpha1 = r.scalar("/damping/alpha1");
  d.alpha2 = r.scalar("/damping/alpha2");
}

void read_nodes(const h5::Reader& r, Sid& sid) {
  for (const std::string& name : r.children("/nodes")) {
    const std::string p = layout::node_path(name);
    Node n;
    n.name = name;
    n.origin = read_taylor(r, p + "/origin");
    n.phi = r.matrix(p + "/phi");
    n.psi = r.matrix(p + "/psi");
    n.AP = read_taylor(r, p + "/AP");
    sid.nodes.push_back(std::move(n));
  }
}

void read_master_patches(const h5::Reader& r, Sid& sid) {
  for (const std::string& name : r.children("/master")) {
    const std::string p = layout::master_path(name);
    MasterPatch m;
    m.name = name;
    const Eigen::VectorXi degrees = r.integers(p + "/degrees");
    if (degrees.size() < 1 || degrees.size() > 3) r.fail(p + "/degrees", "needs 1 to 3 entries");
    m.degrees.assign(degrees.data(), degrees.data() + degrees.size());
    for (std::size_t d = 0; d < m.degrees.size(); ++d) m.knots.push_back(r.vector(p + "/knots_" + std::to_string(d)));
    m.weights = r.vector(p + "/weights");
    m.control_points = r.matrix(p + "/control_points");
    m.Phi = r.matrix(p + "/Phi");
    sid.master_patches.push_back(std::move(m));
  }
}

void read_contact(const h5::Reader& r, Sid& sid) {
  for (const std::string& name : r.children("/contact")) {
    const std::string p = layout::contact_path(name);
    ContactSurface s;
    s.name = name;
    s.side = r.string_attribute(p, "side");
    s.master_patch = r.string_attribute(p, "master_patch");
    s.parameter = r.matrix(p + "/parameter");
    s.element = r.integers(p + "/element");
    s.position = r.matrix(p + "/position");
    s.normal = r.matrix(p + "/normal");
    s.weight = r.vector(p + "/weight");
    s.Psi = r.matrix(p + "/Psi");
    sid.contact_surfaces.push_back(std::move(s));
  }
}

void read_stress(const h5::Reader& r, Sid& sid) {
  for (const std::string& name : r.children("/stress")) {
    const std::string p = layout::stress_path(name);
    StressRecovery s;
    s.name = name;
    s.components = r.strings(p + "/components");
    s.position = r.matrix(p + "/position");
    s.S = r.matrix(p + "/S");
    sid.stress_recovery.push_back(std::move(s));
  }
}

void read_transfer(const h5::Reader& r, Sid& sid) {
  if (!r.exists("/transfer")) return;
  TransferOperator t;
  t.coarse_model_sha256 = r.string("/transfer/coarse_model_sha256");
  t.coarse_to_fine = r.matrix("/transfer/coarse_to_fine");
  t.fine_to_coarse = r.matrix("/transfer/fine_to_coarse");
  sid.transfer = std::move(t);
}

void read_discretization(const h5::Reader& r, Sid& sid) {
  if (!r.exists("/discretization")) return;
  Discretization d;
  d.elements_per_level = r.integers("/discretization/elements_per_level");
  d.functions_per_level = r.integers("/discretization/functions_per_level");
  d.free_dofs = int(r.integer("/discretization/free_dofs"));
  sid.discretization = std::move(d);
}

void read_provenance(const h5::Reader& r, Sid& sid) {
  Provenance& p = sid.provenance;
  p.model_file = r.string("/provenance/model_file");
  p.model_sha256 = r.string("/provenance/model_sha256");
  p.program_version = r.string("/provenance/program_version");
  p.created_utc = r.string("/provenance/created_utc");
  const std::vector<std::string> names = r.strings("/provenance/timing_names");
  const Eigen::VectorXd seconds = r.vector("/provenance/timings_s", Eigen::Index(names.size()));
  for (std::size_t i = 0; i < names.size(); ++i) p.timings_s.emplace_back(names[i], seconds(Eigen::Index(i)));
}

}  // namespace

Sid read_sid(const std::string& path) {
  const h5::Reader r(path);
  if (!r.exists("/isosid/version")) r.fail("/isosid/version", "missing: not an isosid SID file");
  const long long version = r.integer("/isosid/version");
  if (version != kSchemaVersion)
    r.fail("/isosid/version", "unsupported schema version " + std::to_string(version) + " (this program reads " +
                                  std::to_string(kSchemaVersion) + ")");
  Sid sid;
  read_body(r, sid);
  read_refmod(r, sid);
  for (const auto& spec : layout::terms()) sid.*(spec.member) = read_taylor(r, layout::term_path(spec.name));
  read_nodes(r, sid);
  read_master_patches(r, sid);
  read_contact(r, sid);
  read_stress(r, sid);
  read_transfer(r, sid);
  read_discretization(r, sid);
  read_provenance(r, sid);
  validate_sid(sid, path);
  return sid;
}

}  // namespace isosid::format

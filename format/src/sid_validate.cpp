// Consistency checks of a SID; the field names are the HDF5 paths of the layout.
#include "isosid/format/sid_validate.hpp"

#include "isosid/format/error.hpp"
#include "isosid/format/bspline_basis.hpp"
#include "sid_layout.hpp"

#include <cmath>
#include <set>

namespace isosid::format {
namespace {

using Eigen::Index;
using Eigen::MatrixXd;

class Checker {
public:
  explicit Checker(const std::string& file) : file_(file) {}

  [[noreturn]] void fail(const std::string& field, const std::string& problem) const {
    throw InputError(file_, field, problem);
  }
  void require(bool ok, const std::string& field, const std::string& problem) const {
    if (!ok) fail(field, problem);
  }
  void finite(const std::string& field, const MatrixXd& m) const {
    for (Index j = 0; j < m.cols(); ++j)
      for (Index i = 0; i < m.rows(); ++i)
        if (!std::isfinite(m(i, j)))
          fail(field, "non-finite value at (" + std::to_string(i) + ", " + std::to_string(j) + ")");
  }
  void finite(const std::string& field, double v) const {
    if (!std::isfinite(v)) fail(field, "non-finite value");
  }
  void shape(const std::string& field, const MatrixXd& m, Index rows, Index cols) const {
    if (m.rows() != rows || m.cols() != cols)
      fail(field, "wrong shape (" + std::to_string(m.rows()) + ", " + std::to_string(m.cols()) + "), expected (" +
                      std::to_string(rows) + ", " + std::to_string(cols) + ")");
    finite(field, m);
  }
  void taylor(const std::string& field, const Taylor& t, Index rows, Index cols, Index nq, bool order1_allowed) const {
    shape(field + "/M0", t.M0, rows, cols);
    if (t.M1.empty()) return;
    require(order1_allowed, field + "/M1", "this term has order 0 and takes no M1");
    require(Index(t.M1.size()) == nq, field + "/M1",
            "has " + std::to_string(t.M1.size()) + " slices, expected nq = " + std::to_string(nq));
    for (std::size_t k = 0; k < t.M1.size(); ++k) shape(field + "/M1[" + std::to_string(k) + "]", t.M1[k], rows, cols);
  }
  // Symmetric to round-off of the products that formed it (relative 1e-8 of the largest entry;
  // congruence transforms in double precision leave asymmetries near 1e-14).
  void symmetric(const std::string& field, const MatrixXd& m) const {
    const double scale = m.cwiseAbs().maxCoeff();
    if (scale == 0) return;
    const double asym = (m - m.transpose()).cwiseAbs().maxCoeff() / scale;
    if (asym > 1e-8) fail(field, "not symmetric (largest relative asymmetry " + std::to_string(asym) + ")");
  }

private:
  std::string file_;
};

void check_body(const Checker& c, const Sid& sid) {
  c.require(!sid.body_name.empty(), "/body/name", "empty body name");
  const Material& m = sid.material;
  c.finite("/body/youngs_modulus", m.youngs_modulus);
  c.require(m.youngs_modulus > 0, "/body/youngs_modulus", "must be positive");
  c.finite("/body/poisson_ratio", m.poisson_ratio);
  c.require(m.poisson_ratio > -1 && m.poisson_ratio < 0.5, "/body/poisson_ratio", "must lie in (-1, 0.5)");
  c.finite("/body/density", m.density);
  c.require(m.density > 0, "/body/density", "must be positive");
  c.finite("/body/thickness", sid.thickness);
  c.require(sid.thickness > 0, "/body/thickness", "must be positive");
}

void check_refmod(const Checker& c, const Sid& sid) {
  const RefMod& r = sid.refmod;
  const Index nq = r.nq();
  c.finite("/refmod/mass", r.mass);
  c.require(r.mass > 0, "/refmod/mass", "must be positive, is " + std::to_string(r.mass));
  c.finite("/refmod/frequencies_hz", r.frequencies_hz);
  for (Index i = 0; i < nq; ++i)
    c.require(r.frequencies_hz(i) >= 0, "/refmod/frequencies_hz", "negative frequency at " + std::to_string(i));
  c.require(Index(r.mode_names.size()) == nq, "/refmod/mode_names",
            "has " + std::to_string(r.mode_names.size()) + " names for nq = " + std::to_string(nq));
  c.require(r.n_low >= 0 && r.n_low <= nq, "/refmod/n_low", "must lie in [0, nq]");
  const Damping& d = sid.damping;
  for (auto [name, v] : {std::pair{"kappa", d.kappa}, {"f1_hz", d.f1_hz}, {"f2_hz", d.f2_hz},
                         {"alpha1", d.alpha1}, {"alpha2", d.alpha2}}) {
    c.finite(std::string("/damping/") + name, v);
    c.require(v >= 0, std::string("/damping/") + name, "must not be negative");
  }
}

void check_terms(const Checker& c, const Sid& sid) {
  const Index nq = sid.nq();
  struct Shape {
    Index rows, cols;
    bool order1;
  };
  const std::vector<std::pair<std::string, Shape>> shapes = {
      {"mdCM", {3, 1, true}},       {"J", {3, 3, true}},        {"Ct", {nq, 3, true}},
      {"Cr", {nq, 3, true}},        {"Me", {nq, nq, false}},    {"Gr", {3, 3 * nq, true}},
      {"Ge", {nq, 3 * nq, false}},  {"Oe", {nq, 6, true}},      {"ksigma", {nq, 1, true}},
      {"Ke", {nq, nq, false}},      {"De", {nq, nq, false}}};
  for (const auto& spec : layout::terms()) {
    const Taylor& t = sid.*(spec.member);
    const std::string field = layout::term_path(spec.name);
    for (const auto& [name, s] : shapes)
      if (name == spec.name) c.taylor(field, t, s.rows, s.cols, nq, s.order1);
  }
  c.symmetric("/terms/J/M0", sid.J.M0);
  c.symmetric("/terms/Me/M0", sid.Me.M0);
  c.symmetric("/terms/Ke/M0", sid.Ke.M0);
  c.symmetric("/terms/De/M0", sid.De.M0);
  for (Index i = 0; i < nq; ++i)
    c.require(sid.Me.M0(i, i) > 0, "/terms/Me/M0", "non-positive diagonal entry at " + std::to_string(i));
}

void check_unique(const Checker& c, const std::string& group, std::set<std::string>& seen, const std::string& name) {
  c.require(!name.empty() && name.find('/') == std::string::npos, group, "invalid name '" + name + "'");
  c.require(seen.insert(name).second, group, "duplicate name '" + name + "'");
}

void check_nodes(const Checker& c, const Sid& sid) {
  std::set<std::string> seen;
  for (const Node& n : sid.nodes) {
    check_unique(c, "/nodes", seen, n.name);
    const std::string p = layout::node_path(n.name);
    c.taylor(p + "/origin", n.origin, 3, 1, sid.nq(), true);
    c.shape(p + "/phi", n.phi, 3, sid.nq());
    c.shape(p + "/psi", n.psi, 3, sid.nq());
    c.taylor(p + "/AP", n.AP, 3, 3, sid.nq(), true);
  }
}

void check_master_patches(const Checker& c, const Sid& sid) {
  std::set<std::string> seen;
  const int dim = sid.dim();
  for (const MasterPatch& m : sid.master_patches) {
    check_unique(c, "/master", seen, m.name);
    const std::string p = layout::master_path(m.name);
    c.require(!m.degrees.empty() && m.degrees.size() <= 3, p + "/degrees", "needs 1 to 3 parametric directions");
    c.require(m.knots.size() == m.degrees.size(), p + "/knots", "one knot vector per direction required");
    Index ncp = 1;
    for (std::size_t d = 0; d < m.degrees.size(); ++d) {
      const std::string f = p + "/knots_" + std::to_string(d);
      c.finite(f, m.knots[d]);
      c.require(m.degrees[d] >= 1 && m.degrees[d] <= kMaxDegree, p + "/degrees", "degree must lie in 1..15");
      for (Index i = 1; i < m.knots[d].size(); ++i)
        c.require(m.knots[d](i) >= m.knots[d](i - 1), f, "knots not non-decreasing at " + std::to_string(i));
      const Index n = m.knots[d].size() - m.degrees[d] - 1;
      c.require(n > m.degrees[d], f, "too few knots for degree " + std::to_string(m.degrees[d]));
      ncp *= n;
    }
    c.require(m.weights.size() == ncp, p + "/weights", "expected " + std::to_string(ncp) + " weights");
    c.finite(p + "/weights", m.weights);
    c.require(m.weights.size() == 0 || m.weights.minCoeff() > 0, p + "/weights", "weights must be positive");
    c.shape(p + "/control_points", m.control_points, ncp, dim);
    c.shape(p + "/Phi", m.Phi, ncp * dim, sid.nq());
  }
}

void check_contact(const Checker& c, const Sid& sid) {
  std::set<std::string> seen;
  const int dim = sid.dim();
  for (const ContactSurface& s : sid.contact_surfaces) {
    check_unique(c, "/contact", seen, s.name);
    const std::string p = layout::contact_path(s.name);
    const Index n = s.points();
    c.require(n > 0, p + "/weight", "a contact surface needs at least one point");
    c.finite(p + "/weight", s.weight);
    c.require(s.weight.minCoeff() > 0, p + "/weight", "weights must be positive");
    c.require(s.parameter.rows() == n, p + "/parameter", "one row per point expected");
    c.finite(p + "/parameter", s.parameter);
    c.require(s.element.size() == n, p + "/element", "one entry per point expected");
    c.require(s.element.minCoeff() >= 0, p + "/element", "element indices must not be negative");
    c.shape(p + "/position", s.position, n, dim);
    c.shape(p + "/normal", s.normal, n, dim);
    for (Index g = 0; g < n; ++g)
      c.require(std::abs(s.normal.row(g).norm() - 1.0) < 1e-8, p + "/normal", "not a unit vector at " + std::to_string(g));
    c.shape(p + "/Psi", s.Psi, n * dim, sid.nq());
    if (!s.master_patch.empty()) {
      bool found = false;
      for (const MasterPatch& m : sid.master_patches) found = found || m.name == s.master_patch;
      c.require(found, p, "names master patch '" + s.master_patch + "', which is not in /master");
    }
  }
}

void check_stress(const Checker& c, const Sid& sid) {
  std::set<std::string> seen;
  for (const StressRecovery& s : sid.stress_recovery) {
    check_unique(c, "/stress", seen, s.name);
    const std::string p = layout::stress_path(s.name);
    c.require(!s.components.empty(), p + "/components", "no stress components");
    c.require(s.position.cols() == sid.dim(), p + "/position", "expected " + std::to_string(sid.dim()) + " columns");
    c.finite(p + "/position", s.position);
    c.shape(p + "/S", s.S, s.position.rows() * Index(s.components.size()), sid.nq());
  }
}

void check_discretization(const Checker& c, const Sid& sid) {
  if (!sid.discretization) return;
  const Discretization& d = *sid.discretization;
  if (d.elements_per_level.size() == 0 || d.elements_per_level.size() != d.functions_per_level.size())
    c.fail("/discretization/functions_per_level", "needs one entry per level, as elements_per_level");
  if ((d.elements_per_level.array() < 0).any() || (d.functions_per_level.array() < 0).any() || d.free_dofs < 0)
    c.fail("/discretization", "negative count");
}

void check_transfer(const Checker& c, const Sid& sid) {
  if (!sid.transfer) return;
  const TransferOperator& t = *sid.transfer;
  const Index nc = t.coarse_to_fine.cols();
  c.shape("/transfer/coarse_to_fine", t.coarse_to_fine, sid.nq(), nc);
  c.shape("/transfer/fine_to_coarse", t.fine_to_coarse, nc, sid.nq());
}

}  // namespace

void validate_sid(const Sid& sid, const std::string& file) {
  const Checker c(file);
  check_body(c, sid);
  check_refmod(c, sid);
  check_terms(c, sid);
  check_nodes(c, sid);
  check_master_patches(c, sid);
  check_contact(c, sid);
  check_stress(c, sid);
  check_transfer(c, sid);
  check_discretization(c, sid);
}

}  // namespace isosid::format

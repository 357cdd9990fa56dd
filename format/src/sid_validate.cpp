// Consistency checks of a SID; field names, shape rules and list groups from the layout table.
#include "isosid/format/sid_validate.hpp"

#include "isosid/format/bspline_basis.hpp"
#include "isosid/format/error.hpp"
#include "isosid/format/patch_side.hpp"
#include "isosid/format/sid_layout.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

namespace isosid::format {
namespace {

using Eigen::Index;
using Eigen::MatrixXd;
using namespace layout;

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
  /// The item's matrix shape rule, evaluated with `sizes`.
  void shape(const layout::Item& item, std::string_view name, const MatrixXd& m, const layout::Sizes& sizes) const {
    shape(item.at(name), m, sizes(item.shape.rows), sizes(item.shape.cols));
  }
  void taylor(const layout::Item& item, std::string_view name, const Taylor& t, const layout::Sizes& sizes) const {
    const std::string field = item.at(name);
    const Index rows = sizes(item.shape.rows), cols = sizes(item.shape.cols), nq = sizes(layout::kNq);
    shape(field + "/M0", t.M0, rows, cols);
    if (t.M1.empty()) return;
    require(item.kind == layout::Kind::TaylorOrder1, field + "/M1", "this term has order 0 and takes no M1");
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

/// A material's values, reported at the given fields.
void check_material(const Checker& c, const Material& m, const std::string& E, const std::string& nu, const std::string& rho) {
  c.finite(E, m.youngs_modulus);
  c.require(m.youngs_modulus > 0, E, "must be positive");
  c.finite(nu, m.poisson_ratio);
  c.require(m.poisson_ratio > -1 && m.poisson_ratio < 0.5, nu, "must lie in (-1, 0.5)");
  c.finite(rho, m.density);
  c.require(m.density > 0, rho, "must be positive");
}

void check_body(const Checker& c, const Sid& sid) {
  c.require(!sid.body_name.empty(), body::name.at(), "empty body name");
  check_material(c, sid.material, body::youngs_modulus.at(), body::poisson_ratio.at(), body::density.at());
  c.finite(body::thickness.at(), sid.thickness);
  c.require(sid.thickness > 0, body::thickness.at(), "must be positive");
}

void check_refmod(const Checker& c, const Sid& sid) {
  const RefMod& r = sid.refmod;
  const Index nq = r.nq();
  c.finite(refmod::mass.at(), r.mass);
  c.require(r.mass > 0, refmod::mass.at(), "must be positive, is " + std::to_string(r.mass));
  c.finite(refmod::frequencies_hz.at(), r.frequencies_hz);
  for (Index i = 0; i < nq; ++i)
    c.require(r.frequencies_hz(i) >= 0, refmod::frequencies_hz.at(), "negative frequency at " + std::to_string(i));
  c.require(Index(r.mode_names.size()) == nq, refmod::mode_names.at(),
            "has " + std::to_string(r.mode_names.size()) + " names for nq = " + std::to_string(nq));
  c.require(r.n_low >= 0 && r.n_low <= nq, refmod::n_low.at(), "must lie in [0, nq]");
  if (r.section_translation.size()) {
    c.shape(refmod::section_translation.at(), r.section_translation, nq, 3);
    // shares of one kinetic energy among orthogonal projections: each in [0, 1], their sum
    // at most 1 (to round-off)
    c.require(r.section_translation.minCoeff() >= -1e-12 && r.section_translation.rowwise().sum().maxCoeff() <= 1 + 1e-9,
              refmod::section_translation.at(), "shares must lie in [0, 1] and sum to at most 1 per coordinate");
    c.finite(refmod::long_axis.at(), Eigen::MatrixXd(r.long_axis));
    c.require(std::abs(r.long_axis.norm() - 1) < 1e-6, refmod::long_axis.at(), "must be a unit vector");
  }
  // the low modes and the high modes each come in ascending order (the runtime takes the
  // leading ones as the low, and a frequency limit splits at the first one above it)
  for (Index i = 1; i < nq; ++i)
    if (i != r.n_low)
      c.require(r.frequencies_hz(i) >= r.frequencies_hz(i - 1), refmod::frequencies_hz.at(),
                "not ascending at " + std::to_string(i) + " (" + std::to_string(r.frequencies_hz(i - 1)) + " Hz, then " +
                    std::to_string(r.frequencies_hz(i)) + " Hz)");
  const Damping& d = sid.damping;
  for (auto [item, v] : {std::pair{&damping::kappa, d.kappa}, {&damping::f1_hz, d.f1_hz}, {&damping::f2_hz, d.f2_hz},
                         {&damping::alpha1, d.alpha1}, {&damping::alpha2, d.alpha2}}) {
    c.finite(item->at(), v);
    c.require(v >= 0, item->at(), "must not be negative");
  }
}

void check_terms(const Checker& c, const Sid& sid) {
  const Index nq = sid.nq();
  const layout::Sizes sizes(nq, sid.dim());
  for (const Term& term : terms()) c.taylor(term.item, {}, sid.*(term.member), sizes);
  auto m0_path = [](Taylor Sid::*member) {
    for (const Term& term : terms())
      if (term.member == member) return term.item.at() + "/M0";
    return std::string();
  };
  for (Taylor Sid::*member : {&Sid::J, &Sid::Me, &Sid::Ke, &Sid::De}) c.symmetric(m0_path(member), (sid.*member).M0);
  // the massless boundary of a MacNeal SID carries no mass, every other coordinate does
  const Index carrying = nq - sid.refmod.n_massless();
  for (Index i = 0; i < carrying; ++i)
    c.require(sid.Me.M0(i, i) > 0, m0_path(&Sid::Me), "non-positive diagonal entry at " + std::to_string(i));
  if (carrying < nq && sid.Me.M0.rows() == nq && sid.Me.M0.cols() == nq)
    c.require(sid.Me.M0.bottomRows(nq - carrying).isZero(0.0), m0_path(&Sid::Me),
              "rows " + std::to_string(carrying) + " to " + std::to_string(nq - 1) + " (the massless boundary) must be zero");
  // in the normal form (Me = I, Ke diagonal) Ke holds the squared circular frequencies: the
  // runtime applies Ke as that diagonal, so a list that disagrees would go unnoticed there
  const MatrixXd& K = sid.Ke.M0;
  if (nq == 0 || !(K - MatrixXd(K.diagonal().asDiagonal())).isZero(1e-12 * K.cwiseAbs().maxCoeff())) return;
  const Eigen::ArrayXd omega2 = (2 * M_PI * sid.refmod.frequencies_hz.array()).square();
  for (Index i = 0; i < nq; ++i)
    c.require(std::abs(K(i, i) - omega2(i)) <= 1e-6 * omega2.maxCoeff(), m0_path(&Sid::Ke),
              "diagonal entry " + std::to_string(i) + " is " + std::to_string(K(i, i)) + ", but " + refmod::frequencies_hz.at() +
                  " gives (2 pi f)^2 = " + std::to_string(omega2(i)));
}

/// Checks that the members of a list group have distinct names usable in a path, then each member.
template <class Member, class CheckMember>
void check_list(const Checker& c, const Item& list, const std::vector<Member>& members, CheckMember check_member) {
  std::set<std::string> seen;
  for (const Member& m : members) {
    c.require(!m.name.empty() && m.name.find('/') == std::string::npos, list.at(), "invalid name '" + m.name + "'");
    c.require(seen.insert(m.name).second, list.at(), "duplicate name '" + m.name + "'");
    check_member(m);
  }
}

void check_nodes(const Checker& c, const Sid& sid) {
  const Sizes sizes(sid.nq(), sid.dim());
  check_list(c, node::list, sid.nodes, [&](const Node& n) {
    c.taylor(node::origin, n.name, n.origin, sizes);
    c.shape(node::phi, n.name, n.phi, sizes);
    c.shape(node::psi, n.name, n.psi, sizes);
    c.taylor(node::AP, n.name, n.AP, sizes);
  });
}

void check_master_patches(const Checker& c, const Sid& sid) {
  check_list(c, master::list, sid.master_patches, [&](const MasterPatch& m) {
    const std::string degrees = master::degrees.at(m.name);
    c.require(!m.degrees.empty() && m.degrees.size() <= 3, degrees, "needs 1 to 3 parametric directions");
    c.require(m.knots.size() == m.degrees.size(), master::group.at(m.name) + "/knots",
              "one knot vector per direction required");
    Index ncp = 1;
    for (std::size_t d = 0; d < m.degrees.size(); ++d) {
      const std::string f = master::knots.at(m.name, std::to_string(d));
      c.finite(f, m.knots[d]);
      c.require(m.degrees[d] >= 1 && m.degrees[d] <= kMaxDegree, degrees, "degree must lie in 1..15");
      for (Index i = 1; i < m.knots[d].size(); ++i)
        c.require(m.knots[d](i) >= m.knots[d](i - 1), f, "knots not non-decreasing at " + std::to_string(i));
      const Index n = m.knots[d].size() - m.degrees[d] - 1;
      c.require(n > m.degrees[d], f, "too few knots for degree " + std::to_string(m.degrees[d]));
      ncp *= n;
    }
    const std::string weights = master::weights.at(m.name);
    c.require(m.weights.size() == ncp, weights, "expected " + std::to_string(ncp) + " weights");
    c.finite(weights, m.weights);
    c.require(m.weights.size() == 0 || m.weights.minCoeff() > 0, weights, "weights must be positive");
    Sizes sizes(sid.nq(), sid.dim());
    sizes.set(Size::ControlPoints, ncp);
    c.shape(master::control_points, m.name, m.control_points, sizes);
    c.shape(master::Phi, m.name, m.Phi, sizes);
  });
}

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", v);
  return text;
}

/// Every point lies on the contact surface's side of the body's patch: its normal parameter
/// is the same for all points, its tangential ones inside the master patch (the side itself).
void check_points_on_side(const Checker& c, const Sid& sid, const ContactSurface& s) {
  const std::string parameter = contact::parameter.at(s.name);
  const int pd = sid.dim();  // bodies are volume-parametrized: one parameter per spatial direction
  c.require(s.parameter.cols() == pd, parameter, "expected " + std::to_string(pd) + " columns (one per parametric direction)");
  const std::optional<PatchSide> side = side_from_name(s.side, pd);
  c.require(side.has_value(), contact::side.at(s.name), "'" + s.side + "' is not a side of the body's patch (xi0, xi1, eta0, ...)");
  const Index d = side->direction;
  // the side's parameter is the knot vector's end value, copied, not computed: equal to round-off
  const double on_side = s.parameter(0, d), tol_side = 1e-12 * std::max(1.0, std::abs(on_side));
  for (Index g = 0; g < s.points(); ++g)
    c.require(std::abs(s.parameter(g, d) - on_side) <= tol_side, parameter,
              "point " + std::to_string(g) + " is not on side " + s.side + ": " + direction_name(int(d)) + " = " +
                  number(s.parameter(g, d)) + ", point 0 has " + number(on_side));
  const MasterPatch* m = find_master_patch(sid, s.master_patch);
  if (!m) return;
  c.require(int(m->knots.size()) == pd - 1, master::degrees.at(m->name),
            "a side of a " + std::to_string(pd) + "-parameter patch needs " + std::to_string(pd - 1) + " parametric direction(s)");
  for (int t = 0, k = 0; t < pd; ++t) {
    if (t == d) continue;
    const Eigen::VectorXd& U = m->knots[std::size_t(k++)];
    const double lo = U(0), hi = U(U.size() - 1), tol = 1e-9 * (hi - lo);  // Gauss points lie strictly inside
    for (Index g = 0; g < s.points(); ++g)
      c.require(s.parameter(g, t) >= lo - tol && s.parameter(g, t) <= hi + tol, parameter,
                "point " + std::to_string(g) + ": " + direction_name(t) + " = " + number(s.parameter(g, t)) +
                    " outside the side's range [" + number(lo) + ", " + number(hi) + "] (" + master::group.at(m->name) + ")");
  }
}

void check_contact(const Checker& c, const Sid& sid) {
  check_list(c, contact::list, sid.contact_surfaces, [&](const ContactSurface& s) {
    const Index n = s.points();
    const std::string weight = contact::weight.at(s.name), parameter = contact::parameter.at(s.name),
                      element = contact::element.at(s.name);
    c.require(n > 0, weight, "a contact surface needs at least one point");
    c.finite(weight, s.weight);
    c.require(s.weight.minCoeff() > 0, weight, "weights must be positive");
    c.require(s.parameter.rows() == n, parameter, "one row per point expected");
    c.finite(parameter, s.parameter);
    c.require(s.element.size() == n, element, "one entry per point expected");
    c.require(s.element.minCoeff() >= 0, element, "element indices must not be negative");
    const Index elements = sid.discretization ? sid.discretization->elements_per_level.cast<Index>().sum() : 0;
    c.require(elements == 0 || s.element.maxCoeff() < elements, element,
              "element index " + std::to_string(s.element.maxCoeff()) + " beyond the body's " + std::to_string(elements) +
                  " elements (" + discretization::elements_per_level.at() + ")");
    Sizes sizes(sid.nq(), sid.dim());
    sizes.set(Size::Points, n);
    c.shape(contact::position, s.name, s.position, sizes);
    c.shape(contact::normal, s.name, s.normal, sizes);
    for (Index g = 0; g < n; ++g)
      c.require(std::abs(s.normal.row(g).norm() - 1.0) < 1e-8, contact::normal.at(s.name),
                "not a unit vector at " + std::to_string(g));
    c.shape(contact::Psi, s.name, s.Psi, sizes);
    if (s.in_interface.size() > 0) {
      const std::string flags = contact::in_interface.at(s.name);
      c.require(s.in_interface.size() == n, flags, "one entry per point expected");
      c.require((s.in_interface.array() == 0 || s.in_interface.array() == 1).all(), flags, "entries must be 0 or 1");
    }
    if (!s.master_patch.empty())
      c.require(find_master_patch(sid, s.master_patch) != nullptr, contact::group.at(s.name),
                "names master patch '" + s.master_patch + "', which is not in " + master::list.at());
    check_points_on_side(c, sid, s);
  });
}

void check_stress(const Checker& c, const Sid& sid) {
  check_list(c, stress::list, sid.stress_recovery, [&](const StressRecovery& s) {
    const std::string position = stress::position.at(s.name);
    c.require(!s.components.empty(), stress::components.at(s.name), "no stress components");
    c.require(s.position.cols() == sid.dim(), position, "expected " + std::to_string(sid.dim()) + " columns");
    c.finite(position, s.position);
    Sizes sizes(sid.nq(), sid.dim());
    sizes.set(Size::Points, s.position.rows()).set(Size::Components, Index(s.components.size()));
    c.shape(stress::S, s.name, s.S, sizes);
  });
}

/// The patches of a multi-patch body: materials, interfaces naming a side and another patch's
/// side, and the patch each contact surface and stress line names.
void check_patches(const Checker& c, const Sid& sid) {
  auto known = [&](const std::string& name) {
    return std::any_of(sid.patches.begin(), sid.patches.end(), [&](const PatchInfo& p) { return p.name == name; });
  };
  check_list(c, patches::list, sid.patches, [&](const PatchInfo& p) {
    check_material(c, p.material, patches::youngs_modulus.at(p.name), patches::poisson_ratio.at(p.name), patches::density.at(p.name));
    for (const std::string& i : p.interfaces) {
      const std::size_t space = i.find(' '), dot = i.find('.', space == std::string::npos ? 0 : space);
      const bool ok = space != std::string::npos && dot != std::string::npos && side_from_name(i.substr(0, space), sid.dim()) &&
                      known(i.substr(space + 1, dot - space - 1)) && side_from_name(i.substr(dot + 1), sid.dim());
      c.require(ok, patches::interfaces.at(p.name), "'" + i + "' is not `side patch.side` with a patch of /patches");
    }
  });
  auto check_patch = [&](const std::string& patches_named, const std::string& field) {
    std::size_t from = 0;
    while (from < patches_named.size()) {  // space-separated for a surface over several patches
      const std::size_t to = std::min(patches_named.find(' ', from), patches_named.size());
      const std::string patch = patches_named.substr(from, to - from);
      c.require(known(patch), field, "names patch '" + patch + "', which is not in " + patches::list.at());
      from = to + 1;
    }
  };
  for (const ContactSurface& s : sid.contact_surfaces) check_patch(s.patch, contact::patch.at(s.name));
  for (const StressRecovery& s : sid.stress_recovery) check_patch(s.patch, stress::patch.at(s.name));
}

void check_discretization(const Checker& c, const Sid& sid) {
  if (!sid.discretization) return;
  const Discretization& d = *sid.discretization;
  if (d.elements_per_level.size() == 0 || d.elements_per_level.size() != d.functions_per_level.size())
    c.fail(discretization::functions_per_level.at(), "needs one entry per level, as elements_per_level");
  if ((d.elements_per_level.array() < 0).any() || (d.functions_per_level.array() < 0).any() || d.free_dofs < 0)
    c.fail(discretization::group.at(), "negative count");
  if (!(d.contact_radius >= 0) || !std::isfinite(d.contact_radius)) c.fail(discretization::contact_radius.at(), "must be a positive length");
}

void check_transfer(const Checker& c, const Sid& sid) {
  if (!sid.transfer) return;
  const TransferOperator& t = *sid.transfer;
  Sizes sizes(sid.nq(), sid.dim());
  sizes.set(Size::CoarseNq, t.coarse_to_fine.cols());
  c.shape(transfer::coarse_to_fine, {}, t.coarse_to_fine, sizes);
  c.shape(transfer::fine_to_coarse, {}, t.fine_to_coarse, sizes);
}

/// The viewing mesh: cells of 4 or 8 corners naming existing points, rows of the right shapes.
void check_visual(const Checker& c, const Sid& sid) {
  if (!sid.visual) return;
  const VisualMesh& v = *sid.visual;
  const int k = v.corners_per_cell;
  c.require(k == 4 || (k == 8 && sid.dim() == 3), visual::corners_per_cell.at(),
            "must be 4 (quadrilaterals) or, for a 3D body, 8 (hexahedra)");
  c.require(v.position.cols() == sid.dim(), visual::position.at(), "expected " + std::to_string(sid.dim()) + " columns");
  c.finite(visual::position.at(), v.position);
  c.require(v.cells.size() % k == 0, visual::cells.at(), "length is not a multiple of corners_per_cell");
  for (Index i = 0; i < v.cells.size(); ++i)
    c.require(v.cells(i) >= 0 && v.cells(i) < v.points(), visual::cells.at(),
              "entry " + std::to_string(i) + " names point " + std::to_string(v.cells(i)) + " of " + std::to_string(v.points()));
  Sizes sizes(sid.nq(), sid.dim());
  sizes.set(Size::Points, v.points()).set(Size::Components, Index(v.stress_components.size()));
  c.shape(visual::Phi, {}, v.Phi, sizes);
  if (!v.stress_components.empty() || v.S.size() > 0) c.shape(visual::S, {}, v.S, sizes);
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
  check_patches(c, sid);
  check_transfer(c, sid);
  check_discretization(c, sid);
  check_visual(c, sid);
}

}  // namespace isosid::format

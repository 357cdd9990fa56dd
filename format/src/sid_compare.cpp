// SID comparison modulo mode-basis sign and rotation; see sid_compare.hpp.
#include "isosid/format/sid_compare.hpp"

#include "isosid/format/rigid_invariants.hpp"
#include "isosid/format/sid_layout.hpp"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <functional>

namespace isosid::format {
namespace {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;

/// Natural magnitudes of a body's quantities (mass-normalized modes), used as absolute
/// floors so that quantities that vanish up to round-off compare equal.
struct Scales {
  double sqrt_m = 1, L = 1, omega2 = 1, E = 1;
};

Scales natural_scales(const Sid& s) {
  Scales sc;
  const double m = std::max(s.refmod.mass, 1e-300);
  sc.sqrt_m = std::sqrt(m);
  sc.L = std::sqrt(std::max(s.J.M0.trace() / m, 1e-300));
  const double fmax = s.refmod.frequencies_hz.size() ? s.refmod.frequencies_hz.maxCoeff() : 0.0;
  sc.omega2 = std::max(std::pow(2 * M_PI * fmax, 2), 1.0);
  sc.E = std::max(s.material.youngs_modulus, 1.0);
  return sc;
}

class Comparer {
public:
  Comparer(double rtol, Comparison& out) : rtol_(rtol), out_(out) {}

  void values(const std::string& what, const MatrixXd& a, const MatrixXd& b, double floor) {
    if (a.rows() != b.rows() || a.cols() != b.cols()) {
      out_.differences.push_back({what, INFINITY, 0,
                                  "shapes differ: (" + std::to_string(a.rows()) + ", " + std::to_string(a.cols()) +
                                      ") vs (" + std::to_string(b.rows()) + ", " + std::to_string(b.cols()) + ")"});
      return;
    }
    if (a.size() == 0) return;
    const double diff = (a - b).norm();
    const double scale = std::max(a.norm(), b.norm());
    const double tol = rtol_ * std::max(scale, floor);
    if (diff > tol)
      out_.differences.push_back(
          {what, diff, tol, "relative difference " + std::to_string(scale > 0 ? diff / scale : INFINITY)});
  }
  void slices(const std::string& what, const std::vector<MatrixXd>& a, const std::vector<MatrixXd>& b, double floor) {
    if (a.size() != b.size()) {
      same(what + " order", std::to_string(a.empty() ? 0 : 1), std::to_string(b.empty() ? 0 : 1));
      return;
    }
    values(what, stack(a), stack(b), floor);
  }
  void scalar(const std::string& what, double a, double b, double floor) {
    values(what, MatrixXd::Constant(1, 1, a), MatrixXd::Constant(1, 1, b), floor);
  }
  void same(const std::string& what, const std::string& a, const std::string& b) {
    if (a != b) out_.differences.push_back({what, INFINITY, 0, "'" + a + "' vs '" + b + "'"});
  }
  void same(const std::string& what, long long a, long long b) { same(what, std::to_string(a), std::to_string(b)); }

private:
  static MatrixXd stack(const std::vector<MatrixXd>& s) {
    if (s.empty()) return MatrixXd();
    MatrixXd out(s[0].rows() * Index(s.size()), s[0].cols());
    for (std::size_t k = 0; k < s.size(); ++k) out.middleRows(Index(k) * s[0].rows(), s[0].rows()) = s[k];
    return out;
  }
  double rtol_;
  Comparison& out_;
};

// ---- how mode-dependent quantities change under the alignment q_a = Q^T q_b ----------------
// Columns of B's basis combine as Phi_b Q ~ Phi_a, so a quantity indexed by a mode in a
// row (Ct), a column (phi), a column block (Gr) or a Taylor slice (M1) transforms as below.
MatrixXd rows_modal(const MatrixXd& X, const MatrixXd& Q) { return Q.transpose() * X; }
MatrixXd cols_modal(const MatrixXd& X, const MatrixXd& Q) { return X * Q; }
MatrixXd blocks_modal(const MatrixXd& X, const MatrixXd& Q, Index width) {
  MatrixXd out = MatrixXd::Zero(X.rows(), X.cols());
  for (Index k = 0; k < Q.cols(); ++k)
    for (Index j = 0; j < Q.rows(); ++j)
      if (Q(j, k) != 0) out.middleCols(k * width, width) += Q(j, k) * X.middleCols(j * width, width);
  return out;
}
std::vector<MatrixXd> slices_modal(const std::vector<MatrixXd>& X, const MatrixXd& Q,
                                   const std::function<MatrixXd(const MatrixXd&)>& each) {
  std::vector<MatrixXd> out;
  for (Index k = 0; k < Index(X.size()); ++k) {
    MatrixXd sum = MatrixXd::Zero(X[0].rows(), X[0].cols());
    for (Index j = 0; j < Index(X.size()); ++j)
      if (Q(j, k) != 0) sum += Q(j, k) * X[std::size_t(j)];
    out.push_back(each(sum));
  }
  return out;
}

/// Rows of a SID that are linear in one elastic coordinate each: the "mode shapes" by
/// which the two bases are aligned. Each block is divided by max(|reference block|, 1e-6 x its
/// natural scale) so that units (metres, radians, pascals) weigh alike and blocks that vanish
/// up to round-off (Ct and Cr in a Buckens frame) stay negligible instead of being blown up.
MatrixXd mode_rows(const Sid& s, const Sid& reference, const Scales& sc) {
  struct Block {
    MatrixXd rows;
    double weight;
  };
  std::vector<Block> blocks;
  const double inv_sm = 1.0 / sc.sqrt_m;
  auto add = [&](const MatrixXd& x, const MatrixXd& ref, double natural) {
    if (x.size() > 0 && x.rows() == ref.rows() && x.cols() == ref.cols())
      blocks.push_back({x, 1.0 / std::max(ref.norm(), 1e-6 * natural * std::sqrt(double(ref.size())))});
  };
  add(s.Ct.M0.transpose(), reference.Ct.M0.transpose(), sc.sqrt_m);
  add(s.Cr.M0.transpose(), reference.Cr.M0.transpose(), sc.sqrt_m * sc.L);
  add(s.Oe.M0.transpose(), reference.Oe.M0.transpose(), sc.sqrt_m * sc.L);
  for (std::size_t i = 0; i < s.nodes.size() && i < reference.nodes.size(); ++i) {
    add(s.nodes[i].phi, reference.nodes[i].phi, inv_sm);
    add(s.nodes[i].psi, reference.nodes[i].psi, inv_sm / sc.L);
  }
  for (std::size_t i = 0; i < s.contact_surfaces.size() && i < reference.contact_surfaces.size(); ++i)
    add(s.contact_surfaces[i].Psi, reference.contact_surfaces[i].Psi, inv_sm);
  for (std::size_t i = 0; i < s.master_patches.size() && i < reference.master_patches.size(); ++i)
    add(s.master_patches[i].Phi, reference.master_patches[i].Phi, inv_sm);
  for (std::size_t i = 0; i < s.stress_recovery.size() && i < reference.stress_recovery.size(); ++i)
    add(s.stress_recovery[i].S, reference.stress_recovery[i].S, sc.E * inv_sm / sc.L);
  Index rows = 0;
  for (const auto& b : blocks) rows += b.rows.rows();
  MatrixXd Y(rows, s.nq());
  Index r = 0;
  for (const auto& b : blocks) {
    Y.middleRows(r, b.rows.rows()) = b.weight * b.rows;
    r += b.rows.rows();
  }
  return Y;
}

/// Groups modes whose frequencies agree to `tol` (relative): their basis is arbitrary up to rotation.
std::vector<ModeCluster> frequency_clusters(const VectorXd& f, double tol) {
  std::vector<ModeCluster> clusters;
  const double fmax = f.size() ? f.cwiseAbs().maxCoeff() : 0.0;
  for (Index i = 0; i < f.size(); ++i) {
    const bool joins = !clusters.empty() && std::abs(f(i) - f(i - 1)) <= tol * std::max(std::abs(f(i)), 1e-9 * fmax);
    if (joins)
      ++clusters.back().size;
    else
      clusters.push_back({i, 1, 0, true});
  }
  return clusters;
}

MatrixXd column_space(const MatrixXd& Y, double threshold) {
  Eigen::JacobiSVD<MatrixXd> svd(Y, Eigen::ComputeThinU);
  Index rank = 0;
  while (rank < svd.singularValues().size() && svd.singularValues()(rank) > threshold) ++rank;
  return svd.matrixU().leftCols(rank);
}

/// Block-diagonal orthogonal Q with Y_b Q ~ Y_a, one block per frequency cluster.
MatrixXd align_bases(const MatrixXd& Ya, const MatrixXd& Yb, std::vector<ModeCluster>& clusters, double rtol,
                     Comparison& out) {
  const Index nq = Ya.cols();
  MatrixXd Q = MatrixXd::Identity(nq, nq);
  Eigen::JacobiSVD<MatrixXd> whole(Ya);
  const double threshold = 1e-10 * (whole.singularValues().size() ? whole.singularValues()(0) : 1.0);
  for (ModeCluster& c : clusters) {
    const MatrixXd a = Ya.middleCols(c.first, c.size), b = Yb.middleCols(c.first, c.size);
    const MatrixXd Ua = column_space(a, threshold), Ub = column_space(b, threshold);
    const std::string modes = c.size == 1 ? "mode " + std::to_string(c.first)
                                          : "modes " + std::to_string(c.first) + "-" + std::to_string(c.first + c.size - 1);
    if (Ua.cols() != Ub.cols()) {
      out.differences.push_back({"mode subspace of " + modes, INFINITY, 0,
                                 "stored rows span dimension " + std::to_string(Ua.cols()) + " vs " + std::to_string(Ub.cols())});
      continue;
    }
    c.determined = Ua.cols() == c.size;
    if (!c.determined) out.notes.push_back(modes + ": the stored rows do not determine the whole subspace");
    if (Ua.cols() > 0) {
      // sine of the largest principal angle, computed stably as the norm of Ub's part outside span(Ua)
      c.max_sine = std::min(1.0, (Ub - Ua * (Ua.transpose() * Ub)).jacobiSvd().singularValues()(0));
      if (c.max_sine > rtol)
        out.differences.push_back({"mode subspace of " + modes, c.max_sine, rtol, "sine of largest principal angle"});
    }
    Eigen::JacobiSVD<MatrixXd> p(b.transpose() * a, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Q.block(c.first, c.first, c.size, c.size) = p.matrixU() * p.matrixV().transpose();
  }
  return Q;
}

void compare_terms(const Sid& a, const Sid& b, const MatrixXd& Q, const Scales& s, Comparer& cmp) {
  const double sm = s.sqrt_m, L = s.L;
  auto same_rows = [&](const MatrixXd& X) { return rows_modal(X, Q); };
  auto unchanged = [](const MatrixXd& X) { return X; };
  auto congruent = [&](const MatrixXd& X) { return MatrixXd(Q.transpose() * X * Q); };
  struct Rule {
    Taylor Sid::*member;
    std::function<MatrixXd(const MatrixXd&)> m0;
    std::function<MatrixXd(const MatrixXd&)> m1_each;
    double floor0, floor1;
  };
  const std::vector<Rule> rules = {
      {&Sid::mdCM, unchanged, unchanged, sm * L, sm},
      {&Sid::J, unchanged, unchanged, sm * sm * L * L, sm * L},
      {&Sid::Ct, same_rows, same_rows, sm, 1.0},
      {&Sid::Cr, same_rows, same_rows, sm * L, 1.0},
      {&Sid::Me, congruent, congruent, 1.0, 1.0},
      {&Sid::Gr, [&](const MatrixXd& X) { return blocks_modal(X, Q, 3); }, [&](const MatrixXd& X) { return blocks_modal(X, Q, 3); }, sm * L, 1.0},
      {&Sid::Ge, [&](const MatrixXd& X) { return blocks_modal(rows_modal(X, Q), Q, 3); }, unchanged, 1.0, 1.0},
      {&Sid::Oe, same_rows, same_rows, sm * L, 1.0},
      {&Sid::ksigma, same_rows, same_rows, s.omega2 * sm * L, s.omega2},
      {&Sid::Ke, congruent, congruent, s.omega2, s.omega2},
      {&Sid::De, congruent, congruent, std::sqrt(s.omega2), std::sqrt(s.omega2)},
  };
  for (const layout::Term& term : layout::terms()) {
    const Rule& rule = *std::find_if(rules.begin(), rules.end(), [&](const Rule& r) { return r.member == term.member; });
    const Taylor& ta = a.*(term.member);
    const Taylor& tb = b.*(term.member);
    const std::string p = term.item.at();
    cmp.values(p + "/M0", ta.M0, rule.m0(tb.M0), rule.floor0);
    cmp.slices(p + "/M1", ta.M1, tb.M1.empty() ? tb.M1 : slices_modal(tb.M1, Q, rule.m1_each), rule.floor1);
  }
}

void compare_parts(const Sid& a, const Sid& b, const MatrixXd& Q, const Scales& s, Comparer& cmp) {
  const double inv_sm = 1.0 / s.sqrt_m, L = s.L;
  for (std::size_t i = 0; i < a.nodes.size(); ++i) {
    const Node &na = a.nodes[i], &nb = b.nodes[i];
    const std::string p = layout::node::group.at(na.name);
    cmp.values(p + "/origin/M0", na.origin.M0, nb.origin.M0, L);
    cmp.slices(p + "/origin/M1", na.origin.M1, nb.origin.M1.empty() ? nb.origin.M1 : slices_modal(nb.origin.M1, Q, [](const MatrixXd& x) { return x; }), inv_sm);
    cmp.values(p + "/phi", na.phi, cols_modal(nb.phi, Q), inv_sm);
    cmp.values(p + "/psi", na.psi, cols_modal(nb.psi, Q), inv_sm / L);
    cmp.values(p + "/AP/M0", na.AP.M0, nb.AP.M0, 1.0);
    cmp.slices(p + "/AP/M1", na.AP.M1, nb.AP.M1.empty() ? nb.AP.M1 : slices_modal(nb.AP.M1, Q, [](const MatrixXd& x) { return x; }), inv_sm / L);
  }
  for (std::size_t i = 0; i < a.contact_surfaces.size(); ++i) {
    const ContactSurface &ca = a.contact_surfaces[i], &cb = b.contact_surfaces[i];
    const std::string p = layout::contact::group.at(ca.name);
    cmp.values(p + "/parameter", ca.parameter, cb.parameter, 1.0);
    cmp.values(p + "/element", ca.element.cast<double>(), cb.element.cast<double>(), 0.0);
    cmp.values(p + "/position", ca.position, cb.position, L);
    cmp.values(p + "/normal", ca.normal, cb.normal, 1.0);
    cmp.values(p + "/weight", ca.weight, cb.weight, L * L);
    cmp.values(p + "/Psi", ca.Psi, cols_modal(cb.Psi, Q), inv_sm);
    cmp.values(p + "/in_interface", ca.in_interface.cast<double>(), cb.in_interface.cast<double>(), 0.0);
  }
  for (std::size_t i = 0; i < a.master_patches.size(); ++i) {
    const MasterPatch &ma = a.master_patches[i], &mb = b.master_patches[i];
    const std::string p = layout::master::group.at(ma.name);
    cmp.same(p + "/degrees", ma.degrees.size(), mb.degrees.size());
    for (std::size_t d = 0; d < ma.degrees.size() && d < mb.degrees.size(); ++d) {
      cmp.same(p + "/degrees[" + std::to_string(d) + "]", ma.degrees[d], mb.degrees[d]);
      cmp.values(p + "/knots_" + std::to_string(d), ma.knots[d], mb.knots[d], 1.0);
    }
    cmp.values(p + "/weights", ma.weights, mb.weights, 1.0);
    cmp.values(p + "/control_points", ma.control_points, mb.control_points, L);
    cmp.values(p + "/Phi", ma.Phi, cols_modal(mb.Phi, Q), inv_sm);
  }
  for (std::size_t i = 0; i < a.stress_recovery.size(); ++i) {
    const StressRecovery &sa = a.stress_recovery[i], &sb = b.stress_recovery[i];
    const std::string p = layout::stress::group.at(sa.name);
    cmp.same(p + "/components", sa.components.size(), sb.components.size());
    cmp.values(p + "/position", sa.position, sb.position, L);
    cmp.values(p + "/S", sa.S, cols_modal(sb.S, Q), s.E * inv_sm / L);
  }
  if (a.visual && b.visual && a.visual->points() == b.visual->points()) {
    const VisualMesh &va = *a.visual, &vb = *b.visual;
    cmp.values("/visual/position", va.position, vb.position, L);
    cmp.values("/visual/Phi", va.Phi, cols_modal(vb.Phi, Q), inv_sm);
    if (va.S.size() > 0 && va.S.rows() == vb.S.rows()) cmp.values("/visual/S", va.S, cols_modal(vb.S, Q), s.E * inv_sm / L);
  }
  if (a.transfer.has_value() != b.transfer.has_value()) {
    cmp.same("/transfer", a.transfer ? "present" : "absent", b.transfer ? "present" : "absent");
  } else if (a.transfer) {
    cmp.values("/transfer/coarse_to_fine", a.transfer->coarse_to_fine, rows_modal(b.transfer->coarse_to_fine, Q), 1.0);
    cmp.values("/transfer/fine_to_coarse", a.transfer->fine_to_coarse, cols_modal(b.transfer->fine_to_coarse, Q), 1.0);
  }
}

/// Section-translation shares per mode; over a cluster of one frequency their sum (a trace,
/// unchanged by the cluster's rotation between the two files).
void compare_section_translation(const RefMod& a, const RefMod& b, const std::vector<ModeCluster>& clusters, Comparer& cmp) {
  cmp.same("/refmod/section_translation present", a.section_translation.size() ? "yes" : "no",
           b.section_translation.size() ? "yes" : "no");
  if (!a.section_translation.size() || !b.section_translation.size()) return;
  if (a.section_translation.rows() != b.section_translation.rows()) {
    cmp.values("/refmod/section_translation", a.section_translation, b.section_translation, 1.0);  // reports the shapes
    return;
  }
  for (const ModeCluster& c : clusters)
    cmp.values("/refmod/section_translation of mode " + std::to_string(c.first) + (c.size > 1 ? " (cluster of " + std::to_string(c.size) + ")" : ""),
               a.section_translation.middleRows(c.first, c.size).colwise().sum(),
               b.section_translation.middleRows(c.first, c.size).colwise().sum(), 1.0);
  cmp.values("/refmod/long_axis", a.long_axis.cwiseAbs(), b.long_axis.cwiseAbs(), 1.0);  // its sign is arbitrary
}

/// Same names, counts and sizes of the parts; returns false if terms cannot be compared.
bool compare_structure(const Sid& a, const Sid& b, Comparer& cmp, const Comparison& out) {
  const std::size_t before = out.differences.size();
  cmp.same("/body/analysis_type", to_string(a.analysis), to_string(b.analysis));
  cmp.same("/refmod/nq", a.nq(), b.nq());
  cmp.same("/refmod/n_low", a.refmod.n_low, b.refmod.n_low);
  cmp.same("/refmod/reduction_method", a.refmod.reduction_method, b.refmod.reduction_method);
  auto names = [&](const std::string& what, const auto& xa, const auto& xb) {
    std::string la, lb;
    for (const auto& x : xa) la += x.name + " ";
    for (const auto& x : xb) lb += x.name + " ";
    cmp.same(what, la, lb);
  };
  names("/nodes", a.nodes, b.nodes);
  names("/contact", a.contact_surfaces, b.contact_surfaces);
  names("/master", a.master_patches, b.master_patches);
  names("/stress", a.stress_recovery, b.stress_recovery);
  if (out.differences.size() != before) return false;
  for (std::size_t i = 0; i < a.contact_surfaces.size(); ++i)
    cmp.same(layout::contact::group.at(a.contact_surfaces[i].name) + " points", a.contact_surfaces[i].points(),
             b.contact_surfaces[i].points());
  for (std::size_t i = 0; i < a.master_patches.size(); ++i)
    cmp.same(layout::master::group.at(a.master_patches[i].name) + " control points", a.master_patches[i].weights.size(),
             b.master_patches[i].weights.size());
  for (std::size_t i = 0; i < a.stress_recovery.size(); ++i)
    cmp.same(layout::stress::group.at(a.stress_recovery[i].name) + " points", a.stress_recovery[i].position.rows(),
             b.stress_recovery[i].position.rows());
  cmp.same("/visual", a.visual ? "present" : "absent", b.visual ? "present" : "absent");
  if (a.visual && b.visual) {
    cmp.same("/visual points", a.visual->points(), b.visual->points());
    cmp.same("/visual cells", a.visual->cell_count(), b.visual->cell_count());
    cmp.same("/visual/stress_components", a.visual->stress_components.size(), b.visual->stress_components.size());
  }
  return out.differences.size() == before;
}

}  // namespace

Comparison compare_sids(const Sid& a, const Sid& b, double requested_rtol) {
  const double rtol = std::max(requested_rtol, kComparisonRoundOff);
  Comparison out;
  Comparer cmp(rtol, out);
  const Scales s = natural_scales(a);
  const RigidInvariants ia = rigid_invariants(a), ib = rigid_invariants(b);
  cmp.scalar("mass", ia.mass, ib.mass, 0.0);
  cmp.values("center of mass", ia.center_of_mass, ib.center_of_mass, s.L);
  cmp.values("inertia tensor", ia.inertia_origin, ib.inertia_origin, s.sqrt_m * s.sqrt_m * s.L * s.L);
  cmp.scalar("/body/youngs_modulus", a.material.youngs_modulus, b.material.youngs_modulus, 0.0);
  cmp.scalar("/body/poisson_ratio", a.material.poisson_ratio, b.material.poisson_ratio, 1.0);
  cmp.scalar("/body/density", a.material.density, b.material.density, 0.0);
  cmp.scalar("/body/thickness", a.thickness, b.thickness, 0.0);
  for (auto [name, x, y] : {std::tuple{"/damping/alpha1", a.damping.alpha1, b.damping.alpha1},
                            {"/damping/alpha2", a.damping.alpha2, b.damping.alpha2}})
    cmp.scalar(name, x, y, 0.0);
  if (!compare_structure(a, b, cmp, out)) {
    out.notes.push_back("structure differs: mode-dependent terms were not compared");
    return out;
  }
  const VectorXd &fa = a.refmod.frequencies_hz, &fb = b.refmod.frequencies_hz;
  const double fmax = fa.size() ? fa.maxCoeff() : 0.0;
  for (Index i = 0; i < fa.size(); ++i)
    cmp.scalar("frequency of mode " + std::to_string(i), fa(i), fb(i), 1e-6 * fmax);
  out.clusters = frequency_clusters(fa, std::max(rtol, 1e-8));
  const MatrixXd Q = align_bases(mode_rows(a, a, s), mode_rows(b, a, s), out.clusters, rtol, out);
  compare_section_translation(a.refmod, b.refmod, out.clusters, cmp);
  compare_terms(a, b, Q, s, cmp);
  compare_parts(a, b, Q, s, cmp);
  return out;
}

}  // namespace isosid::format

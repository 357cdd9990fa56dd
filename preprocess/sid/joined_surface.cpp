// Contact surfaces over several patch sides; see joined_surface.hpp.
#include "sid/joined_surface.hpp"

#include "sid/contact_data.hpp"
#include "sid/master_patch.hpp"
#include "isosid/format/error.hpp"

namespace isosid::prep {
namespace {

/// Control point index of (i along direction `chain`, j along the other) in a master patch
/// with first direction fastest; n = counts per direction.
Eigen::Index at(const std::vector<Eigen::Index>& n, int chain, Eigen::Index i, Eigen::Index j) {
  if (n.size() == 1) return i;
  return chain == 0 ? i + n[0] * j : j + n[0] * i;
}

std::vector<Eigen::Index> counts(const format::MasterPatch& m) {
  std::vector<Eigen::Index> n;
  for (std::size_t d = 0; d < m.degrees.size(); ++d) n.push_back(basis_count(m.knots[d], m.degrees[d]));
  return n;
}

/// Appends master patch `b` to `a` along direction `chain` (b's first row of control points is
/// a's last). b's chain knots are shifted by `shift` first; its weights are scaled to a's on the
/// shared row (a NURBS is unchanged by scaling all its weights).
format::MasterPatch append(const format::MasterPatch& a, const format::MasterPatch& b, int chain, double shift, int dim) {
  const std::vector<Eigen::Index> na = counts(a), nb = counts(b);
  const int p = a.degrees[std::size_t(chain)];
  format::MasterPatch out = a;
  const Eigen::VectorXd &Ua = a.knots[std::size_t(chain)], Ub = (b.knots[std::size_t(chain)].array() + shift).matrix();
  Eigen::VectorXd U(Ua.size() - 1 + Ub.size() - (p + 1));
  U << Ua.head(Ua.size() - 1), Ub.tail(Ub.size() - (p + 1));
  out.knots[std::size_t(chain)] = U;
  std::vector<Eigen::Index> n = na;
  n[std::size_t(chain)] = na[std::size_t(chain)] + nb[std::size_t(chain)] - 1;
  const Eigen::Index across = n.size() == 1 ? 1 : n[std::size_t(1 - chain)], total = n[0] * (n.size() == 1 ? 1 : n[1]);
  out.weights.resize(total);
  out.control_points.resize(total, a.control_points.cols());
  out.Phi.resize(total * dim, a.Phi.cols());
  const double scale = a.weights(at(na, chain, na[std::size_t(chain)] - 1, 0)) / b.weights(at(nb, chain, 0, 0));
  for (Eigen::Index j = 0; j < across; ++j)
    for (Eigen::Index i = 0; i < n[std::size_t(chain)]; ++i) {
      const bool from_a = i < na[std::size_t(chain)];
      const format::MasterPatch& src = from_a ? a : b;
      const Eigen::Index k = from_a ? at(na, chain, i, j) : at(nb, chain, i - na[std::size_t(chain)] + 1, j), o = at(n, chain, i, j);
      out.weights(o) = from_a ? src.weights(k) : scale * src.weights(k);
      out.control_points.row(o) = src.control_points.row(k);
      out.Phi.middleRows(o * dim, dim) = src.Phi.middleRows(k * dim, dim);
    }
  return out;
}

}  // namespace

JoinedSurface joined_contact_surface(const BodyModel& body, const ContactSurfaceSpec& spec, const Eigen::MatrixXd& Phi_nodal,
                                     const std::vector<int>* interface_dofs) {
  const std::string field = "contact_surface " + spec.name + ".side";
  std::vector<std::pair<int, std::string>> parts{{spec.patch, spec.side}};
  parts.insert(parts.end(), spec.continued.begin(), spec.continued.end());
  const int dim = body.dofs.dim(), pd = body.space.param_dim();
  const PatchSide side = *body.refined[std::size_t(spec.patch)].side(spec.side);
  std::vector<int> tangential;
  for (int d = 0; d < pd; ++d)
    if (d != side.direction) tangential.push_back(d);
  std::vector<format::ContactSurface> surfaces;
  std::vector<format::MasterPatch> masters;
  for (const auto& [patch, name] : parts) {
    ContactSurfaceSpec one = spec;
    one.patch = patch;
    one.side = name;
    one.continued.clear();
    surfaces.push_back(contact_surface(body, one, Phi_nodal, interface_dofs));
    masters.push_back(master_patch(body, spec.name, patch, *body.refined[std::size_t(patch)].side(name), Phi_nodal));
  }
  auto label = [&](std::size_t k) { return body.spec.patches[std::size_t(parts[k].first)].name + "." + parts[k].second; };
  // the direction along which each side continues the one before: its first control-point
  // row is the previous side's last
  const double tol = 1e-10 * body_size(body);
  int chain = -1;
  for (int c = 0; c < int(tangential.size()) && chain < 0; ++c) {
    bool ok = true;
    for (std::size_t k = 1; k < masters.size() && ok; ++k) {
      const auto na = counts(masters[k - 1]), nb = counts(masters[k]);
      const Eigen::Index across = na.size() == 1 ? 1 : na[std::size_t(1 - c)];
      ok = na.size() == 1 || na[std::size_t(1 - c)] == nb[std::size_t(1 - c)];
      for (Eigen::Index j = 0; j < across && ok; ++j)
        ok = (masters[k - 1].control_points.row(at(na, c, na[std::size_t(c)] - 1, j)) - masters[k].control_points.row(at(nb, c, 0, j))).norm() <= tol;
    }
    if (ok) chain = c;
  }
  if (chain < 0)
    throw format::InputError(body.spec.file, field, "the sides do not continue each other in the order given (" + label(0) + " ends where " + label(1) + " begins?)");
  const int d_chain = tangential[std::size_t(chain)];
  JoinedSurface out{surfaces[0], masters[0]};
  double end = body.refined[std::size_t(parts[0].first)].upper(d_chain);
  for (std::size_t k = 1; k < parts.size(); ++k) {
    const NurbsPatch& P = body.refined[std::size_t(parts[k].first)];
    for (int d : tangential)  // the other direction must run over the same range, the side lie at the same parameter
      if (d != d_chain && (std::abs(P.lower(d) - body.refined[std::size_t(parts[0].first)].lower(d)) > 1e-12 ||
                           std::abs(P.upper(d) - body.refined[std::size_t(parts[0].first)].upper(d)) > 1e-12))
        throw format::InputError(body.spec.file, field, label(k) + " runs over another parameter range across the surface than " + label(0));
    if (std::abs(surfaces[k].parameter(0, side.direction) - surfaces[0].parameter(0, side.direction)) > 1e-12)
      throw format::InputError(body.spec.file, field, label(k) + " lies at another parameter than " + label(0) + " (its side's own direction)");
    const double shift = end - P.lower(d_chain);
    format::ContactSurface s = surfaces[k];
    s.parameter.col(d_chain).array() += shift;
    format::ContactSurface& j = out.surface;
    const Eigen::Index n0 = j.points(), n1 = s.points();
    auto stack = [](Eigen::MatrixXd& top, const Eigen::MatrixXd& bottom) {
      top.conservativeResize(top.rows() + bottom.rows(), Eigen::NoChange);
      top.bottomRows(bottom.rows()) = bottom;
    };
    stack(j.parameter, s.parameter);
    stack(j.position, s.position);
    stack(j.normal, s.normal);
    stack(j.Psi, s.Psi);
    j.element.conservativeResize(n0 + n1);
    j.element.tail(n1) = s.element;
    j.weight.conservativeResize(n0 + n1);
    j.weight.tail(n1) = s.weight;
    if (s.in_interface.size() > 0) {
      j.in_interface.conservativeResize(n0 + n1);
      j.in_interface.tail(n1) = s.in_interface;
    }
    out.master = append(out.master, masters[k], chain, shift, dim);
    end += P.upper(d_chain) - P.lower(d_chain);
  }
  return out;
}

}  // namespace isosid::prep

// Penalty contact against a plane; see plane_contact.hpp.
#include "contact/plane_contact.hpp"

#include "isosid/format/error.hpp"

#include <cmath>

namespace isosid::run {

namespace {
const format::ContactSurface& find_surface(const ContactSpec& spec, const FlexibleBody& body) {
  const format::ContactSurface* s = body.contact_surface(spec.surface);
  if (!s) throw format::InputError(spec.name, "surface", "the SID of '" + body.name() + "' has no contact surface '" + spec.surface + "'");
  return *s;
}
}  // namespace

PlaneContact::PlaneContact(const ContactSpec& spec, const FlexibleBody& body, const PlaneSpec& plane)
    : spec_(spec), body_(body), surface_(find_surface(spec, body)), plane_(plane), dim_(body.sid().dim()) {
  if (body.sid().analysis == format::AnalysisType::Axisymmetric && std::abs(std::abs(plane.normal.y()) - 1) > 1e-12)
    throw format::InputError(spec.name, "target", "an axisymmetric body can only touch planes normal to its axis (y)");
}

template <class F>
void PlaneContact::for_each_point(const double* y, F&& f) const {
  const Eigen::Matrix3d A = body_.orientation(y).toRotationMatrix();
  const Eigen::Vector3d r = body_.r(y);
  for (Eigen::Index g = 0; g < surface_.points(); ++g) {
    const auto Psi = surface_.Psi.middleRows(g * dim_, dim_);
    const Eigen::Vector3d P = body_.body_point(surface_.position.row(g).transpose(), Psi, y);
    f(g, Psi, P, plane_.normal.dot(r + A * P - plane_.point), A);
  }
}

Eigen::Vector3d PlaneContact::sliding_velocity(const Eigen::Vector3d& P, const Eigen::Ref<const Eigen::MatrixXd>& Psi,
                                               const double* y) const {
  const Eigen::Vector3d vp = body_.point_velocity(P, Psi, y);
  return vp - plane_.normal.dot(vp) * plane_.normal;
}

Eigen::Vector3d PlaneContact::friction_per_normal_force(const Eigen::Vector3d& vt) const {
  return -spec_.friction * vt / std::sqrt(vt.squaredNorm() + spec_.regularization * spec_.regularization);
}

ContactState PlaneContact::apply(const double* y, GeneralizedForce& f) const {
  ContactState s;
  const Eigen::Vector3d& n = plane_.normal;
  for_each_point(y, [&](Eigen::Index g, const auto& Psi, const Eigen::Vector3d& P, double gap, const Eigen::Matrix3d& A) {
    if (gap >= 0) return;
    const double w = surface_.weight(g);
    const double fn = -spec_.penalty * gap * w;  // > 0
    Eigen::Vector3d F = fn * n;
    if (spec_.friction > 0) {
      const Eigen::Vector3d vt = sliding_velocity(P, Psi, y);
      const Eigen::Vector3d Ft = fn * friction_per_normal_force(vt);
      F += Ft;
      s.friction_power -= Ft.dot(vt);
    }
    body_.apply_force(F, P, Psi, A, f);
    s.force += F;
    ++s.active_points;
    s.max_penetration = std::max(s.max_penetration, -gap);
    s.penalty_energy += 0.5 * spec_.penalty * gap * gap * w;
  });
  return s;
}

void PlaneContact::add_quasistatic_terms(const double* y, Eigen::Index first, Eigen::VectorXd& force,
                                         Eigen::MatrixXd& stiffness) const {
  const Eigen::Vector3d& n = plane_.normal;
  const Eigen::Index nh = body_.nq() - first;
  for_each_point(y, [&](Eigen::Index g, const auto& Psi, const Eigen::Vector3d& P, double gap, const Eigen::Matrix3d& A) {
    if (gap >= 0) return;
    const Eigen::Vector3d nK = A.transpose() * n;
    const double w = surface_.weight(g), fn = -spec_.penalty * gap * w;
    const auto Psi_h = Psi.rightCols(nh);
    const Eigen::RowVectorXd dgap = nK.head(dim_).transpose() * Psi_h;  // d gap / d q_h
    Eigen::Vector3d FK = fn * nK;
    Eigen::VectorXd dF_dgap_K = -spec_.penalty * w * nK.head(dim_);       // d F_K / d gap
    if (spec_.friction > 0) {
      const Eigen::Vector3d dir = friction_per_normal_force(sliding_velocity(P, Psi, y));
      FK += fn * (A.transpose() * dir);
      dF_dgap_K += -spec_.penalty * w * (A.transpose() * dir).head(dim_);
    }
    add_elastic_force(Psi_h, FK, force);
    stiffness.noalias() -= (Psi_h.transpose() * dF_dgap_K) * dgap;
  });
}

double PlaneContact::penalty_energy(const double* y) const {
  double energy = 0;
  for_each_point(y, [&](Eigen::Index g, const auto&, const Eigen::Vector3d&, double gap, const Eigen::Matrix3d&) {
    if (gap < 0) energy += 0.5 * spec_.penalty * gap * gap * surface_.weight(g);
  });
  return energy;
}

double PlaneContact::min_gap(const double* y) const {
  double smallest = INFINITY;
  for_each_point(y, [&](Eigen::Index, const auto&, const Eigen::Vector3d&, double gap, const Eigen::Matrix3d&) {
    smallest = std::min(smallest, gap);
  });
  return smallest;
}

}  // namespace isosid::run

// Projection onto a deformed master patch; see master_patch_target.hpp.
#include "contact/master_patch_target.hpp"

#include "isosid/format/error.hpp"

#include <cmath>

namespace isosid::run {

namespace {
const format::MasterPatch& find_master_patch(const FloatingBody& body, const std::string& surface, const std::string& contact) {
  const format::ContactSurface* s = body.contact_surface(surface);
  if (!s) throw format::InputError(contact, "target_surface", "the SID of '" + body.name() + "' has no contact surface '" + surface + "'");
  for (const format::MasterPatch& m : body.sid().master_patches)
    if (m.name == s->master_patch) return m;
  throw format::InputError(contact, "target_surface", "the SID of '" + body.name() + "' has no master patch '" + s->master_patch + "'");
}
}  // namespace

MasterPatchTarget::MasterPatchTarget(const FloatingBody& body, const std::string& surface, const std::string& contact_name)
    : body_(body), name_(body.name() + "." + surface), dim_(body.sid().dim()), patch_(find_master_patch(body, surface, contact_name), dim_) {
  // orient the normal by the reference geometry: at the middle of the patch it must point
  // away from the centre of mass (true for the convex contact regions this is used on)
  Eigen::Vector2d mid = Eigen::Vector2d::Zero();
  for (int d = 0; d < patch_.parameter_dim(); ++d) mid(d) = 0.5 * (patch_.lower(d) + patch_.upper(d));
  patch_.evaluate(mid, point_);
  const Eigen::Vector3d centroid = body.sid().mdCM.M0.col(0) / body.sid().refmod.mass;
  if (normal(point_, mid).dot(point_.C - centroid) < 0) orientation_ = -1;
}

void MasterPatchTarget::update(const double* y) const {
  A_ = body_.orientation(y).toRotationMatrix();
  r_ = body_.r(y);
  patch_.deform(body_.q(y));
  // the patch lies in the convex hull of its control net, hence in the net's bounding sphere
  const Eigen::MatrixXd& net = patch_.net();
  center_.setZero();
  for (Eigen::Index i = 0; i < net.rows(); ++i) center_.head(dim_) += net.row(i).transpose() / double(net.rows());
  radius_ = 0;
  for (Eigen::Index i = 0; i < net.rows(); ++i) radius_ = std::max(radius_, (net.row(i).transpose() - center_.head(dim_)).norm());
}

double MasterPatchTarget::clearance(const Eigen::Vector3d& center, double radius) const {
  return (center - (r_ + A_ * center_)).norm() - radius - radius_;
}

Eigen::Vector3d MasterPatchTarget::normal(const DeformedPatch::Point& point, const Eigen::Vector2d& u) const {
  // unnormalized: the tangent turned by -90 degrees (curve) or C_u x C_v (surface)
  auto parametric_normal = [&](const DeformedPatch::Point& p) {
    return patch_.parameter_dim() == 1 ? Eigen::Vector3d(p.dC[0].y(), -p.dC[0].x(), 0) : Eigen::Vector3d(p.dC[0].cross(p.dC[1]));
  };
  Eigen::Vector3d n = parametric_normal(point);
  if (n.norm() <= 1e-12 * (point.dC[0].norm() + point.dC[1].norm()) || n.norm() == 0) {
    // a collapsed edge (the pole of a revolved patch): the normal of a point just inside
    DeformedPatch::Point inner;
    Eigen::Vector2d v = u;
    for (int d = 0; d < patch_.parameter_dim(); ++d) v(d) += 1e-7 * (0.5 * (patch_.lower(d) + patch_.upper(d)) - u(d));
    patch_.evaluate(v, inner);
    n = parametric_normal(inner);
  }
  return orientation_ * n.normalized();
}

bool MasterPatchTarget::closest_point(const Eigen::Vector3d& x, Eigen::Vector2d& u) const {
  // minimizes 1/2 |C(u) - x|^2: gradient C_a . (C - x), Hessian C_a . C_b + C_ab . (C - x),
  // falling back to Gauss-Newton where the Hessian is not positive definite
  const int pd = patch_.parameter_dim();
  for (int iteration = 0; iteration < 30; ++iteration) {
    patch_.evaluate(u, point_);
    const Eigen::Vector3d d = point_.C - x;
    Eigen::Matrix2d H = Eigen::Matrix2d::Identity();
    Eigen::Vector2d g = Eigen::Vector2d::Zero();
    for (int a = 0; a < pd; ++a) {
      g(a) = point_.dC[a].dot(d);
      for (int b = 0; b < pd; ++b) H(a, b) = point_.dC[a].dot(point_.dC[b]) + point_.ddC[a + b].dot(d);
    }
    Eigen::Vector2d step = Eigen::Vector2d::Zero();
    if (pd == 1) {
      const double gauss_newton = point_.dC[0].squaredNorm();
      step(0) = -g(0) / (H(0, 0) > 0.1 * gauss_newton ? H(0, 0) : gauss_newton);
    } else {
      Eigen::LLT<Eigen::Matrix2d> llt(H);
      if (llt.info() != Eigen::Success) {
        for (int a = 0; a < 2; ++a)
          for (int b = 0; b < 2; ++b) H(a, b) = point_.dC[a].dot(point_.dC[b]);
        H.diagonal().array() += 1e-14 * H.trace() + 1e-300;
      }
      step = -H.ldlt().solve(g);
    }
    const Eigen::Vector2d before = u;
    for (int a = 0; a < pd; ++a) u(a) = std::clamp(u(a) + step(a), patch_.lower(a), patch_.upper(a));
    // A last step below 1e-9 of the parameter range is taken to first order: the position
    // error is O(step^2) (1e-18 of the patch size), and a warm-started projection costs one
    // evaluation instead of two.
    const Eigen::Vector2d moved = u - before;
    if (moved.cwiseAbs().maxCoeff() <= 1e-9 * (patch_.upper(0) - patch_.lower(0))) {
      for (int a = 0; a < pd; ++a) point_.C += moved(a) * point_.dC[a];
      return true;
    }
  }
  patch_.evaluate(u, point_);
  return false;
}

bool MasterPatchTarget::project(const Eigen::Vector3d& x_world, const double* y, TargetPoint& out, Eigen::Vector2d& hint) const {
  Eigen::Vector3d x = A_.transpose() * (x_world - r_);
  if (dim_ == 2) x.z() = 0;
  if ((x - center_).norm() > radius_) return false;  // outside the bounding sphere: cannot touch
  bool converged = !std::isnan(hint(0)) && closest_point(x, hint);
  if (!converged) {  // no warm start or Newton failed: start from the nearest span midpoint
    double best = INFINITY;
    for (const Eigen::Vector2d& m : patch_.span_midpoints()) {
      patch_.evaluate(m, point_);
      if ((point_.C - x).norm() < best) best = (point_.C - x).norm(), hint = m;
    }
    converged = closest_point(x, hint);
  }
  if (!converged) {
    hint.setConstant(NAN);
    return false;
  }
  const Eigen::Vector3d n = normal(point_, hint);
  const Eigen::Vector3d d = x - point_.C;
  out.gap = n.dot(d);
  // beside the edge of the patch rather than above it: no candidate
  if ((d - out.gap * n).norm() > std::abs(out.gap) + 1e-9 * radius_) return false;
  out.normal = A_ * n;
  if (out.gap >= 0) return true;  // the rest only matters where a force acts
  out.body_point = point_.C;
  patch_.shape_rows(point_, out.Psi);
  out.velocity = body_.point_velocity(point_.C, out.Psi, y);
  return true;
}

}  // namespace isosid::run

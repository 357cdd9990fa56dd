// Projection onto a deformed master patch; see master_patch_target.hpp.
#include "contact/master_patch_target.hpp"

#include "contact/surface_curvature.hpp"

#include "isosid/format/error.hpp"

#include <cmath>

namespace isosid::run {

namespace {
const format::MasterPatch& find_master_patch(const FloatingBody& body, const std::string& surface, const std::string& contact) {
  const format::ContactSurface* s = body.contact_surface(surface);
  if (!s) throw format::InputError(contact, "target_surface", "the SID of '" + body.name() + "' has no contact surface '" + surface + "'");
  if (const format::MasterPatch* m = format::find_master_patch(body.sid(), s->master_patch)) return *m;
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
  patch_.bounding_sphere(center_, radius_);
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

bool MasterPatchTarget::project(const Eigen::Vector3d& x_world, const double* y, TargetPoint& out, Eigen::Vector2d& hint, Fill fill) const {
  Eigen::Vector3d x = A_.transpose() * (x_world - r_);
  if (dim_ == 2) x.z() = 0;
  // outside the bounding sphere a point cannot touch; the touch search also sees points as
  // far again beyond it, whose closest points start its search
  if ((x - center_).norm() > (fill == Fill::Approach ? 2 : 1) * radius_) return false;
  if (!patch_.closest_point(x, hint, point_)) return false;
  const Eigen::Vector3d n = normal(point_, hint);
  const Eigen::Vector3d d = x - point_.C;
  out.gap = n.dot(d);
  // beside the edge of the patch rather than above it: no candidate
  if ((d - out.gap * n).norm() > std::abs(out.gap) + 1e-9 * radius_) return false;
  out.normal = A_ * n;
  if (out.gap < 0 && fill == Fill::Loads) fill_loads(y, out);  // the rest only matters where a force acts
  return true;
}

void MasterPatchTarget::fill_loads(const double* y, TargetPoint& out) const {
  out.body_point = point_.C;
  patch_.shape_rows(point_, out.Psi);
  out.velocity = body_.point_velocity(point_.C, out.Psi, y);
}

bool MasterPatchTarget::carriers(std::vector<int>& control_points, std::vector<double>& basis) const {
  control_points = point_.control_points, basis = point_.R;
  return true;
}

Eigen::Vector2d MasterPatchTarget::curvatures(const Eigen::Vector3d& x_world) const {
  Eigen::Vector3d x = A_.transpose() * (x_world - r_);
  if (dim_ == 2) x.z() = 0;
  Eigen::Vector2d u = Eigen::Vector2d::Constant(NAN);
  if (!patch_.closest_point(x, u, point_)) return Eigen::Vector2d::Constant(NAN);
  patch_.evaluate(u, point_);  // the curvatures need the second derivatives at u itself
  return principal_curvatures(point_, normal(point_, u), patch_.parameter_dim(), body_.sid().analysis == format::AnalysisType::Axisymmetric);
}

}  // namespace isosid::run

// Closest approach of a contact's exact surfaces; see surface_touch.hpp.
#include "contact/surface_touch.hpp"

#include <algorithm>
#include <cmath>

namespace isosid::run {

SurfaceTouch::SurfaceTouch(const SurfaceContact& contact) : contact_(contact), dim_(contact.body().sid().dim()) {
  const format::MasterPatch* patch = format::find_master_patch(contact.body().sid(), contact.surface().master_patch);
  if (!patch) return;
  patch_ = std::make_unique<DeformedPatch>(*patch, dim_);
  const int pd = patch_->parameter_dim();
  for (int a = 0; a < pd; ++a) lower_(a) = patch_->lower(a), upper_(a) = patch_->upper(a);
  // a surface on an interval of one patch side: the search keeps to the elements of its Gauss
  // points (their parameters' box in the side's free directions, in order, widened to the
  // knots around it), as the contact does; beyond lie parts of the side no contact is meant
  // on, poles among them, where normals degenerate
  const format::ContactSurface& s = contact.surface();
  if (const std::vector<Eigen::Index> free = side_parameters(s, pd); !free.empty()) {
    const Eigen::VectorXd lo = s.parameter.colwise().minCoeff(), hi = s.parameter.colwise().maxCoeff();
    for (int a = 0; a < pd; ++a) {
      const Eigen::VectorXd& knots = patch->knots[std::size_t(a)];
      const double first = lo(free[std::size_t(a)]), last = hi(free[std::size_t(a)]);
      for (Eigen::Index k = 0; k < knots.size(); ++k) {
        if (knots(k) <= first) lower_(a) = knots(k);
        if (knots(k) >= last) upper_(a) = std::min(upper_(a), knots(k));
      }
    }
  }
  // the start grid's points per direction in proportion to the surface's lengths along them
  // (about 81 in all, at least 3 per direction): a long band gets cells as long as wide, so
  // that its closest approach lies within half a cell of a grid point
  if (pd < 2) return;
  patch_->deform(Eigen::VectorXd::Zero(contact.body().nq()));
  Eigen::Vector2d length = Eigen::Vector2d::Zero();
  for (int a = 0; a < 2; ++a) {
    Eigen::Vector2d u = 0.5 * (lower_ + upper_);
    Eigen::Vector3d last;
    for (int i = 0; i <= 16; ++i) {
      u(a) = lower_(a) + (upper_(a) - lower_(a)) * i / 16;
      patch_->evaluate(u, point_);
      if (i > 0) length(a) += (point_.C - last).norm();
      last = point_.C;
    }
  }
  if (!(length.minCoeff() > 0)) return;
  const double aspect = std::sqrt(length(0) / length(1));
  grid_ = {std::clamp(int(std::lround(9 * aspect)), 3, 27), std::clamp(int(std::lround(9 / aspect)), 3, 27)};
}

bool SurfaceTouch::distance(const double* y, const Eigen::Vector2d& u, double& gap, Eigen::Vector2d& gradient) const {
  patch_->evaluate(u, point_);
  Eigen::Vector3d x = point_.C;
  if (dim_ == 2) x.z() = 0;
  if (!contact_.target().project(r_ + A_ * x, y, target_point_, target_hint_, ContactTarget::Fill::Approach)) return false;
  gap = target_point_.gap;
  // the signed distance's gradient in space is the target's normal (where it is smooth):
  // along the patch, its product with the tangents
  gradient.setZero();
  for (int a = 0; a < patch_->parameter_dim(); ++a) gradient(a) = target_point_.normal.dot(A_ * point_.dC[a]);
  return true;
}

bool SurfaceTouch::grid_start(const double* y, Eigen::Vector2d& u) const {
  const int pd = patch_->parameter_dim();
  double best = INFINITY, g = 0;
  Eigen::Vector2d gradient;
  u = Eigen::Vector2d::Constant(NAN);
  for (int j = 0; j < (pd > 1 ? grid_[1] : 1); ++j)
    for (int i = 0; i < grid_[0]; ++i) {
      const Eigen::Vector2d c(lower_(0) + (upper_(0) - lower_(0)) * i / (grid_[0] - 1),
                              pd > 1 ? lower_(1) + (upper_(1) - lower_(1)) * j / (grid_[1] - 1) : 0.0);
      if (distance(y, c, g, gradient) && g < best) best = g, u = c;
    }
  return !std::isnan(u(0));
}

double SurfaceTouch::descend(const double* y, Eigen::Vector2d& u, Eigen::Vector2d& gradient) const {
  const int pd = patch_->parameter_dim();
  Eigen::Vector2d range = Eigen::Vector2d::Ones();
  for (int a = 0; a < pd; ++a) range(a) = upper_(a) - lower_(a);
  // Newton on the gradient; its Jacobian exactly against a fixed plane (n . A C_ab), else by
  // central differences of the gradient (the target's curvature enters it, which an analytic
  // Hessian would need per kind of target)
  Eigen::Vector3d plane_normal;
  double plane_offset = 0, gap = INFINITY;
  const bool plane = contact_.target().fixed_plane(plane_normal, plane_offset);
  // the last parameter whose point the target saw: where Newton steps off the target (beside
  // its edge), the closest approach found so far stands instead of no touch at all
  Eigen::Vector2d seen = u;
  for (int iteration = 0; iteration < 50; ++iteration) {
    if (!distance(y, u, gap, gradient)) {
      u = seen;
      break;
    }
    seen = u;
    Eigen::Matrix2d H = Eigen::Matrix2d::Identity();
    bool ok = true;
    for (int a = 0; a < pd && plane; ++a)
      for (int b = 0; b < pd; ++b) H(a, b) = plane_normal.dot(A_ * point_.ddC[a + b]);
    for (int b = 0; b < pd && ok && !plane; ++b) {
      const double h = 1e-6 * range(b);
      Eigen::Vector2d up = u, down = u, g_up, g_down;
      up(b) += h, down(b) -= h;
      double unused = 0;
      ok = distance(y, up, unused, g_up) && distance(y, down, unused, g_down);
      if (ok) H.col(b) = (g_up - g_down) / (2 * h);
    }
    if (!ok) break;
    Eigen::Vector2d step = Eigen::Vector2d::Zero();
    if (pd == 1) {
      // a minimum needs positive curvature; elsewhere a gradient step of a tenth of the range
      step(0) = H(0, 0) > 0 ? -gradient(0) / H(0, 0) : -0.1 * range(0) * (gradient(0) > 0 ? 1 : -1);
    } else {
      H = 0.5 * (H + H.transpose()).eval();
      Eigen::LLT<Eigen::Matrix2d> llt(H);
      step = llt.info() == Eigen::Success ? Eigen::Vector2d(-llt.solve(gradient)) : Eigen::Vector2d(-0.1 * range.cwiseProduct(gradient.normalized()));
    }
    if (!step.allFinite()) break;  // a degenerate point: keep the last finite parameter
    Eigen::Vector2d next = u + step;
    for (int a = 0; a < pd; ++a) next(a) = std::clamp(next(a), lower_(a), upper_(a));
    const bool converged = ((next - u).cwiseQuotient(range)).cwiseAbs().maxCoeff() <= 1e-13;
    u = next;
    if (converged) break;
  }
  return distance(y, u, gap, gradient) ? gap : INFINITY;
}

bool SurfaceTouch::held_by_bound(const Eigen::Vector2d& u, const Eigen::Vector2d& gradient) const {
  for (int a = 0; a < patch_->parameter_dim(); ++a)
    if ((u(a) <= lower_(a) && gradient(a) > 0) || (u(a) >= upper_(a) && gradient(a) < 0)) return true;
  return false;
}

void SurfaceTouch::place(const double* y) const {
  const FloatingBody& body = contact_.body();
  contact_.target().update(y);
  patch_->deform(body.q(y));
  A_ = body.orientation(y).toRotationMatrix();
  r_ = body.r(y);
}

double SurfaceTouch::clearance(const double* y) const {
  if (!patch_) return -INFINITY;
  place(y);
  Eigen::Vector3d center;
  double radius = 0;
  patch_->bounding_sphere(center, radius);
  const double bound = contact_.target().clearance(r_ + A_ * center, radius);
  // a warm start from before a stretch apart can lead Newton to a minimum the real closest
  // approach has left (a touch at 0.9736 s of scene E went unseen that way)
  if (bound > 0) last_parameter_ = Eigen::Vector2d::Constant(NAN);
  return bound;
}

const Touch& SurfaceTouch::evaluate(const double* y) const {
  touch_ = Touch{};
  if (!patch_) return touch_;
  place(y);

  // from the last closest point; from the best point of the start grid where there is none,
  // or where the last one ends held by a bound of the search with the distance still falling
  // beyond it: a minimum the real one may have left (around a body of revolution the two
  // ends of the longitude meet, and the closest approach crosses that seam)
  Eigen::Vector2d u = last_parameter_, gradient, start;
  double gap = INFINITY;
  const bool warm = !std::isnan(u(0)) && distance(y, u, gap, gradient);
  if (warm) gap = descend(y, u, gradient);
  if ((!warm || (std::isfinite(gap) && held_by_bound(u, gradient))) && grid_start(y, start)) {
    Eigen::Vector2d unused;
    const double other = descend(y, start, unused);
    if (other < gap) gap = other, u = start;
  }
  if (!std::isfinite(gap) || !distance(y, u, gap, gradient)) return touch_;  // the target sees none of the surface
  last_parameter_ = u;
  touch_.gap = gap;
  touch_.slave_parameter = u;
  touch_.target_parameter = contact_.target().body() ? target_hint_ : Eigen::Vector2d::Constant(NAN);
  Eigen::Vector3d x = point_.C;
  if (dim_ == 2) x.z() = 0;
  touch_.point = r_ + A_ * x;
  touch_.parameter_dim = patch_->parameter_dim();
  return touch_;
}

}  // namespace isosid::run

// Hertz estimate of an impact; see impact_estimate.hpp.
#include "contact/impact_estimate.hpp"

#include "contact/default_penalty.hpp"
#include "contact/deformed_patch.hpp"
#include "contact/surface_curvature.hpp"
#include "isosid/common/number_text.hpp"

#include <cmath>
#include <functional>
#include <limits>
#include <numbers>

namespace isosid::run {

namespace {

/// Peak line load P (N/m) of a cylinder (radius R) pressed into a flat by the energy per unit
/// length W: the approach delta(P) = P/(pi E*) (2 ln(4R/b) - 1) (Johnson, Contact Mechanics
/// eq. 5.34 for a cylinder on a flat) integrates to W(P) = P^2/(2 pi E*) (ln(4 pi E* R / P) - 3/2),
/// solved by bisection in ln P below the load at which b reaches R.
double line_load(double energy, double R, double modulus) {
  const double C = std::log(4 * std::numbers::pi * modulus * R);
  auto work = [&](double P) { return P * P / (2 * std::numbers::pi * modulus) * (C - 1.5 - std::log(P)); };
  double lo = std::log(1e-12), hi = std::log(std::numbers::pi * modulus * R / 4);
  if (work(std::exp(hi)) < energy) return NAN;  // more than the law covers: no Hertz contact
  for (int i = 0; i < 200 && hi - lo > 1e-12; ++i) {
    const double mid = 0.5 * (lo + hi);
    (work(std::exp(mid)) < energy ? lo : hi) = mid;
  }
  return std::exp(0.5 * (lo + hi));
}

}  // namespace

std::optional<ImpactEstimate> estimate_impact(const SurfaceContact& contact, const double* y) {
  const FloatingBody& body = contact.body();
  const format::Sid& sid = body.sid();
  const format::ContactSurface& surface = contact.surface();
  const ContactTarget& target = contact.target();
  const int dim = sid.dim();
  const bool axisymmetric = sid.analysis == format::AnalysisType::Axisymmetric, line = dim == 2 && !axisymmetric;
  target.update(y);
  const Eigen::Matrix3d A = body.orientation(y).toRotationMatrix();
  const Eigen::VectorXd& q = body.q(y);
  // the slave's contact point nearest the target
  Eigen::Index nearest = -1;
  TargetPoint point, best;
  Eigen::Vector3d P = Eigen::Vector3d::Zero(), best_P = P;
  for (Eigen::Index g = 0; g < surface.points(); ++g) {
    P.head(dim) = surface.position.row(g).transpose() + surface.Psi.middleRows(g * dim, dim) * q;
    Eigen::Vector2d hint = Eigen::Vector2d::Constant(NAN);
    if (!target.project(body.r(y) + A * P, y, point, hint, ContactTarget::Fill::Gap)) continue;
    if (nearest < 0 || point.gap < best.gap) nearest = g, best = point, best_P = P;
  }
  const format::MasterPatch* master = format::find_master_patch(sid, surface.master_patch);
  if (nearest < 0 || !master) return std::nullopt;

  DeformedPatch patch(*master, dim);
  patch.deform(q);
  Eigen::Vector2d u = Eigen::Vector2d::Constant(NAN);
  DeformedPatch::Point on_patch;
  if (!patch.closest_point(best_P, u, on_patch)) return std::nullopt;
  patch.evaluate(u, on_patch);  // the curvatures need the second derivatives at u itself
  // the patch's own normal, turned out of the body (toward the target)
  const Eigen::Vector3d toward = -(A.transpose() * best.normal);
  Eigen::Vector3d outward = patch.parameter_dim() == 1 ? Eigen::Vector3d(on_patch.dC[0].y(), -on_patch.dC[0].x(), 0.0)
                                                       : Eigen::Vector3d(on_patch.dC[0].cross(on_patch.dC[1]));
  outward.normalize();
  if (outward.dot(toward) < 0) outward = -outward;
  Eigen::Vector2d slave = principal_curvatures(on_patch, outward, patch.parameter_dim(), axisymmetric);
  Eigen::Vector2d other = target.curvatures(body.r(y) + A * best_P);
  if (!slave.allFinite() || !other.allFinite()) return std::nullopt;
  if (slave(0) < slave(1)) std::swap(slave(0), slave(1));
  if (other(0) < other(1)) std::swap(other(0), other(1));
  const Eigen::Vector2d relative = slave + other;  // principal directions taken as aligned

  ImpactEstimate e;
  e.gap = best.gap;
  e.line_contact = line;
  const Eigen::MatrixXd Psi = surface.Psi.middleRows(nearest * dim, dim);
  const Eigen::Vector3d v_target = target.body() ? Eigen::Vector3d(target.body()->v(y)) : Eigen::Vector3d::Zero();
  e.approach_speed = -best.normal.dot(body.point_velocity(best_P, Psi, y) - v_target);
  const double m1 = sid.refmod.mass, m2 = target.body() ? target.body()->sid().refmod.mass : INFINITY;
  const double mass = std::isinf(m2) ? m1 : m1 * m2 / (m1 + m2);
  const double modulus = combined_modulus(body, target.body(), surface.patch);
  const auto lengths = contact_element_lengths(surface, sid);
  const auto element = lengths.find(surface.element(nearest));
  if (e.approach_speed <= 0 || !std::isfinite(modulus) || relative(0) <= 0 || (!line && relative(1) <= 0) || element == lengths.end())
    return std::nullopt;
  e.element_size = element->second;
  const double energy = 0.5 * mass * e.approach_speed * e.approach_speed;
  if (line) {
    const double R = 1 / relative(0), P = line_load(energy / sid.thickness, R, modulus);
    if (!std::isfinite(P)) return std::nullopt;
    e.contact_radius = std::sqrt(4 * P * R / (std::numbers::pi * modulus));
    e.peak_force = P * sid.thickness;
    return e;
  }
  // point contact (Johnson, Contact Mechanics 11.2): R the equivalent radius of the relative curvatures
  const double R = 1 / std::sqrt(relative(0) * relative(1));
  e.approach = std::pow(15 * (2 * energy) / (16 * modulus * std::sqrt(R)), 0.4);  // 15 m v^2 / (16 E* sqrt R)
  e.contact_radius = std::sqrt(R * e.approach);
  e.peak_force = 4.0 / 3.0 * modulus * std::sqrt(R) * std::pow(e.approach, 1.5);
  e.contact_time = 2.9432 * e.approach / e.approach_speed;
  return e;
}

std::string closed_at_end_prediction(const SurfaceContact& contact, const ImpactEstimate& e, double t0, double end_time) {
  if (e.contact_time <= 0 || e.approach_speed <= 0) return "";
  const double touch = t0 + std::max(e.gap, 0.0) / e.approach_speed, release = touch + e.contact_time;
  if (touch >= end_time || release <= end_time) return "";
  return "contact '" + contact.name() + "' will likely still be closed at simulation.end_time (" + common::number_text(end_time) +
         " s): at its approach speed it touches at t = " + common::number_text(touch) + " s and the Hertz estimate releases it at " +
         common::number_text(release) + " s; extend end_time";
}

std::string resolution_warning(const SurfaceContact& contact, const ImpactEstimate& e) {
  // 1 % slack: elements sized to exactly a/8 measure a hair either side of it
  if (e.elements_per_radius() >= 0.99 * kConvergedElementsPerContactRadius) return "";
  return "contact '" + contact.name() + "': elements of " + common::number_text(e.element_size) + " m where the impact starts, against an expected Hertz contact " +
         (e.line_contact ? "half-width" : "radius") + " of " + common::number_text(e.contact_radius) + " m (" +
         common::number_text(e.elements_per_radius()) + " per radius; forces converge to 0.3 % from " +
         common::number_text(kConvergedElementsPerContactRadius) + " on): refine the contact of '" + contact.body().name() + "' to " +
         common::number_text(e.contact_radius / kConvergedElementsPerContactRadius) + " m";
}

}  // namespace isosid::run

// Static start of flexible bodies; see static_start.hpp.
#include "solve/static_start.hpp"

#include "isosid/common/dense_decompositions.hpp"
#include "isosid/format/error.hpp"

#include <algorithm>
#include <cmath>

namespace isosid::run {

namespace {

/// The unknowns of one body in the static solve.
struct Unknowns {
  const FloatingBody* body;
  Eigen::Index modes;           ///< its integrated modes if flagged, else 0
  Eigen::Index first;           ///< its first unknown
  Eigen::Index first_equation;  ///< its first acceleration among the equations
};

/// Unknowns per flagged body: its integrated modes, then a translation and a rotation of its
/// frame; a body jointed to one of them (directly or along a chain) moves its frame only, so
/// that the flagged bodies' deflection does not pull the joints apart (a rigid ball hanging
/// from a sagging rod follows it). `n` receives the unknowns' count, `accelerations` the
/// modal equations'.
std::vector<Unknowns> static_unknowns(const MultibodySystem& system, const std::vector<bool>& static_start, Eigen::Index& n,
                                      Eigen::Index& accelerations) {
  std::vector<bool> moves(static_start);
  for (bool grown = true; grown;) {
    grown = false;
    for (const Joint& j : system.joints().joints()) {
      if (!j.side(0).body || !j.side(1).body) continue;
      const std::size_t a = j.side(0).index, b = j.side(1).index;
      if (moves[a] != moves[b]) moves[a] = moves[b] = true, grown = true;
    }
  }
  std::vector<Unknowns> bodies;
  n = 0, accelerations = 0;
  for (std::size_t i = 0; i < system.bodies().size(); ++i) {
    if (!moves[i]) continue;
    const FloatingBody& b = *system.bodies()[i];
    const Eigen::Index modes = static_start[i] ? b.n_dynamic() : 0;
    bodies.push_back({&b, modes, n, accelerations});
    n += modes + 6;
    accelerations += modes;
  }
  return bodies;
}

}  // namespace

void settle_static_start(const MultibodySystem& system, const std::vector<bool>& static_start, double* y) {
  Eigen::Index n = 0, accelerations = 0;
  const std::vector<Unknowns> bodies = static_unknowns(system, static_start, n, accelerations);
  if (accelerations == 0) return;
  std::vector<const Joint*> joints;  // those holding a settled body
  Eigen::Index rows = accelerations;
  for (const Joint& j : system.joints().joints())
    for (const Unknowns& u : bodies)
      if (j.side(0).body == u.body || j.side(1).body == u.body) {
        joints.push_back(&j);
        rows += j.rows();
        break;
      }

  const Eigen::VectorXd y0 = Eigen::Map<const Eigen::VectorXd>(y, system.size());
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n), ydot(system.size());
  // y for the unknowns x: modes replaced, frames moved by x's translation and turned by its
  // rotation vector (world frame) from where they were placed
  auto place = [&](const Eigen::VectorXd& xx) {
    Eigen::Map<Eigen::VectorXd>(y, system.size()) = y0;
    for (const Unknowns& u : bodies) {
      const FloatingBody& b = *u.body;
      const Eigen::Index s = b.offset(), nd = u.modes;
      Eigen::Map<Eigen::VectorXd>(y + s + 7, nd) = xx.segment(u.first, nd);
      Eigen::Map<Eigen::Vector3d>(y + s) += xx.segment<3>(u.first + nd);
      const Eigen::Vector3d turn = xx.segment<3>(u.first + nd + 3);
      const double angle = turn.norm();
      const Eigen::Quaterniond p0(y0(s + 3), y0(s + 4), y0(s + 5), y0(s + 6));
      const Eigen::Quaterniond p = angle > 0 ? Eigen::Quaterniond(Eigen::AngleAxisd(angle, turn / angle)) * p0 : p0;
      y[s + 3] = p.w(), y[s + 4] = p.x(), y[s + 5] = p.y(), y[s + 6] = p.z();
    }
  };
  auto equations = [&](const Eigen::VectorXd& xx, Eigen::VectorXd& out) {
    place(xx);
    system.rhs(0, y, ydot.data());
    out.resize(rows);
    for (const Unknowns& u : bodies) {
      const Eigen::Index nd = u.modes;
      out.segment(u.first_equation, nd) = ydot.segment(u.body->offset() + 13 + nd, nd);
    }
    Eigen::Index at = accelerations;
    for (const Joint* j : joints) out.segment(at, j->rows()) = j->residual(y), at += j->rows();
  };
  // difference steps small against each unknown's scale: a mode's static deflection |qdd| / k
  // (mass-normalized modes: k = omega^2), a nanometre and a nanoradian for the frame
  Eigen::VectorXd F, shifted, scale(n);
  equations(x, F);
  for (const Unknowns& u : bodies) {
    const Eigen::Index nd = u.modes;
    for (Eigen::Index j = 0; j < nd; ++j) scale(u.first + j) = std::max(std::abs(F(u.first_equation + j)) / u.body->sid().Ke.M0(j, j), 1e-300);
    scale.segment<6>(u.first + nd).setConstant(1e-3);  // h = 1e-9 m and rad
  }
  // converged at 1e-10 of the accelerations the solve removes; the residual's own round-off
  // (the modal accelerations are differences of gravity, frame and elastic terms) can sit above
  // that: Newton then stalls with the joints held, and the best iterate, if within 1e-7 of
  // those accelerations, is that floor, not a failure
  const double initial = std::max(F.head(accelerations).cwiseAbs().maxCoeff(), 1e-300);
  const double tolerance = 1e-10 * initial, floor = 1e-7 * initial;
  double best = INFINITY;
  Eigen::VectorXd best_x = x;
  int stalled = 0;
  Eigen::MatrixXd J(rows, n);
  for (int iteration = 0;; ++iteration) {
    const double joint_error = rows > accelerations ? F.tail(rows - accelerations).cwiseAbs().maxCoeff() : 0.0;
    const double residual = F.head(accelerations).cwiseAbs().maxCoeff();
    if (residual <= tolerance && joint_error <= 1e-13) {
      place(x);
      return;
    }
    if (joint_error <= 1e-13) {  // a stall: three iterations in a row that do not halve the best residual
      stalled = residual < 0.5 * best ? 0 : stalled + 1;
      if (residual < best) best = residual, best_x = x;
      if (stalled >= 3) break;
    }
    if (iteration == 20) break;  // 20 updates, the last one checked above
    for (Eigen::Index j = 0; j < n; ++j) {
      Eigen::VectorXd moved = x;
      const double h = 1e-6 * std::max(std::abs(x(j)), scale(j));
      moved(j) += h;
      equations(moved, shifted);
      J.col(j) = (shifted - F) / h;
    }
    // the least change that solves the linearized equations: the frame's free motions (a
    // pendulum's swing) stay as placed
    x += common::minimum_norm_solve(J, -F);
    if (!x.allFinite()) break;
    equations(x, F);
  }
  if (best <= floor) {
    place(best_x);
    return;
  }
  place(Eigen::VectorXd::Zero(n));  // as placed
  throw format::ComputationError("elastic_start = \"static\": Newton's method found no static equilibrium of the flexible bodies "
                                 "at the initial state (accelerations left at " + std::to_string(best / initial) + " of the initial ones)");
}

}  // namespace isosid::run

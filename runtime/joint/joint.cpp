// Joint constraint rows; see joint.hpp.
#include "joint/joint.hpp"

#include "isosid/common/number_text.hpp"
#include "isosid/format/error.hpp"
#include "isosid/format/skew.hpp"

namespace isosid::run {

using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {
/// Accelerations of a body held in a state derivative: v' (world), omega' (body), q''.
struct BodyAccelerations {
  Vector3d a, alpha;
  Eigen::Map<const Eigen::VectorXd> qdd;
};
BodyAccelerations accelerations(const FloatingBody& b, const double* ydot) {
  const double* d = ydot + b.offset() + 7 + b.n_dynamic();
  return {Vector3d(d[0], d[1], d[2]), Vector3d(d[3], d[4], d[5]), Eigen::Map<const Eigen::VectorXd>(d + 6, b.n_dynamic())};
}

/// A unit vector across `axis`, and the one across both.
std::pair<Vector3d, Vector3d> across(const Vector3d& axis) {
  Eigen::Index least = 0;
  axis.cwiseAbs().minCoeff(&least);
  const Vector3d u = axis.cross(Vector3d::Unit(least)).normalized();
  return {u, axis.cross(u)};
}
}  // namespace

Joint::Joint(const JointSpec& spec, const std::vector<std::unique_ptr<FloatingBody>>& bodies, const double* y0,
             const std::string& scene_file)
    : name_(spec.name), kind_(spec.kind) {
  auto fail = [&](const std::string& field, const std::string& problem) {
    throw format::InputError(scene_file, "joint " + name_ + "." + field, problem);
  };
  Vector3d point = spec.point.value_or(Vector3d::Zero());  // a flexible first side sets it below
  auto attach = [&](const std::string& body, const std::string& node, const char* field) {
    JointAttachment a;
    if (body.empty()) {  // the ground, at the joint's point
      a.point = point;
      return a;
    }
    for (std::size_t i = 0; i < bodies.size(); ++i)
      if (bodies[i]->name() == body) a.body = bodies[i].get(), a.index = i;
    const Matrix3d A = a.body->orientation(y0).toRotationMatrix();
    if (node.empty()) {  // a rigid body, at the joint's point
      a.point = A.transpose() * (point - a.body->r(y0));
      a.phi = a.psi = Eigen::MatrixXd::Zero(3, a.body->nq());
      return a;
    }
    const format::Node* n = a.body->node(node);
    if (!n) fail(std::string(field) == "body" ? "node" : "other_node", "the SID of '" + body + "' has no node '" + node + "'");
    a.point = n->origin.M0.col(0);
    a.phi = n->phi;
    a.psi = n->psi;
    // the joint holds the node as the integrated modes move it: quasistatic modes (solved
    // from the contacts alone) neither load it nor move it, see joint.hpp
    const Eigen::Index nqs = a.body->n_quasistatic();
    a.phi.rightCols(nqs).setZero();
    a.psi.rightCols(nqs).setZero();
    return a;
  };
  sides_[0] = attach(spec.body, spec.node, "body");
  if (!spec.point) point = motion(0, y0).x;  // two flexible sides: the joint sits at the first node
  sides_[1] = attach(spec.other, spec.other_node, "other");
  const AttachmentMotion m0 = motion(0, y0), m1 = motion(1, y0);
  for (int s = 0; s < 2; ++s) {
    const double off = (motion(s, y0).x - point).norm();
    if (off > 1e-9 + 1e-7 * point.norm())
      fail(s == 0 ? "node" : "other_node", "the attachment lies " + common::number_text(off) + " m from the joint's point " +
                                               "at t = 0 (bodies and point must meet)");
  }
  if (kind_ == JointSpec::Kind::Revolute) {
    rotation_rows_ = 2;
    sides_[0].axis = m0.R.transpose() * spec.axis;
    sides_[1].axis = m1.R.transpose() * spec.axis;
  } else if (kind_ == JointSpec::Kind::Fixed) {
    rotation_rows_ = 3;
    relative_ = m1.R.transpose() * m0.R;
  }
}

AttachmentMotion Joint::motion(int s, const double* y) const {
  const JointAttachment& a = sides_[std::size_t(s)];
  AttachmentMotion m;
  if (!a.body) {
    m.x = a.point;
    m.v = m.a_known = m.w = m.alpha_known = Vector3d::Zero();
    m.R = Matrix3d::Identity();
    return m;
  }
  const FloatingBody& b = *a.body;
  const Matrix3d A = b.orientation(y).toRotationMatrix();
  const Eigen::VectorXd& q = b.q(y);
  const Eigen::VectorXd& qd = b.qdot(y);
  const Vector3d w = b.omega(y), s_now = a.point + a.phi * q, phi_qd = a.phi * qd, psi_qd = a.psi * qd;
  m.x = b.r(y) + A * s_now;
  m.v = b.v(y) + A * (w.cross(s_now) + phi_qd);
  m.a_known = A * (w.cross(w.cross(s_now)) + 2 * w.cross(phi_qd));
  m.w = A * (w + psi_qd);
  m.alpha_known = A * w.cross(psi_qd);
  m.R = A * (Matrix3d::Identity() + format::skew(a.psi * q));
  return m;
}

JointPose Joint::pose(const double* y) const {
  JointPose p;
  Matrix3d R1 = Matrix3d::Identity();  // side 1's attachment frame (as motion(1, y).R)
  for (int s = 0; s < 2; ++s) {
    const JointAttachment& a = sides_[std::size_t(s)];
    if (!a.body) continue;
    const Eigen::VectorXd& q = a.body->q(y);
    p.A[std::size_t(s)] = a.body->orientation(y).toRotationMatrix();
    p.s_now[std::size_t(s)] = a.point + a.phi * q;
    if (s == 1) R1 = p.A[1] * (Matrix3d::Identity() + format::skew(a.psi * q));
  }
  p.D.resize(3, rows());
  p.D.leftCols<3>().setIdentity();
  if (kind_ == JointSpec::Kind::Revolute) {
    // across side 1's axis, turning with side 1 (so their rate is w1 x D)
    const auto [u, v] = across(sides_[1].axis);
    p.D.col(3) = R1 * u;
    p.D.col(4) = R1 * v;
  } else if (kind_ == JointSpec::Kind::Fixed) {
    p.D.rightCols<3>().setIdentity();
  }
  return p;
}

JointDirections Joint::directions(const double* y) const { return pose(y).D; }

Vector3d Joint::rotation_error(const AttachmentMotion& a, const AttachmentMotion& b) const {
  if (kind_ == JointSpec::Kind::Revolute)  // side 0's axis turned away from side 1's by e (small)
    return (b.R * sides_[1].axis).cross(a.R * sides_[0].axis);
  const Matrix3d E = a.R * (b.R * relative_).transpose();  // side 0 against where it should be
  return 0.5 * Vector3d(E(2, 1) - E(1, 2), E(0, 2) - E(2, 0), E(1, 0) - E(0, 1));
}

JointRows Joint::row_acceleration(int s, const JointPose& pose, const double* delta) const {
  JointRows out = JointRows::Zero(rows());
  const JointAttachment& a = sides_[std::size_t(s)];
  if (!a.body) return out;
  const FloatingBody& b = *a.body;
  const BodyAccelerations acc = accelerations(b, delta);
  const Matrix3d& A = pose.A[std::size_t(s)];
  // the accelerations of the integrated modes only (quasistatic ones are not in the state)
  const Eigen::Index nd = b.n_dynamic();
  out.head<3>() = acc.a + A * (acc.alpha.cross(pose.s_now[std::size_t(s)]) + a.phi.leftCols(nd) * acc.qdd);
  if (rotation_rows_)
    out.tail(rotation_rows_) = pose.D.rightCols(rotation_rows_).transpose() * (A * (acc.alpha + a.psi.leftCols(nd) * acc.qdd));
  return out;
}

JointRows Joint::stabilized_acceleration(const double* y, const JointPose& p, const double* ydot, double rate) const {
  const AttachmentMotion m0 = motion(0, y), m1 = motion(1, y);
  JointRows c = row_acceleration(0, p, ydot) - row_acceleration(1, p, ydot);
  c.head<3>() += m0.a_known - m1.a_known + 2 * rate * (m0.v - m1.v) + rate * rate * (m0.x - m1.x);
  if (rotation_rows_) {
    const auto D = p.D.rightCols(rotation_rows_);
    const Vector3d w_rel = m0.w - m1.w;
    c.tail(rotation_rows_) += D.transpose() * (m0.alpha_known - m1.alpha_known + 2 * rate * w_rel + rate * rate * rotation_error(m0, m1));
    // the directions turn with side 1: d/dt (D^T w_rel) also holds (w1 x D)^T w_rel
    if (kind_ == JointSpec::Kind::Revolute)
      for (Eigen::Index k = 0; k < rotation_rows_; ++k) c(3 + k) += m1.w.cross(D.col(k)).dot(w_rel);
  }
  return c;
}

void Joint::add_load(int s, int row, double amount, const JointPose& pose, GeneralizedForce& f) const {
  const JointAttachment& a = sides_[std::size_t(s)];
  if (!a.body) return;
  const FloatingBody& b = *a.body;
  const double signed_amount = s == 0 ? amount : -amount;
  const Matrix3d& A = pose.A[std::size_t(s)];
  if (row < 3) {
    b.apply_force(signed_amount * Vector3d::Unit(row), pose.s_now[std::size_t(s)], a.phi, A, f);
    return;
  }
  const Vector3d T = A.transpose() * (signed_amount * pose.D.col(row));  // body frame torque
  f.torque += T;
  f.elastic.noalias() += a.psi.transpose() * T;
}

JointRows Joint::residual(const double* y) const {
  const AttachmentMotion m0 = motion(0, y), m1 = motion(1, y);
  JointRows out(rows());
  out.head<3>() = m0.x - m1.x;
  if (rotation_rows_) out.tail(rotation_rows_) = directions(y).rightCols(rotation_rows_).transpose() * rotation_error(m0, m1);
  return out;
}

std::pair<double, double> Joint::errors(const double* y) const {
  const JointRows c = residual(y);
  return {c.head<3>().norm(), c.tail(rotation_rows_).norm()};
}

}  // namespace isosid::run

// Lumped-mass SID terms straight from the body-integral definitions of the SID (docs/references.md
// [R8]; MBSim's fbt_lma), used as an independent reference.
#include "support/lumped_sid.hpp"

#include "isosid/format/skew.hpp"

#include <random>

namespace isosid::test {
namespace {
using Eigen::Index;
using Eigen::Matrix3d;
using Eigen::MatrixXd;
using Eigen::Vector3d;
using Eigen::VectorXd;

MatrixXd random_matrix(Index r, Index c, std::mt19937& gen) {
  std::uniform_real_distribution<double> u(-1, 1);
  MatrixXd m(r, c);
  for (Index j = 0; j < c; ++j)
    for (Index i = 0; i < r; ++i) m(i, j) = u(gen);
  return m;
}
}  // namespace

LumpedBody random_lumped_body(int n, int nq, unsigned seed) {
  std::mt19937 gen(seed);
  LumpedBody b;
  b.points = 0.05 * random_matrix(n, 3, gen);
  b.masses = (random_matrix(n, 1, gen).array().abs() + 0.1).matrix() * 0.01;
  MatrixXd Phi = random_matrix(3 * n, nq, gen);
  // mass-orthonormalize: Phi^T M Phi = I
  VectorXd m3(3 * n);
  for (int i = 0; i < n; ++i) m3.segment<3>(3 * i).setConstant(b.masses(i));
  const MatrixXd Me = Phi.transpose() * m3.asDiagonal() * Phi;
  const Eigen::LLT<MatrixXd> llt(Me);
  b.Phi = llt.matrixL().solve(Phi.transpose()).transpose();  // Phi U^-1, with Me = U^T U
  b.omega.resize(nq);
  for (int k = 0; k < nq; ++k) b.omega(k) = 2 * M_PI * 1000.0 * (1 + k);
  if (nq > 2) b.omega(2) = b.omega(1);  // a repeated pair
  b.Ke = b.omega.array().square().matrix().asDiagonal();
  return b;
}

LumpedBody rotate_modes(const LumpedBody& body, const MatrixXd& Q) {
  LumpedBody b = body;
  b.Phi = body.Phi * Q;
  b.Ke = Q.transpose() * body.Ke * Q;
  return b;
}

format::Sid lumped_sid(const LumpedBody& body) {
  const Index n = body.points.rows(), nq = body.Phi.cols();
  auto c = [&](Index i) -> Vector3d { return body.points.row(i).transpose(); };
  auto phi = [&](Index i, Index k) -> Vector3d { return body.Phi.block(3 * i, k, 3, 1); };

  format::Sid s;
  s.body_name = "lumped";
  s.analysis = format::AnalysisType::Solid;
  s.material = {2.1e11, 0.3, 7850};
  s.refmod.mass = body.masses.sum();
  s.refmod.frequencies_hz = body.omega / (2 * M_PI);
  for (Index k = 0; k < nq; ++k) s.refmod.mode_names.push_back("mode " + std::to_string(k + 1));
  s.refmod.n_low = int(nq);
  s.refmod.reduction_method = "modal";
  s.damping = {1e-3, 900, 5100, 10.0, 1e-8};

  // P(a,b)(j,k) = sum m Phi_{a,j} Phi_{b,k}
  auto P = [&](int a, int bb) {
    MatrixXd out = MatrixXd::Zero(nq, nq);
    for (Index i = 0; i < n; ++i) out += body.masses(i) * body.Phi.row(3 * i + a).transpose() * body.Phi.row(3 * i + bb);
    return out;
  };
  MatrixXd Pab[3][3];
  for (int a = 0; a < 3; ++a)
    for (int bb = 0; bb < 3; ++bb) Pab[a][bb] = P(a, bb);

  s.mdCM.M0 = MatrixXd::Zero(3, 1);
  s.J.M0 = MatrixXd::Zero(3, 3);
  s.mdCM.M1.assign(nq, MatrixXd::Zero(3, 1));
  s.J.M1.assign(nq, MatrixXd::Zero(3, 3));
  s.Ct.M0 = MatrixXd::Zero(nq, 3);
  s.Cr.M0 = MatrixXd::Zero(nq, 3);
  s.Gr.M0 = MatrixXd::Zero(3, 3 * nq);
  s.Gr.M1.assign(nq, MatrixXd::Zero(3, 3 * nq));
  s.Ge.M0 = MatrixXd::Zero(nq, 3 * nq);
  s.Oe.M0 = MatrixXd::Zero(nq, 6);
  s.Oe.M1.assign(nq, MatrixXd::Zero(nq, 6));
  s.Cr.M1.assign(nq, MatrixXd::Zero(nq, 3));
  for (Index i = 0; i < n; ++i) {
    const double m = body.masses(i);
    s.mdCM.M0 += m * c(i);
    s.J.M0 += m * (c(i).squaredNorm() * Matrix3d::Identity() - c(i) * c(i).transpose());
    for (Index k = 0; k < nq; ++k) {
      const Vector3d p = phi(i, k);
      s.mdCM.M1[k] += m * p;
      s.J.M1[k] += m * (2 * c(i).dot(p) * Matrix3d::Identity() - c(i) * p.transpose() - p * c(i).transpose());
      s.Ct.M0.row(k) += m * p.transpose();
      s.Cr.M0.row(k) += m * c(i).cross(p).transpose();
      s.Gr.M0.middleCols(3 * k, 3) += 2 * m * (c(i).dot(p) * Matrix3d::Identity() - p * c(i).transpose());
      const Matrix3d R = m * c(i) * p.transpose();  // R^(k)(a,b) = m c_a phi_b
      s.Oe.M0.row(k) += Eigen::Matrix<double, 1, 6>(-(R(1, 1) + R(2, 2)), -(R(0, 0) + R(2, 2)), -(R(0, 0) + R(1, 1)),
                                                    R(0, 1) + R(1, 0), R(1, 2) + R(2, 1), R(2, 0) + R(0, 2));
      for (Index j = 0; j < nq; ++j) {
        const Vector3d pj = phi(i, j);
        s.Gr.M1[j].middleCols(3 * k, 3) += 2 * m * (pj.dot(p) * Matrix3d::Identity() - p * pj.transpose());
        s.Ge.M0.block(k, 3 * j, 1, 3) += 2 * m * pj.cross(p).transpose();
      }
    }
  }
  for (Index j = 0; j < nq; ++j)
    for (Index k = 0; k < nq; ++k) {
      s.Cr.M1[j](k, 0) = Pab[2][1](k, j) - Pab[1][2](k, j);
      s.Cr.M1[j](k, 1) = Pab[0][2](k, j) - Pab[2][0](k, j);
      s.Cr.M1[j](k, 2) = Pab[1][0](k, j) - Pab[0][1](k, j);
      s.Oe.M1[j].row(k) << -(Pab[1][1](k, j) + Pab[2][2](k, j)), -(Pab[0][0](k, j) + Pab[2][2](k, j)),
          -(Pab[0][0](k, j) + Pab[1][1](k, j)), Pab[0][1](k, j) + Pab[1][0](k, j),
          Pab[1][2](k, j) + Pab[2][1](k, j), Pab[2][0](k, j) + Pab[0][2](k, j);
    }
  VectorXd m3(3 * n);
  for (Index i = 0; i < n; ++i) m3.segment<3>(3 * i).setConstant(body.masses(i));
  s.Me.M0 = body.Phi.transpose() * m3.asDiagonal() * body.Phi;
  s.Me.M0 = 0.5 * (s.Me.M0 + s.Me.M0.transpose()).eval();
  s.Ke.M0 = body.Ke;
  s.De.M0 = s.damping.alpha1 * s.Me.M0 + s.damping.alpha2 * s.Ke.M0;
  s.Ct.M1.clear();
  s.ksigma.M0 = MatrixXd::Zero(nq, 1);

  // a node at point 0 with rotational modes from a fixed linear map of the displacements
  format::Node node;
  node.name = "tip";
  node.origin.M0 = c(0);
  node.phi = body.Phi.topRows(3);
  node.psi = (body.Phi.middleRows(3, 3) - body.Phi.topRows(3)) / 0.05;
  for (Index k = 0; k < nq; ++k) node.origin.M1.push_back(node.phi.col(k));
  node.AP.M0 = Matrix3d::Identity();
  for (Index k = 0; k < nq; ++k) node.AP.M1.push_back(format::skew(node.psi.col(k)));
  s.nodes.push_back(node);

  // contact points: the first four points; master patch: a bilinear 2x2 patch on points 0..3
  format::ContactSurface cs;
  cs.name = "face";
  cs.side = "zeta0";  // the points have zeta = 0
  cs.master_patch = "face";
  const Index np = 4;
  cs.parameter = MatrixXd(np, 3);
  cs.element = Eigen::VectorXi::LinSpaced(np, 0, int(np) - 1);
  cs.position = body.points.topRows(np);
  cs.normal = MatrixXd(np, 3);
  cs.weight = VectorXd(np);
  for (Index g = 0; g < np; ++g) {
    cs.parameter.row(g) << 0.25 * double(g), 0.5, 0.0;
    cs.normal.row(g) = Vector3d(0.1 * double(g), -1, 0.2).normalized().transpose();
    cs.weight(g) = 1e-5 * double(g + 1);
  }
  cs.Psi = body.Phi.topRows(3 * np);
  s.contact_surfaces.push_back(cs);
  format::MasterPatch mp;
  mp.name = "face";
  mp.degrees = {1, 1};
  mp.knots = {(VectorXd(4) << 0, 0, 1, 1).finished(), (VectorXd(4) << 0, 0, 1, 1).finished()};
  mp.weights = VectorXd::Ones(4);
  mp.control_points = body.points.topRows(4);
  mp.Phi = body.Phi.topRows(12);
  s.master_patches.push_back(mp);

  format::StressRecovery st;
  st.name = "axis";
  st.components = {"xx", "yy", "zz", "xy", "yz", "xz"};
  st.position = body.points.topRows(2);
  st.S = 2e11 * body.Phi.topRows(12) / 0.05;
  s.stress_recovery.push_back(st);

  format::TransferOperator t;
  t.coarse_model_sha256 = "0123abcd";
  // any nq x nc and nc x nq maps (nc = nq - 1), taken from Phi's rows cyclically: a body may
  // have more modes than Phi has rows
  t.coarse_to_fine.resize(nq, nq - 1);
  t.fine_to_coarse.resize(nq - 1, nq);
  const Eigen::Index rows = body.Phi.rows();
  for (Eigen::Index i = 0; i < nq; ++i)
    for (Eigen::Index j = 0; j + 1 < nq; ++j) {
      t.coarse_to_fine(i, j) = 3.0 * body.Phi(j % rows, i);
      t.fine_to_coarse(j, i) = 2.0 * body.Phi((nq + j) % rows, i);
    }
  s.transfer = t;

  // the points as a viewing mesh: quadrilaterals of four consecutive points
  format::VisualMesh v;
  v.corners_per_cell = 4;
  v.position = body.points;
  v.cells.resize(4 * (body.points.rows() / 4));
  for (Eigen::Index i = 0; i < v.cells.size(); ++i) v.cells(i) = int(i);
  v.Phi = body.Phi;
  v.stress_components = {"xx", "yy", "zz", "xy", "yz", "xz"};
  v.S.resize(6 * body.points.rows(), nq);
  for (Eigen::Index p = 0; p < body.points.rows(); ++p)
    v.S.middleRows(6 * p, 6) << body.Phi.middleRows(3 * p, 3), -body.Phi.middleRows(3 * p, 3);
  v.S *= 2e11 / 0.05;
  s.visual = v;

  s.provenance = {"lumped.model.toml", "feedbeef", "test", "2026-11-22T00:00:00Z", "isosid-prep lumped.model.toml", {{"assembly", 0.5}, {"eigen", 1.25}}};
  return s;
}

}  // namespace isosid::test

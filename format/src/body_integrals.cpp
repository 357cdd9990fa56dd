// Body integrals from SID terms; see body_integrals.hpp. With R^(k)(a,b) = int c_a Phi_bk dm
// and P_ab(j,k) = int Phi_aj Phi_bk dm, the SID holds (sid-and-ffrf.md section 1):
//   J0 = tr(rrdm) I - rrdm,  Ct0 = Pdm^T,  Me = P_xx + P_yy + P_zz,
//   Cr0 row k = [R_yz - R_zy, R_zx - R_xz, R_xy - R_yx]^(k),
//   Oe0 row k = [-(R_yy + R_zz), -(R_xx + R_zz), -(R_xx + R_yy), R_xy + R_yx, R_yz + R_zy, R_zx + R_xz]^(k),
//   Cr1[j](k, :) = [P_zy - P_yz, P_xz - P_zx, P_yx - P_xy](k, j),  Oe1[j](k, :) likewise with P for R;
// sums and differences give every entry back (Me = P_xx + P_yy + P_zz is then a check).
#include "isosid/format/body_integrals.hpp"

namespace isosid::format {
namespace {

/// A Taylor term's coefficient of q_j as a matrix of the term's shape (zero if order 0).
Eigen::MatrixXd slice(const Taylor& t, Eigen::Index j) {
  return t.M1.empty() ? Eigen::MatrixXd::Zero(t.rows(), t.cols()) : t.M1[std::size_t(j)];
}

/// The 3 x 3 matrix X with X(a,a) from the diagonal combinations d = [-(X_yy + X_zz), -(X_xx +
/// X_zz), -(X_xx + X_yy)], X_ab + X_ba from s = [xy, yz, zx], X_ab - X_ba from the cross
/// combination w = [X_yz - X_zy, X_zx - X_xz, X_xy - X_yx].
Eigen::Matrix3d from_combinations(const double* d, const double* s, const double* w) {
  const double trace = -(d[0] + d[1] + d[2]) / 2;
  Eigen::Matrix3d X;
  X(0, 0) = trace + d[0];
  X(1, 1) = trace + d[1];
  X(2, 2) = trace + d[2];
  X(0, 1) = (s[0] + w[2]) / 2, X(1, 0) = (s[0] - w[2]) / 2;
  X(1, 2) = (s[1] + w[0]) / 2, X(2, 1) = (s[1] - w[0]) / 2;
  X(2, 0) = (s[2] + w[1]) / 2, X(0, 2) = (s[2] - w[1]) / 2;
  return X;
}

}  // namespace

BodyIntegrals body_integrals(const Sid& sid) {
  const Eigen::Index nq = sid.nq();
  BodyIntegrals b;
  b.m = sid.refmod.mass;
  b.rdm = sid.mdCM.M0.col(0);
  const Eigen::Matrix3d J0 = sid.J.M0;
  b.rrdm = 0.5 * J0.trace() * Eigen::Matrix3d::Identity() - J0;
  b.Pdm = sid.Ct.M0.transpose();
  for (auto& r : b.rPdm) r.resize(3, nq);
  for (Eigen::Index k = 0; k < nq; ++k) {
    const Eigen::RowVectorXd oe = sid.Oe.M0.row(k), cr = sid.Cr.M0.row(k);
    const Eigen::Matrix3d R = from_combinations(oe.data(), oe.data() + 3, cr.data());  // R(a,b) = int c_a Phi_bk
    for (int a = 0; a < 3; ++a) b.rPdm[std::size_t(a)].col(k) = R.row(a).transpose();
  }
  for (auto& row : b.PPdm)
    for (auto& p : row) p.resize(nq, nq);
  for (Eigen::Index j = 0; j < nq; ++j) {
    const Eigen::MatrixXd oe = slice(sid.Oe, j), cr = slice(sid.Cr, j);
    for (Eigen::Index k = 0; k < nq; ++k) {
      // Oe1[j](k, :) and Cr1[j](k, :) combine P_ab(k, j); the cross combination there is
      // [P_zy - P_yz, P_xz - P_zx, P_yx - P_xy], the negative of R's order
      const Eigen::RowVectorXd o = oe.row(k), c = -cr.row(k);
      const Eigen::Matrix3d P = from_combinations(o.data(), o.data() + 3, c.data());
      for (int a = 0; a < 3; ++a)
        for (int bb = 0; bb < 3; ++bb) b.PPdm[std::size_t(a)][std::size_t(bb)](k, j) = P(a, bb);
    }
  }
  return b;
}

}  // namespace isosid::format

// Body integrals and SID terms; see sid_terms.hpp.
#include "sid/sid_terms.hpp"

#include "reduce/sparse_products.hpp"
#include "sid/body_integrals.hpp"

#include <array>
#include <cmath>

namespace isosid::prep {

using Eigen::Index;
using Eigen::MatrixXd;

format::Damping rayleigh_damping(double kappa, double f1, double f2) {
  format::Damping d;
  d.kappa = kappa;
  d.f1_hz = f1;
  d.f2_hz = f2;
  d.alpha2 = (f1 + f2) > 0 ? kappa / (M_PI * (f1 + f2)) : 0.0;
  d.alpha1 = 4 * M_PI * M_PI * f1 * f2 * d.alpha2;
  return d;
}

void fill_inertia_terms(format::Sid& sid, const Eigen::SparseMatrix<double>& Ms, const MatrixXd& X, const MatrixXd& Phi_nodal) {
  const Index n = X.rows(), nq = Phi_nodal.cols(), dim = X.cols();
  // the products over the columns that move mass: a massless boundary's trailing columns are
  // zero in this field, and their terms with them (n nq^2 work otherwise, for a boundary of
  // thousands of DOFs the largest part of the SID's preparation)
  const Index used = leading_columns(Phi_nodal);
  // section components of the modes: Phi_c[i] is n x used
  std::vector<MatrixXd> Phi_c(std::size_t(dim), MatrixXd(n, used));
  for (Index node = 0; node < n; ++node)
    for (Index i = 0; i < dim; ++i) Phi_c[std::size_t(i)].row(node) = Phi_nodal.row(node * dim + i).head(used);
  std::vector<MatrixXd> MPhi;
  for (const MatrixXd& p : Phi_c) MPhi.push_back(Ms * p);
  const Eigen::RowVectorXd ones_M = Eigen::RowVectorXd::Ones(n) * Ms;

  const auto pairs = section_pairs(sid.analysis);
  const auto singles = section_singles(sid.analysis);
  const RigidIntegrals rigid = rigid_integrals(Ms, X, sid.analysis);
  sid.refmod.mass = rigid.mass;

  MatrixXd C1 = MatrixXd::Zero(3, nq);                              // int Phi dm
  std::array<std::array<Eigen::RowVectorXd, 3>, 3> R;               // R[a][b](k) = int c_a Phi_bk dm
  std::array<std::array<MatrixXd, 3>, 3> P;                         // P[a][b](j,k) = int Phi_aj Phi_bk dm
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      R[a][b] = Eigen::RowVectorXd::Zero(nq);
      P[a][b] = MatrixXd::Zero(nq, nq);
    }
  for (const SectionSingle& s : singles) C1.row(s.b).head(used) += s.w * ones_M * Phi_c[std::size_t(s.j)];
  for (const SectionPair& p : pairs) {
    R[p.a][p.b].head(used) += p.w * X.col(p.i).transpose() * MPhi[std::size_t(p.j)];
    P[p.a][p.b].topLeftCorner(used, used) += p.w * Phi_c[std::size_t(p.i)].transpose() * MPhi[std::size_t(p.j)];
  }
  auto Rk = [&](Index k) {
    Eigen::Matrix3d r;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) r(a, b) = R[a][b](k);
    return r;
  };
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();

  sid.mdCM.M0 = rigid.first_moment;
  sid.mdCM.M1.assign(std::size_t(nq), MatrixXd(3, 1));
  sid.J.M0 = rigid.inertia();
  sid.J.M1.assign(std::size_t(nq), MatrixXd(3, 3));
  sid.Ct.M0 = C1.transpose();
  sid.Ct.M1.clear();  // no geometric stiffening
  sid.Cr.M0 = MatrixXd(nq, 3);
  sid.Gr.M0 = MatrixXd(3, 3 * nq);
  sid.Oe.M0 = MatrixXd(nq, 6);
  for (Index k = 0; k < nq; ++k) {
    const Eigen::Matrix3d r = Rk(k);
    sid.mdCM.M1[std::size_t(k)] = C1.col(k);
    sid.J.M1[std::size_t(k)] = 2 * r.trace() * I - r - r.transpose();
    sid.Cr.M0.row(k) << r(1, 2) - r(2, 1), r(2, 0) - r(0, 2), r(0, 1) - r(1, 0);
    sid.Gr.M0.middleCols(3 * k, 3) = 2 * (r.trace() * I - r.transpose());
    sid.Oe.M0.row(k) << -(r(1, 1) + r(2, 2)), -(r(0, 0) + r(2, 2)), -(r(0, 0) + r(1, 1)), r(0, 1) + r(1, 0),
        r(1, 2) + r(2, 1), r(2, 0) + r(0, 2);
  }
  sid.Cr.M1.assign(std::size_t(nq), MatrixXd(nq, 3));
  sid.Oe.M1.assign(std::size_t(nq), MatrixXd(nq, 6));
  sid.Gr.M1.assign(std::size_t(nq), MatrixXd(3, 3 * nq));
  sid.Ge.M0 = MatrixXd(nq, 3 * nq);
  for (Index j = 0; j < nq; ++j) {
    MatrixXd& cr = sid.Cr.M1[std::size_t(j)];
    cr.col(0) = P[2][1].col(j) - P[1][2].col(j);
    cr.col(1) = P[0][2].col(j) - P[2][0].col(j);
    cr.col(2) = P[1][0].col(j) - P[0][1].col(j);
    MatrixXd& oe = sid.Oe.M1[std::size_t(j)];
    oe.col(0) = -(P[1][1].col(j) + P[2][2].col(j));
    oe.col(1) = -(P[0][0].col(j) + P[2][2].col(j));
    oe.col(2) = -(P[0][0].col(j) + P[1][1].col(j));
    oe.col(3) = P[0][1].col(j) + P[1][0].col(j);
    oe.col(4) = P[1][2].col(j) + P[2][1].col(j);
    oe.col(5) = P[2][0].col(j) + P[0][2].col(j);
    for (Index k = 0; k < nq; ++k) {
      Eigen::Matrix3d pjk;  // P^(jk)(a,b) = int Phi_aj Phi_bk dm
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) pjk(a, b) = P[a][b](j, k);
      sid.Gr.M1[std::size_t(j)].middleCols(3 * k, 3) = 2 * (pjk.trace() * I - pjk.transpose());
      // Ge(k, block j) = 2 int (Phi_j x Phi_k)^T dm
      sid.Ge.M0.block(k, 3 * j, 1, 3) << 2 * (pjk(1, 2) - pjk(2, 1)), 2 * (pjk(2, 0) - pjk(0, 2)), 2 * (pjk(0, 1) - pjk(1, 0));
    }
  }
  // Taylor parts that vanish identically (e.g. Cr of a body of revolution) are stored as order 0
  for (format::Taylor* t : {&sid.Cr, &sid.Oe, &sid.Gr, &sid.J, &sid.mdCM}) {
    double largest = 0;
    for (const MatrixXd& m : t->M1) largest = std::max(largest, m.cwiseAbs().maxCoeff());
    if (largest == 0) t->M1.clear();
  }
  sid.ksigma.M0 = MatrixXd::Zero(nq, 1);
}

}  // namespace isosid::prep

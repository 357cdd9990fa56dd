// Stiffness and mass integrands; see integrands.hpp.
#include "assemble/integrands.hpp"

namespace isosid::prep {

void StiffnessIntegrand::element_matrix(const ElementPoints& p, Eigen::MatrixXd& local) const {
  const Eigen::MatrixXd& R = p.values.R;
  const Elasticity& elasticity = elasticity_.of_patch(p.patch);
  const int nf = int(R.rows()), n = int(R.cols()), d = elasticity.dim(), nc = elasticity.channel_count();
  // G(q, c*nf + f): channel c of function f at point q
  Eigen::MatrixXd G(n, nf * nc);
  for (int c = 0; c < d; ++c) G.middleCols(c * nf, nf) = p.dR_dx[c].transpose();
  if (nc > d)
    for (int f = 0; f < nf; ++f)
      for (int q = 0; q < n; ++q) G(q, d * nf + f) = Elasticity::hoop(R(f, q), p.dR_dx[0](f, q), p.values.x(0, q));
  const Eigen::MatrixXd weighted = p.weight.asDiagonal() * G;
  const Eigen::MatrixXd channel_products = G.transpose() * weighted;
  // K(f*d + a, g*d + b) = sum over channel pairs of E(c*d + a, c2*d + b) * products(c*nf + f, c2*nf + g)
  const Eigen::MatrixXd& E = elasticity.channel_stiffness();
  const int size = nf * d;
  local.setZero(size, size);
  using Strided = Eigen::Map<Eigen::MatrixXd, 0, Eigen::Stride<Eigen::Dynamic, Eigen::Dynamic>>;
  for (int a = 0; a < d; ++a)
    for (int b = 0; b < d; ++b) {
      Strided block(local.data() + a + Eigen::Index(b) * size, nf, nf,
                    Eigen::Stride<Eigen::Dynamic, Eigen::Dynamic>(Eigen::Index(d) * size, d));
      for (int c = 0; c < nc; ++c)
        for (int c2 = 0; c2 < nc; ++c2) {
          const double e = E(c * d + a, c2 * d + b);
          if (e != 0) block += e * channel_products.block(c * nf, c2 * nf, nf, nf);
        }
    }
}

void MassIntegrand::element_matrix(const ElementPoints& p, Eigen::MatrixXd& local) const {
  const Eigen::MatrixXd weighted = p.values.R * (elasticity_.of_patch(p.patch).density() * p.weight).asDiagonal();
  local.noalias() = weighted * p.values.R.transpose();
}

}  // namespace isosid::prep

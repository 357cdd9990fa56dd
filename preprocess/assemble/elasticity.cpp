// Material matrices and strain operators; see elasticity.hpp.
#include "assemble/elasticity.hpp"

#include <cmath>

namespace isosid::prep {

using format::AnalysisType;

Elasticity::Elasticity(AnalysisType type, const format::Material& material, double thickness)
    : type_(type), material_(material), thickness_(thickness) {
  const double E = material.youngs_modulus, nu = material.poisson_ratio;
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  switch (type) {
    case AnalysisType::PlaneStrain:
      D_ = Eigen::MatrixXd::Zero(3, 3);
      D_ << lambda + 2 * mu, lambda, 0, lambda, lambda + 2 * mu, 0, 0, 0, mu;
      break;
    case AnalysisType::PlaneStress: {
      const double c = E / (1 - nu * nu);
      D_ = Eigen::MatrixXd::Zero(3, 3);
      D_ << c, c * nu, 0, c * nu, c, 0, 0, 0, mu;
      break;
    }
    case AnalysisType::Axisymmetric:
      D_ = Eigen::MatrixXd::Constant(4, 4, 0.0);
      D_.topLeftCorner(3, 3).setConstant(lambda);
      D_.topLeftCorner(3, 3).diagonal().array() += 2 * mu;
      D_(3, 3) = mu;
      break;
    case AnalysisType::Solid:
      D_ = Eigen::MatrixXd::Zero(6, 6);
      D_.topLeftCorner(3, 3).setConstant(lambda);
      D_.topLeftCorner(3, 3).diagonal().array() += 2 * mu;
      D_.bottomRightCorner(3, 3).diagonal().setConstant(mu);
      break;
  }
  // strain rows: channel c (derivative c, or hoop) of displacement component a
  const int d = dim();
  auto set = [&](int strain, int channel, int component) { S_(strain, channel * d + component) = 1.0; };
  switch (type) {
    case AnalysisType::PlaneStrain:
    case AnalysisType::PlaneStress:  // xx yy xy
      S_ = Eigen::MatrixXd::Zero(3, 2 * d);
      set(0, 0, 0); set(1, 1, 1); set(2, 1, 0); set(2, 0, 1);
      break;
    case AnalysisType::Axisymmetric:  // x = r (radial), y = z (axis); rr zz tt rz
      S_ = Eigen::MatrixXd::Zero(4, 3 * d);
      set(0, 0, 0); set(1, 1, 1); set(2, 2, 0); set(3, 1, 0); set(3, 0, 1);
      break;
    case AnalysisType::Solid:  // xx yy zz xy yz xz
      S_ = Eigen::MatrixXd::Zero(6, 3 * d);
      set(0, 0, 0); set(1, 1, 1); set(2, 2, 2); set(3, 1, 0); set(3, 0, 1); set(4, 2, 1); set(4, 1, 2);
      set(5, 2, 0); set(5, 0, 2);
      break;
  }
  E_ = S_.transpose() * D_ * S_;
}

double Elasticity::measure(const Eigen::Ref<const Eigen::VectorXd>& x) const {
  switch (type_) {
    case AnalysisType::PlaneStrain:
    case AnalysisType::PlaneStress: return thickness_;
    case AnalysisType::Axisymmetric: return 2 * M_PI * x(0);
    case AnalysisType::Solid: return 1.0;
  }
  return 1.0;
}

void Elasticity::strain_operator(const Eigen::VectorXd& R, const Eigen::MatrixXd& dR, const Eigen::VectorXd& x,
                                 Eigen::MatrixXd& B) const {
  const int nf = int(R.size()), d = dim(), nc = channel_count();
  B.setZero(strain_count(), nf * d);
  for (int f = 0; f < nf; ++f)
    for (int c = 0; c < nc; ++c) {
      const double channel = c < d ? dR(f, c) : hoop(R(f), dR(f, 0), x(0));
      for (int a = 0; a < d; ++a) B.col(f * d + a) += S_.col(c * d + a) * channel;
    }
}

std::vector<std::string> Elasticity::stress_components() const {
  switch (type_) {
    case AnalysisType::PlaneStrain:
    case AnalysisType::PlaneStress: return {"xx", "yy", "xy"};
    case AnalysisType::Axisymmetric: return {"rr", "zz", "tt", "rz"};
    case AnalysisType::Solid: return {"xx", "yy", "zz", "xy", "yz", "xz"};
  }
  return {};
}

}  // namespace isosid::prep

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
}

double Elasticity::measure(const Eigen::VectorXd& x) const {
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
  const int nf = int(R.size()), d = dim();
  B.setZero(strain_count(), nf * d);
  for (int f = 0; f < nf; ++f) {
    const int c = f * d;
    switch (type_) {
      case AnalysisType::PlaneStrain:
      case AnalysisType::PlaneStress:
        B(0, c) = dR(f, 0);
        B(1, c + 1) = dR(f, 1);
        B(2, c) = dR(f, 1);
        B(2, c + 1) = dR(f, 0);
        break;
      case AnalysisType::Axisymmetric:  // x = r (radial), y = z (axis)
        B(0, c) = dR(f, 0);
        B(1, c + 1) = dR(f, 1);
        // hoop strain u_r / r; on the axis (u_r = 0 there) its limit is du_r/dr
        B(2, c) = x(0) > 0 ? R(f) / x(0) : dR(f, 0);
        B(3, c) = dR(f, 1);
        B(3, c + 1) = dR(f, 0);
        break;
      case AnalysisType::Solid:
        B(0, c) = dR(f, 0);
        B(1, c + 1) = dR(f, 1);
        B(2, c + 2) = dR(f, 2);
        B(3, c) = dR(f, 1);
        B(3, c + 1) = dR(f, 0);
        B(4, c + 1) = dR(f, 2);
        B(4, c + 2) = dR(f, 1);
        B(5, c) = dR(f, 2);
        B(5, c + 2) = dR(f, 0);
        break;
    }
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

// Rigid-body integrals from the scalar mass matrix; see body_integrals.hpp.
#include "sid/body_integrals.hpp"

namespace isosid::prep {

RigidIntegrals rigid_integrals(const Eigen::SparseMatrix<double>& Ms, const Eigen::MatrixXd& P,
                               format::AnalysisType analysis) {
  RigidIntegrals r;
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(P.rows());
  const Eigen::VectorXd m_row = Ms * ones;  // sum_j M_s(i, j)
  r.mass = m_row.sum();
  const Eigen::MatrixXd MP = Ms * P;       // sum_j M_s(i, j) x_j
  const Eigen::VectorXd first = MP.colwise().sum().transpose();
  const Eigen::MatrixXd second = P.transpose() * MP;
  if (analysis == format::AnalysisType::Axisymmetric) {
    // c = (r cos t, y, r sin t): the mean over t of cos^2 and sin^2 is 1/2, of cos, sin and cos sin 0
    r.first_moment = Eigen::Vector3d(0, first(1), 0);
    r.second_moment.diagonal() << 0.5 * second(0, 0), second(1, 1), 0.5 * second(0, 0);
  } else if (P.cols() == 2) {
    r.first_moment.head<2>() = first;
    r.second_moment.topLeftCorner<2, 2>() = second;
  } else {
    r.first_moment = first;
    r.second_moment = second;
  }
  return r;
}

}  // namespace isosid::prep

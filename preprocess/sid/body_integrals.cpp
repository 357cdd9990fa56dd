// Rigid-body integrals from the scalar mass matrix; see body_integrals.hpp.
#include "sid/body_integrals.hpp"

namespace isosid::prep {

std::vector<SectionPair> section_pairs(format::AnalysisType t) {
  if (t == format::AnalysisType::Axisymmetric) return {{0, 0, 0.5, 0, 0}, {2, 2, 0.5, 0, 0}, {1, 1, 1.0, 1, 1}};
  std::vector<SectionPair> p;
  const int d = t == format::AnalysisType::Solid ? 3 : 2;
  for (int a = 0; a < d; ++a)
    for (int b = 0; b < d; ++b) p.push_back({a, b, 1.0, a, b});
  return p;
}

std::vector<SectionSingle> section_singles(format::AnalysisType t) {
  if (t == format::AnalysisType::Axisymmetric) return {{1, 1.0, 1}};
  std::vector<SectionSingle> s;
  const int d = t == format::AnalysisType::Solid ? 3 : 2;
  for (int b = 0; b < d; ++b) s.push_back({b, 1.0, b});
  return s;
}

RigidIntegrals rigid_integrals(const Eigen::SparseMatrix<double>& Ms, const Eigen::MatrixXd& P,
                               format::AnalysisType analysis) {
  RigidIntegrals r;
  const Eigen::RowVectorXd ones_M = Eigen::RowVectorXd::Ones(P.rows()) * Ms;  // row sums of M_s
  const Eigen::MatrixXd MP = Ms * P;
  r.mass = ones_M.sum();
  for (const SectionSingle& s : section_singles(analysis)) r.first_moment(s.b) += s.w * ones_M.dot(P.col(s.j));
  for (const SectionPair& p : section_pairs(analysis)) r.second_moment(p.a, p.b) += p.w * P.col(p.i).dot(MP.col(p.j));
  return r;
}

}  // namespace isosid::prep

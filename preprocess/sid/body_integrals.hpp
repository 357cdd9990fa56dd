// Rigid-body integrals of a body from its scalar consistent mass matrix and node positions:
// m = sum M_s, int c dm = sum M_s(i,j) x_j, int c c^T dm = sum M_s(i,j) x_i x_j^T (exact for
// IGA because the geometry is interpolated by the same partition of unity). Axisymmetric
// sections (x radial, y axial) are revolved about y; planar bodies lie in z = 0.
#pragma once
#include "isosid/format/analysis_type.hpp"

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <vector>

namespace isosid::prep {

struct RigidIntegrals {
  double mass = 0;
  Eigen::Vector3d first_moment = Eigen::Vector3d::Zero();   ///< int c dm, kg m
  Eigen::Matrix3d second_moment = Eigen::Matrix3d::Zero();  ///< int c c^T dm, kg m^2
  /// Inertia tensor about the frame origin: tr(S) I - S.
  Eigen::Matrix3d inertia() const { return second_moment.trace() * Eigen::Matrix3d::Identity() - second_moment; }
};

/// How section components combine into 3D body integrals, for one analysis type:
/// int F_a G_b dm = w F_i^T M_s G_j (pairs) and int G_b dm = w 1^T M_s G_j (singles).
/// Axisymmetric sections: x = r cos t, z = r sin t, so cos^2 and sin^2 average to 1/2 and the
/// x, z parts of single integrals vanish; planar bodies have no z part.
struct SectionPair {
  int a, b;
  double w;
  int i, j;
};
struct SectionSingle {
  int b;
  double w;
  int j;
};
std::vector<SectionPair> section_pairs(format::AnalysisType analysis);
std::vector<SectionSingle> section_singles(format::AnalysisType analysis);

RigidIntegrals rigid_integrals(const Eigen::SparseMatrix<double>& scalar_mass, const Eigen::MatrixXd& node_points,
                               format::AnalysisType analysis);

}  // namespace isosid::prep

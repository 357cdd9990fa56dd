// Rigid-body integrals of a body from its scalar consistent mass matrix and node positions:
// m = sum M_s, int c dm = sum M_s(i,j) x_j, int c c^T dm = sum M_s(i,j) x_i x_j^T (exact for
// IGA because the geometry is interpolated by the same partition of unity). Axisymmetric
// sections (x radial, y axial) are revolved about y; planar bodies lie in z = 0.
#pragma once
#include "isosid/format/analysis_type.hpp"

#include <Eigen/Dense>
#include <Eigen/Sparse>

namespace isosid::prep {

struct RigidIntegrals {
  double mass = 0;
  Eigen::Vector3d first_moment = Eigen::Vector3d::Zero();   ///< int c dm, kg m
  Eigen::Matrix3d second_moment = Eigen::Matrix3d::Zero();  ///< int c c^T dm, kg m^2
  /// Inertia tensor about the frame origin: tr(S) I - S.
  Eigen::Matrix3d inertia() const { return second_moment.trace() * Eigen::Matrix3d::Identity() - second_moment; }
};

RigidIntegrals rigid_integrals(const Eigen::SparseMatrix<double>& scalar_mass, const Eigen::MatrixXd& node_points,
                               format::AnalysisType analysis);

}  // namespace isosid::prep

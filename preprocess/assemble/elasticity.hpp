// Linear elasticity of one analysis type: strain operator B, material matrix D, and the
// measure factor (thickness for planar bodies, 2*pi*r for axisymmetric ones).
#pragma once
#include "isosid/format/analysis_type.hpp"
#include "isosid/format/sid.hpp"

#include <Eigen/Dense>

namespace isosid::prep {

class Elasticity {
public:
  Elasticity(format::AnalysisType type, const format::Material& material, double thickness);

  format::AnalysisType type() const { return type_; }
  int dim() const { return format::spatial_dim(type_); }
  /// Strain components: plane xx yy xy; axisymmetric rr zz tt rz; solid xx yy zz xy yz xz
  /// (engineering shear strains).
  int strain_count() const { return int(D_.rows()); }
  const Eigen::MatrixXd& D() const { return D_; }
  double density() const { return material_.density; }
  /// Integration factor at physical point x (planar: thickness, axisymmetric: 2 pi r, solid: 1).
  double measure(const Eigen::VectorXd& x) const;
  /// Fills B (strain_count x nf*dim) from the functions and their physical gradients at x.
  void strain_operator(const Eigen::VectorXd& R, const Eigen::MatrixXd& dR_dx, const Eigen::VectorXd& x,
                       Eigen::MatrixXd& B) const;
  /// Names of the stress components in the order of D's rows (e.g. "xx").
  std::vector<std::string> stress_components() const;

private:
  format::AnalysisType type_;
  format::Material material_;
  double thickness_;
  Eigen::MatrixXd D_;
};

}  // namespace isosid::prep

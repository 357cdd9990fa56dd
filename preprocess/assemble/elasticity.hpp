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
  double measure(const Eigen::Ref<const Eigen::VectorXd>& x) const;

  /// Every strain is a sum of displacement components times scalar "channels" of a function:
  /// its dim physical derivatives and, when axisymmetric, the hoop factor R/r. Channel c of
  /// component a is column c*dim + a of `strain_of_channels()` (strain_count x channels*dim).
  int channel_count() const { return int(S_.cols()) / dim(); }
  const Eigen::MatrixXd& strain_of_channels() const { return S_; }
  /// S^T D S: the stiffness density between channel-component pairs.
  const Eigen::MatrixXd& channel_stiffness() const { return E_; }
  /// The hoop channel of a function with value R and radial derivative dR_dr at radius r; on
  /// the axis (where u_r = 0) the limit of u_r / r is du_r/dr.
  static double hoop(double R, double dR_dr, double r) { return r > 0 ? R / r : dR_dr; }

  /// Fills B (strain_count x nf*dim) from the functions and their physical gradients at x.
  void strain_operator(const Eigen::VectorXd& R, const Eigen::MatrixXd& dR_dx, const Eigen::VectorXd& x,
                       Eigen::MatrixXd& B) const;
  /// Names of the stress components in the order of D's rows (e.g. "xx").
  std::vector<std::string> stress_components() const;

private:
  format::AnalysisType type_;
  format::Material material_;
  double thickness_;
  Eigen::MatrixXd D_, S_, E_;
};

}  // namespace isosid::prep

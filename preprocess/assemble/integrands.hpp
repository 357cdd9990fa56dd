// Element integrands: each turns the evaluated Gauss points of one element into its local
// matrix; the element loop (element_loop.hpp) does the rest (quadrature, threads, scatter).
#pragma once
#include "assemble/body_elasticity.hpp"
#include "space/element_evaluator.hpp"

#include <Eigen/Dense>
#include <array>

namespace isosid::prep {

/// An element's Gauss points, evaluated and mapped to physical space.
struct ElementPoints {
  ElementValues values;                  ///< R, x and parametric derivatives, one column per point
  std::array<Eigen::MatrixXd, 3> dR_dx;  ///< per physical direction: nf x points
  Eigen::VectorXd weight;                ///< Gauss weight x element size x |det J| x measure factor
  int patch = 0;                         ///< the element's patch: whose material applies
};

class ElementIntegrand {
public:
  virtual ~ElementIntegrand() = default;
  /// Unknowns per function in the local matrix: dim for vector integrands, 1 for scalar ones
  /// (which the loop spreads over the displacement components when assembling on DOFs).
  virtual int components() const = 0;
  /// The local matrix, rows and columns f*components() + a.
  virtual void element_matrix(const ElementPoints& p, Eigen::MatrixXd& local) const = 0;
};

/// Stiffness int B^T D B dV, from the products of the strain channels (elasticity.hpp):
/// one GEMM over all points per element instead of B^T D B per point.
class StiffnessIntegrand : public ElementIntegrand {
public:
  explicit StiffnessIntegrand(const BodyElasticity& elasticity) : elasticity_(elasticity) {}
  int components() const override { return elasticity_.dim(); }
  void element_matrix(const ElementPoints& p, Eigen::MatrixXd& local) const override;

private:
  const BodyElasticity& elasticity_;
};

/// Scalar mass rho int R_i R_j dV (consistent mass on each component, or over nodes).
class MassIntegrand : public ElementIntegrand {
public:
  explicit MassIntegrand(const BodyElasticity& elasticity) : elasticity_(elasticity) {}
  int components() const override { return 1; }
  void element_matrix(const ElementPoints& p, Eigen::MatrixXd& local) const override;

private:
  const BodyElasticity& elasticity_;
};

}  // namespace isosid::prep

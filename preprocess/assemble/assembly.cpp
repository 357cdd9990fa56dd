// Stiffness, mass and load assembly; see assembly.hpp.
#include "assemble/assembly.hpp"

#include "assemble/boundary_quadrature.hpp"
#include "assemble/element_loop.hpp"
#include "isosid/common/progress_line.hpp"
#include "reduce/memory_budget.hpp"

#include <omp.h>

namespace isosid::prep {
namespace {

/// Refuses an element loop whose matrices would not fit: per matrix, a value array per thread
/// (the first is the matrix's own) and the matrix's row indices, beside its pattern's.
void check_element_loop_memory(const std::string& what, std::initializer_list<const ElementPattern*> patterns) {
  double bytes = 0;
  for (const ElementPattern* p : patterns)
    bytes += double(p->non_zeros()) * (double(omp_get_max_threads()) * sizeof(double) + sizeof(SparseMatrix::StorageIndex));
  check_memory("refinement", what, bytes);
}

}  // namespace

SystemMatrices assemble_system(const AnalysisSpace& space, const DofMap& dofs, const BodyElasticity& elasticity,
                               int extra_points) {
  const StiffnessIntegrand stiffness(elasticity);
  const MassIntegrand mass(elasticity);
  common::set_work_step("the matrices' patterns");  // a minute for a million DOFs, before the element loop reports
  const ElementPattern coupled(space, dofs, Unknowns::FreeDofs, Coupling::AllComponents);
  const ElementPattern per_component(space, dofs, Unknowns::FreeDofs, Coupling::SameComponent);
  check_element_loop_memory("the assembly of the stiffness and mass of " + std::to_string(dofs.free_count()) + " DOFs",
                            {&coupled, &per_component});
  common::set_work_step("the element loop");
  std::vector<SparseMatrix> m =
      assemble_matrices(space, elasticity, {{stiffness, coupled}, {mass, per_component}}, extra_points);
  return {std::move(m[0]), std::move(m[1])};
}

SparseMatrix assemble_scalar_mass(const AnalysisSpace& space, const DofMap& dofs, const BodyElasticity& elasticity,
                                  int extra_points) {
  const MassIntegrand mass(elasticity);
  const ElementPattern nodes(space, dofs, Unknowns::Nodes, Coupling::AllComponents);
  check_element_loop_memory("the assembly of the scalar mass of " + std::to_string(dofs.node_count()) + " nodes", {&nodes});
  return std::move(assemble_matrices(space, elasticity, {{mass, nodes}}, extra_points)[0]);
}

Eigen::VectorXd assemble_traction(const AnalysisSpace& space, const DofMap& dofs, const BodyElasticity& elasticity,
                                  int patch, PatchSide side,
                                  const std::function<Eigen::VectorXd(const Eigen::VectorXd&, const Eigen::VectorXd&)>& t) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(dofs.free_count());
  const int dim = dofs.dim();
  std::vector<int> free;
  for (const BoundaryPoint& bp : boundary_points(space, elasticity, patch, side)) {
    const Eigen::VectorXd traction = t(bp.x, bp.normal);
    dofs.element_free_dofs(space.elements[bp.element], free);
    for (int i = 0; i < int(free.size()); ++i)
      if (free[i] >= 0) f(free[i]) += bp.weight * bp.R(i / dim) * traction(i % dim);
  }
  return f;
}

}  // namespace isosid::prep

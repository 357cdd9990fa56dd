// The one element loop of assembly: one reference rule and Bernstein table for the space, each
// element's Gauss points evaluated once and shared by all integrands, element matrices added
// in place into preallocated sparse patterns, elements split over threads.
#pragma once
#include "assemble/element_pattern.hpp"
#include "assemble/integrands.hpp"

#include <vector>

namespace isosid::prep {

/// One global matrix: an integrand assembled on a pattern.
struct MatrixTerm {
  const ElementIntegrand& integrand;
  const ElementPattern& pattern;
};

/// Assembles every term in one pass over the elements with p+1+extra_points Gauss points per
/// direction; the matrices come back in the order of the terms.
std::vector<SparseMatrix> assemble_matrices(const AnalysisSpace& space, const BodyElasticity& elasticity,
                                            const std::vector<MatrixTerm>& terms, int extra_points = 0);

}  // namespace isosid::prep

// A patch must map its parameter box one-to-one onto the body: a self-intersecting (bowtie)
// or inverted patch folds over, its Jacobian determinant changes sign inside, and the
// integrals (which use |det J|) count the folded part twice (a bowtie square weighed half its
// true mass). Poles and collapsed edges lie on the boundary, where det J may vanish.
#pragma once
#include "geometry/nurbs_patch.hpp"

#include <string>

namespace isosid::prep {

/// Throws InputError naming `file` and `field` when det J, sampled at interior points of every
/// knot span (2 (p + 1) per direction), changes sign or falls below 1e-10 of its largest value.
void check_mapping(const NurbsPatch& patch, const std::string& file, const std::string& field);

}  // namespace isosid::prep

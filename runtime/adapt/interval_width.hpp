// The first impact's refined width of an adaptive run ([adaptive] interval_width) against what
// it can do: the region is centred on the touch of a contact surface, and [R2] Alg. 2
// (docs/references.md) widens it by at most half per try.
#pragma once
#include "isosid/format/sid.hpp"
#include "scene/scene.hpp"

#include <vector>

namespace isosid::run {

/// Refuses (InputError naming adaptive.interval_width) a width larger than the contact
/// surface of an adaptive body it refines (its master patch's control net across): such a
/// region refines the whole side, and beyond the patch the whole body. `coarse_sids` are the
/// SIDs of the scene's bodies, in order.
void check_interval_width_fits(const Scene& scene, const std::vector<format::Sid>& coarse_sids);

/// The widest refined region contact `c` can have: the smallest extent (control net across) of
/// the surfaces of adaptive bodies it refines, or infinity if it refines none. Beyond it the
/// preprocessor would refine the whole patch and refuses; Alg. 2's widening stops there.
double widest_interval(const Scene& scene, const std::vector<format::Sid>& coarse_sids, const ContactSpec& c);

/// Refuses a width that the tries of one impact cannot widen to the contact's Hertz width
/// `estimated_width` (m) at its touch: it never holds the contact, and every try is wasted.
void check_interval_width_reaches(const Scene& scene, const std::string& contact, double estimated_width, int tries,
                                  double growth_per_try);

}  // namespace isosid::run

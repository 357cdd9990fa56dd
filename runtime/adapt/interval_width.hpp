// The width of an adaptive run's refined region: [R2] Alg. 2's decision after each try
// (docs/references.md), and the checks of [adaptive] interval_width against what the tries can
// do (the region is centred on the touch of a contact surface and widens by at most half per try).
#pragma once
#include "isosid/format/sid.hpp"
#include "scene/scene.hpp"

#include <string>
#include <vector>

namespace isosid::run {

/// [R2] Sect. 4.2: the contact interval is used best at 70 % (the first impact's width makes the
/// Hertz contact diameter 70 % of it); 50-90 % is acceptable.
constexpr double kTargetUtilization = 0.7, kMinUtilization = 0.5, kMaxUtilization = 0.9;
/// Alg. 2 widens a width by at most this factor per try (and narrows it to half at most).
constexpr double kMaxWidening = 1.5;

/// [R2] Alg. 2: whether an impact's refined region fits its contact, and the width for the
/// next try or the next impact of that contact. `utilization` is the farthest loaded point's
/// distance from the region's centre over half its width (0: nothing was loaded). Over 1 the
/// load reached beyond the region (widen by half); over kMaxUtilization it came within a tenth
/// of its edge, where the edge elements of [R2] are (widen toward the target); under
/// kMinUtilization the region wastes its elements (narrow toward the target); in between the
/// model is acceptable and the width still moves toward the target, by at most half. A touch
/// that loaded nothing (the surfaces grazed) says nothing about the width: acceptable, kept.
struct IntervalDecision {
  bool acceptable = false;
  double next_width = 0;
  std::string reason;
  bool learned = true;  ///< false for a graze: the next impact's width is not learned from it
};
IntervalDecision decide_interval(double utilization, bool beyond, double width);

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

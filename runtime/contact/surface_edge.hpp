// Which Gauss points of a contact surface lie in its edge elements: where the surface (its
// interval, or the patch side) ends and whatever lies beyond is not checked for contact. A
// contact that loads them has outgrown its surface, and its force is cut off at the edge.
#pragma once
#include "isosid/format/sid.hpp"

#include <vector>

namespace isosid::run {

/// Per point of `surface`: 1 if its element is the first or last along a tangential direction
/// of the surface and the surface really ends there, 0 otherwise. Not ends: a pole (a patch
/// side collapsed to a point, or an axisymmetric curve meeting the axis), a seam (the first and
/// last elements meet, as around a body of revolution), and, given the master patch of the
/// whole side (`side_patch`), the end of a one-patch body's side: a corner of the body, where no
/// more of this boundary lies beyond to check (a bar landing flat on its whole side). On a body
/// of several patches the side may go on in the next patch, so its ends stay ends.
std::vector<char> edge_points(const format::ContactSurface& surface, format::AnalysisType analysis,
                              const format::MasterPatch* side_patch = nullptr);

}  // namespace isosid::run

// Where the patches of a body meet. A conforming interface is a side of one patch whose
// control points and weights coincide with a side of another (its directions possibly swapped
// or reversed); the DofMap then merges those control points into shared nodes. Refinement is
// kept conforming by inserting on each side the knots of the other. Sides that touch over an
// area without matching, and patches that overlap, are refused.
#pragma once
#include "model/model_file.hpp"

#include <string>
#include <vector>

namespace isosid::prep {

struct PatchInterface {
  int a = 0, b = 0;                ///< patch indices, a < b
  PatchSide side_a, side_b;
  /// per tangential direction of side_a (ascending): the direction of b it runs along, and
  /// whether it runs the other way
  std::vector<int> b_direction;
  std::vector<bool> reversed;
};

/// The conforming interfaces of the coarse patches. Throws InputError(file) naming the
/// patches and sides of a non-matching interface, the patches that overlap, or two patches
/// the interfaces do not join into one solid.
std::vector<PatchInterface> find_interfaces(const std::vector<PatchSpec>& patches, const std::string& file);

/// The conforming interfaces of the patches of a generated mesh (one patch per element, the
/// mesher's elements conforming by construction): sides are paired through a hash of their
/// end points, then matched as find_interfaces does, in time linear in the elements. No
/// overlap check: the mesher guarantees none.
std::vector<PatchInterface> find_mesh_interfaces(const std::vector<PatchSpec>& patches);

/// Makes the refined patches conform again on every interface: a knot in a tangential
/// direction of one side goes into the matching direction of the other, and the lower degree
/// is raised to the higher; repeated until nothing changes (chains of patches). Finally every
/// patch is raised to the highest degree of each direction (one reference rule per body).
void make_conforming(std::vector<NurbsPatch>& refined, const std::vector<PatchInterface>& interfaces);

}  // namespace isosid::prep

// A rigid body as a floating frame without elastic coordinates: its SID holds only the mass
// and the inertia tensor (frame at the centre of mass, so mdCM = 0), and the floating-frame
// equations reduce to Newton-Euler.
#pragma once
#include "isosid/format/sid.hpp"
#include "body/body_spec.hpp"

namespace isosid::run {

/// The SID of a rigid body (nq = 0) in a scene of the given dimension.
format::Sid rigid_body_sid(const BodySpec& body, Dimension dimension);

}  // namespace isosid::run

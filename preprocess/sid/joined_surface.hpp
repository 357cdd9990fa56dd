// A contact surface over several patch sides of a multi-patch body (`side = ["a.zeta1",
// "b.zeta1"]`): the sides continue each other along one tangential direction, so their Gauss
// points form one surface and their master patches join into one NURBS with a C0 knot where
// two patches meet. Parameters along that direction are laid end to end (patch k's range
// shifted to follow patch k-1's), which keeps every point on one side and inside the joined
// master patch, as the SID validator checks, and lets the runtime project onto it unchanged.
#pragma once
#include "model/body_model.hpp"
#include "isosid/format/sid.hpp"

namespace isosid::prep {

struct JoinedSurface {
  format::ContactSurface surface;
  format::MasterPatch master;
};

/// The surface `spec` over spec.patch/spec.side and spec.continued; InputError(model file) if
/// the sides do not continue each other. interface_dofs: as for contact_surface.
JoinedSurface joined_contact_surface(const BodyModel& body, const ContactSurfaceSpec& spec, const Eigen::MatrixXd& Phi_nodal,
                                     const std::vector<int>* interface_dofs = nullptr);

}  // namespace isosid::prep

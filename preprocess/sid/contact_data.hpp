// Contact data of a SID: Gauss points of a boundary side (optionally a parametric interval
// of it) with positions, outward normals, weights and reduced shape rows Psi = N Phi. The
// side's NURBS for closest-point projection is in master_patch.hpp.
#pragma once
#include "model/body_model.hpp"
#include "isosid/format/sid.hpp"

#include <Eigen/Sparse>
#include <array>
#include <vector>

namespace isosid::prep {

/// Gauss points of the surface (element, parameter, position, normal, weight) without Psi.
format::ContactSurface contact_points(const BodyModel& body, const ContactSurfaceSpec& spec);

/// N (npts*dim x nodal DOFs): displacement at each point from nodal displacements.
Eigen::SparseMatrix<double> contact_shape_rows(const BodyModel& body, const ContactSurfaceSpec& spec);

/// Complete contact surface: points and Psi = N Phi_nodal; with a Craig-Bampton reduction's
/// interface (its free DOFs, possibly none) also which points it covers (ContactSurface::in_interface).
format::ContactSurface contact_surface(const BodyModel& body, const ContactSurfaceSpec& spec, const Eigen::MatrixXd& Phi_nodal,
                                       const std::vector<int>* interface_dofs = nullptr);

}  // namespace isosid::prep

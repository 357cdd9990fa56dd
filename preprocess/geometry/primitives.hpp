// RIGA-style primitives: exact NURBS control nets of the bodies of [R1] (docs/references.md), with
// named sides. 2D bodies lie in the x-y plane; bodies of revolution have x radial and y on the
// axis.
#pragma once
#include "geometry/nurbs_patch.hpp"

namespace isosid::prep::primitives {

/// Half-disk x >= 0 of radius r centred at the origin ([R1] eq. 35-36): p=2, q=1.
/// Sides: axis (xi0), lower (eta0, contact at the bottom pole), upper (eta1); xi1 collapses to (r, 0).
NurbsPatch half_disk(double r);

/// Rod of radius r and length l with a spherical end at y = 0 ([R1] eq. 38): p=2, q=1.
/// Sides: axis (xi0), cap (eta0, contact at the pole), top (eta1), lateral (xi1).
NurbsPatch rod_with_spherical_end(double r, double l);

/// Disk of radius r centred at the origin ([R1] eq. 39-41): p=q=2, one patch.
/// Sides: top (xi0), bottom (xi1, contact at (0, -r)), left (eta0), right (eta1).
NurbsPatch disk(double r);

/// Rectangle [x0, x0+lx] x [y0, y0+ly]: bilinear. Sides: left, right, bottom, top.
NurbsPatch rectangle(double lx, double ly, double x0 = 0, double y0 = 0);

/// Box [0,lx] x [0,ly] x [0,lz] shifted by origin: trilinear.
/// Sides: left/right (x), bottom/top (y), back/front (z).
NurbsPatch box(double lx, double ly, double lz, const Eigen::Vector3d& origin = Eigen::Vector3d::Zero());

/// Quarter annulus between radii ri < ro in the first quadrant: p=2 (angle), q=1 (radius).
/// Sides: x_axis (xi0, y = 0), y_axis (xi1, x = 0), inner (eta0), outer (eta1).
NurbsPatch quarter_annulus(double ri, double ro);

/// Revolves a planar profile (x radial >= 0, y axial) by a full turn about the y axis:
/// the third direction is the 9-point quadratic circle. The axis and the seam are
/// coincident control points, merged into single DOFs by the analysis space.
NurbsPatch revolve_about_y(const NurbsPatch& profile);

/// Ball of radius r (revolved half-disk). Sides: lower (eta0), upper (eta1), axis (xi0).
NurbsPatch ball(double r);

/// Ball of radius r in spherical coordinates: xi the latitude from the pole (0, -r, 0) to
/// (0, r, 0) (the semicircle, three rational arcs of 60 deg; the equator xi = 0.5 lies inside
/// the middle one, where the basis is smooth), eta the radius (linear from the centre), zeta
/// the longitude (x = cos, z = sin). Side: surface (eta1), the whole sphere, singular only at
/// its poles, so every great circle but the meridians avoids its singularities. The centre,
/// the poles, the axis and the seam are coincident control points, merged into single DOFs.
NurbsPatch ball_spherical(double r);

/// Cylinder of radius r along y from 0 to l (revolved rectangle). Sides: bottom (eta0), top (eta1), lateral (xi1).
NurbsPatch cylinder_rod(double r, double l);

}  // namespace isosid::prep::primitives

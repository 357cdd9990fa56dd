// A SID in the formats other multibody tools read (issue 18):
//  - the classic ASCII SID (".SID_FEM", Wallrapp's standard input data) as the open Modelica
//    EMBS library reads it: Taylor blocks with 1-based m0(row, col) and m1(row, q, col)
//    entries, Fortran D exponents, J as 6 x 1 (xx yy zz xy xz yz), nodes numbered 1, 2, ...
//    in the SID's order;
//  - MBSim's flexible FFR body input (HDF5, ExternalFlexibleFfrBody): the volume integrals
//    (body_integrals.hpp), stiffness and damping, and the SID nodes' positions and shapes.
// Both are written atomically. Massless-boundary SIDs are refused (InputError): both tools
// integrate every coordinate with its mass, and their boundary coordinates have none.
#pragma once
#include "isosid/format/sid.hpp"

#include <string>

namespace isosid::format {

void write_sid_fem(const Sid& sid, const std::string& path);
void write_mbsim_h5(const Sid& sid, const std::string& path);

}  // namespace isosid::format

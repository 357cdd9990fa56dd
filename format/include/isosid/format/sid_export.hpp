// A SID in the formats other multibody tools read (docs/references.md [R12]):
//  - the classic ASCII SID (".SID_FEM", Wallrapp's standard input data) as the open Modelica
//    EMBS library reads it: Taylor blocks with 1-based m0(row, col) and m1(row, q, col)
//    entries, Fortran D exponents, J as 6 x 1 (xx yy zz xy xz yz), nodes numbered 1, 2, ...
//    in the SID's order;
//  - MBSim's flexible FFR body input (HDF5, ExternalFlexibleFfrBody): the volume integrals
//    (body_integrals.hpp), stiffness and damping, and the SID nodes' positions and shapes.
// Both are written atomically. check_exportable says what a format cannot hold.
#pragma once
#include "isosid/format/sid.hpp"

#include <string>

namespace isosid::format {

enum class ExportFormat { SidFem, MbsimH5 };

/// InputError naming `sid_file` and the dataset if `sid` cannot be written in `format`: a
/// massless-boundary SID (both tools integrate every coordinate with its mass, its boundary
/// coordinates have none), and for MBSim a SID whose terms do not give back the volume
/// integrals (the trace of the recovered Phi^T Phi integrals must be Me, to 1e-8).
void check_exportable(const Sid& sid, const std::string& sid_file, ExportFormat format);

/// Write `sid` (check_exportable first: these do not check again).
void write_sid_fem(const Sid& sid, const std::string& path);
void write_mbsim_h5(const Sid& sid, const std::string& path);

}  // namespace isosid::format

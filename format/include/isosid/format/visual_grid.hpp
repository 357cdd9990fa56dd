// A SID's viewing mesh (/visual) as a VTK grid: the shared step of isosid-run's ParaView
// frames and isosid-info's mode shapes.
#pragma once
#include "isosid/format/sid.hpp"
#include "isosid/format/vtk_xml.hpp"

namespace isosid::format {

/// The cells of the viewing mesh at its reference points (2D bodies in the x-y plane), with
/// no point data yet.
vtk::UnstructuredGrid visual_grid(const VisualMesh& visual);

/// The mode shapes of a SID with a viewing mesh: one 3-component point array per elastic
/// coordinate (`mode_001` ...) and the frequencies as field data `frequency_hz`.
vtk::UnstructuredGrid mode_shape_grid(const Sid& sid);

}  // namespace isosid::format

// Model files of meshed bodies ([mesh] instead of [geometry]): the isoparametric comparison
// bodies of [R1] Tables 1-2 (docs/references.md). gmsh meshes the primitive; each 9-node element
// becomes a patch in Bezier form; contact surfaces are the boundary edges of a primitive side
// within a distance of the contact point, joined along the side; nodes and the Craig-Bampton
// interface are given in metres.
#pragma once
#include "model/model_tables.hpp"

namespace isosid::prep {

/// Fills m (whose [body] is read) from the rest of the model file `top`.
void read_mesh_model(const TomlView& top, ModelSpec& m, const format::Material& material);

}  // namespace isosid::prep

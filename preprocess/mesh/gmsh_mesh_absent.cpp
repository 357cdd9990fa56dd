// Meshed bodies in a build without gmsh (ISOSID_GMSH=OFF, as scripts/demo configures it): the
// model file's [mesh] is refused by name, and the message says how to build with gmsh.
#include "mesh/gmsh_mesh.hpp"

#include "isosid/format/error.hpp"

namespace isosid::prep {

QuadMesh gmsh_quad_mesh(const MeshSpec&, const std::string& file) {
  throw format::InputError(file, "mesh",
                           "this isosid-prep was built without gmsh (ISOSID_GMSH=OFF); scripts/test installs "
                           "libgmsh-dev and builds it with gmsh");
}

}  // namespace isosid::prep

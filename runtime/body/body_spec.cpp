// The scene's word for an analysis; see body_spec.hpp.
#include "body/body_spec.hpp"

namespace isosid::run {

std::string to_string(Dimension d) {
  switch (d) {
    case Dimension::Planar: return "planar";
    case Dimension::Axisymmetric: return "axisymmetric";
    case Dimension::Solid: return "3d";
  }
  return "?";
}

}  // namespace isosid::run

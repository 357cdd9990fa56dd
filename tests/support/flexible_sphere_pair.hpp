// Test support: scene text of two flexible spheres meeting head-on (the golden sphere_small,
// interface modes quasistatic), the runtime's smallest flexible-flexible contact.
#pragma once
#include <string>

namespace isosid::test {

/// The bodies and the contact of the pair, to follow a [simulation] table: "upper" 0.1 um
/// above the origin, "lower" turned upside down 0.1 um below it (so the poles of their contact
/// surfaces face each other, 0.2 um apart), each approaching at `speed` m/s (TOML number
/// text), and the contact "pair" of the lower one's points on the upper one's deformed master
/// patch at 5e17 N/m^3. Needs ISOSID_GOLDEN_DIR (the tests' compile definition).
inline std::string flexible_sphere_pair(const std::string& speed) {
  auto sphere = [](const std::string& name, const std::string& y, const std::string& vy, const std::string& extra) {
    return "[[flexible_body]]\nname = \"" + name + "\"\nsid = \"" + std::string(ISOSID_GOLDEN_DIR) + "/sphere_small.sid.h5\"\n" +
           "position = [0.0, " + y + ", 0.0]\nvelocity = [0.0, " + vy + ", 0.0]\nhigh_modes = \"quasistatic\"\n" + extra;
  };
  return sphere("upper", "0.0100001", "-" + speed, "") + sphere("lower", "-0.0100001", speed, "orientation = [3.141592653589793, 0.0, 0.0]\n") +
         "[[contact]]\nname = \"pair\"\nbody = \"lower\"\nsurface = \"contact\"\ntarget = \"upper\"\ntarget_surface = \"contact\"\npenalty = 5e17\n";
}

}  // namespace isosid::test

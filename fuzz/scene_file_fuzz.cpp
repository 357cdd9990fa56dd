// Fuzz target: the scene-file loader (TOML bounds, parsing, every table's fields and their
// consistency) on arbitrary text. Bad input must end in InputError.
#include "fuzz_input.hpp"
#include "scene/scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return isosid::fuzz::load_input(data, size, ".scene.toml", [](const std::string& path) { isosid::run::read_scene_file(path); });
}

// Fuzz target: the scene-file loader (TOML bounds, parsing, every table's fields and their
// consistency) on arbitrary text. Bad input must end in InputError.
#include "fuzz_input.hpp"
#include "isosid/format/error.hpp"
#include "scene/scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = isosid::fuzz::input_file(data, size, ".scene.toml");
  try {
    isosid::run::read_scene_file(path);
  } catch (const isosid::format::InputError&) {
  }
  return 0;
}

// Fuzz target: the model-file loader (TOML bounds, parsing, fields, geometry and its fold
// check) on arbitrary text. Bad input must end in InputError.
#include "fuzz_input.hpp"
#include "model/model_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return isosid::fuzz::load_input(data, size, ".model.toml", [](const std::string& path) { isosid::prep::read_model_file(path); });
}

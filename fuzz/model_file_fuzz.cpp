// Fuzz target: the model-file loader (TOML bounds, parsing, fields, geometry and its fold
// check) on arbitrary text. Bad input must end in InputError.
#include "fuzz_input.hpp"
#include "isosid/format/error.hpp"
#include "model/model_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = isosid::fuzz::input_file(data, size, ".model.toml");
  try {
    isosid::prep::read_model_file(path);
  } catch (const isosid::format::InputError&) {
  }
  return 0;
}

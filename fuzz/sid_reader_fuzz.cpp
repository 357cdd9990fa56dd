// Fuzz target: format::read_sid on arbitrary bytes. Bad files must end in InputError; a crash,
// a leak or unbounded memory in the reader (after its child-process probe) is a finding.
#include "fuzz_input.hpp"
#include "isosid/format/sid_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return isosid::fuzz::load_input(data, size, ".sid.h5", [](const std::string& path) { isosid::format::read_sid(path); });
}

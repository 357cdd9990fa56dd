// libFuzzer helper: the loaders read files, so each input is written to a file of this process
// first (the same path every time: one input at a time), then loaded; bad input must end in
// InputError, anything else is a finding.
#pragma once
#include "isosid/format/error.hpp"

#include <cstddef>
#include <cstdio>
#include <cstdint>
#include <fstream>
#include <string>
#include <unistd.h>

namespace isosid::fuzz {

/// Writes the input to `path` and loads it; the file is removed after (a finding aborts first
/// and leaves it).
template <class Load>
int load_input_at(const std::uint8_t* data, std::size_t size, const std::string& path, Load load) {
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data), std::streamsize(size));
  struct Remove {
    const std::string& path;
    ~Remove() { std::remove(path.c_str()); }
  } remove{path};
  try {
    load(path);
  } catch (const format::InputError&) {
  }
  return 0;
}

/// Writes the input to a file of this process named with `suffix` and loads it.
template <class Load>
int load_input(const std::uint8_t* data, std::size_t size, const std::string& suffix, Load load) {
  return load_input_at(data, size, "/tmp/isosid-fuzz-" + std::to_string(::getpid()) + suffix, load);
}

}  // namespace isosid::fuzz

// SHA-256 (FIPS 180-4) of files and strings, for provenance and for caching models by the
// hash of their input.
#pragma once
#include <string>

namespace isosid::format {

/// Lower-case hex digest of `data`.
std::string sha256_hex(const std::string& data);

/// Digest of a file's bytes; throws InputError if it cannot be read.
std::string sha256_file(const std::string& path);

}  // namespace isosid::format

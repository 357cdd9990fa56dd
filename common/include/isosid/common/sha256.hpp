// SHA-256 (FIPS 180-4) of files and strings, for provenance and for caching models by the
// hash of their input. Incremental, so files are hashed in chunks rather than read whole.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace isosid::common {

class Sha256 {
public:
  /// Appends bytes to the message; may be called any number of times.
  void update(std::string_view bytes);
  /// Pads the message and returns its lower-case hex digest; the hasher is spent afterwards.
  std::string hex_digest();

private:
  void compress_buffer();
  std::array<uint32_t, 8> state_ = {0x6a09e667, 0xbb67ae85, 0x3c6ef372, 0xa54ff53a,
                                    0x510e527f, 0x9b05688c, 0x1f83d9ab, 0x5be0cd19};
  std::array<unsigned char, 64> buffer_{};
  std::size_t buffered_ = 0;    ///< bytes waiting in buffer_
  uint64_t message_bytes_ = 0;  ///< total length, for the padding
};

/// Lower-case hex digest of `data`.
std::string sha256_hex(std::string_view data);

/// Digest of a file's bytes; throws format::InputError if it cannot be read.
std::string sha256_file(const std::string& path);

}  // namespace isosid::common

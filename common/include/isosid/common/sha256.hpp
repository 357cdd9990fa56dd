// SHA-256 (FIPS 180-4) of files and strings, for provenance and for caching models by the
// hash of their input. Incremental, so files are hashed in chunks rather than read whole.
// OpenSSL's libcrypto computes it: with the CPU's SHA extensions it hashes a SID of tens of
// megabytes in milliseconds, which matters because every run hashes all its SIDs.
#pragma once
#include <memory>
#include <string>
#include <string_view>

namespace isosid::common {

class Sha256 {
public:
  Sha256();
  ~Sha256();
  Sha256(Sha256&&) noexcept;
  Sha256& operator=(Sha256&&) noexcept;

  /// Appends bytes to the message; may be called any number of times.
  void update(std::string_view bytes);
  /// Pads the message and returns its lower-case hex digest; the hasher is spent afterwards
  /// (update or hex_digest on it again, or on a moved-from one, throws std::logic_error).
  std::string hex_digest();

private:
  struct Context;
  std::unique_ptr<Context> context_;
};

/// Lower-case hex digest of `data`.
std::string sha256_hex(std::string_view data);

/// Digest of a file's bytes; throws format::InputError if it cannot be read.
std::string sha256_file(const std::string& path);

}  // namespace isosid::common

// SHA-256 by OpenSSL's EVP digest interface; see sha256.hpp.
#include "isosid/common/sha256.hpp"

#include "isosid/format/error.hpp"

#include <openssl/evp.h>

#include <fstream>
#include <stdexcept>

namespace isosid::common {

struct Sha256::Context {
  EVP_MD_CTX* ctx = EVP_MD_CTX_new();
  bool spent = false;
  ~Context() { EVP_MD_CTX_free(ctx); }
};

namespace {
// libcrypto fails only when it cannot allocate or has no SHA-256: neither is the input's fault
void require(int ok, const char* what) {
  if (ok != 1) throw std::runtime_error(std::string("SHA-256: libcrypto's ") + what + " failed");
}
}  // namespace

Sha256::Sha256() : context_(std::make_unique<Context>()) {
  if (!context_->ctx) throw std::bad_alloc();
  require(EVP_DigestInit_ex(context_->ctx, EVP_sha256(), nullptr), "EVP_DigestInit_ex");
}
Sha256::~Sha256() = default;
Sha256::Sha256(Sha256&&) noexcept = default;
Sha256& Sha256::operator=(Sha256&&) noexcept = default;

void Sha256::update(std::string_view bytes) {
  if (!context_ || context_->spent) throw std::logic_error("SHA-256: update of a spent or moved-from hasher");
  require(EVP_DigestUpdate(context_->ctx, bytes.data(), bytes.size()), "EVP_DigestUpdate");
}

std::string Sha256::hex_digest() {
  if (!context_ || context_->spent) throw std::logic_error("SHA-256: hex_digest of a spent or moved-from hasher");
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  require(EVP_DigestFinal_ex(context_->ctx, digest, &length), "EVP_DigestFinal_ex");
  context_->spent = true;
  static const char* hex = "0123456789abcdef";
  std::string out;
  for (unsigned int i = 0; i < length; ++i) {
    out.push_back(hex[digest[i] >> 4]);
    out.push_back(hex[digest[i] & 0xf]);
  }
  return out;
}

std::string sha256_hex(std::string_view data) {
  Sha256 hasher;
  hasher.update(data);
  return hasher.hex_digest();
}

std::string sha256_file(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw format::InputError(path, "", "cannot be read");
  Sha256 hasher;
  std::string chunk(std::size_t{1} << 20, '\0');
  while (f.read(chunk.data(), std::streamsize(chunk.size())) || f.gcount() > 0)
    hasher.update(std::string_view(chunk.data(), std::size_t(f.gcount())));
  if (f.bad()) throw format::InputError(path, "", "cannot be read");
  return hasher.hex_digest();
}

}  // namespace isosid::common

// Known-answer tests of SHA-256: the FIPS 180-2 / NIST example messages, fed whole, in
// chunks that straddle the 64-byte blocks, and from a file.
#include "isosid/common/sha256.hpp"
#include "isosid/format/error.hpp"
#include "support/run_program.hpp"

#include <catch2/catch.hpp>
#include <fstream>
#include <stdexcept>
#include <utility>

using isosid::common::Sha256;
using isosid::common::sha256_file;
using isosid::common::sha256_hex;

namespace {
const std::string kMillionA(1000000, 'a');
constexpr const char* kMillionADigest = "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0";
}  // namespace

TEST_CASE("SHA-256 of the FIPS 180-2 example messages", "[common][sha256]") {
  CHECK(sha256_hex("") == "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  CHECK(sha256_hex("abc") == "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  CHECK(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq") ==
        "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  CHECK(sha256_hex(kMillionA) == kMillionADigest);
}

TEST_CASE("SHA-256 fed in chunks equals SHA-256 of the whole message", "[common][sha256]") {
  // Chunk sizes below, at and across the 64-byte block, and the 55/56-byte padding boundary.
  for (std::size_t chunk : {1u, 55u, 56u, 63u, 64u, 65u, 1000u, 4096u}) {
    Sha256 hasher;
    for (std::size_t at = 0; at < kMillionA.size(); at += chunk) hasher.update(std::string_view(kMillionA).substr(at, chunk));
    INFO("chunk " << chunk);
    CHECK(hasher.hex_digest() == kMillionADigest);
  }
  for (std::size_t length : {55u, 56u, 63u, 64u, 119u, 120u}) {
    const std::string message(length, 'x');
    Sha256 hasher;
    hasher.update(std::string_view(message).substr(0, length / 2));
    hasher.update(std::string_view(message).substr(length / 2));
    INFO("length " << length);
    CHECK(hasher.hex_digest() == sha256_hex(message));
  }
}

TEST_CASE("SHA-256 of a file is that of its bytes, and a missing file is bad input", "[common][sha256]") {
  const isosid::test::ScratchDir dir("sha256");
  std::ofstream(dir.path("million_a.txt"), std::ios::binary) << kMillionA;
  CHECK(sha256_file(dir.path("million_a.txt")) == kMillionADigest);
  CHECK_THROWS_AS(sha256_file(dir.path("missing.txt")), isosid::format::InputError);
}

TEST_CASE("SHA-256: a spent or moved-from hasher refuses more work", "[common][sha256]") {
  Sha256 hasher;
  hasher.update("abc");
  Sha256 moved = std::move(hasher);
  CHECK_THROWS_AS(hasher.update("d"), std::logic_error);
  CHECK(moved.hex_digest() == sha256_hex("abc"));
  CHECK_THROWS_AS(moved.hex_digest(), std::logic_error);
  CHECK_THROWS_AS(moved.update("d"), std::logic_error);
}

// The adaptive loop's SID cache; see model_cache.hpp.
#include "adapt/model_cache.hpp"

#include "isosid/common/sha256.hpp"
#include "isosid/format/error.hpp"
#include "scene/prep_process.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>

namespace isosid::run {
namespace fs = std::filesystem;

namespace {

/// What isosid-prep is, for the key: a rebuilt preprocessor may build other SIDs from the
/// same request, so its file's size and modification time are part of the key.
std::string prep_identity() {
  const std::string prep = find_prep();
  std::error_code ec;
  const auto size = fs::file_size(prep, ec);
  if (ec) return prep;  // found on PATH only: the name is all we know
  const auto stamp = fs::last_write_time(prep, ec).time_since_epoch().count();
  return prep + " " + std::to_string(size) + " " + std::to_string(stamp);
}

}  // namespace

ModelCache::ModelCache(std::string directory, bool quiet) : directory_(std::move(directory)), quiet_(quiet) {}

CachedSid ModelCache::coarse(const std::string& model_file) { return lookup(model_file, {"--coarse"}, " (its coarse model)"); }

CachedSid ModelCache::fine(const std::string& model_file, const RefinementRequest& request) {
  std::string at = request.surface + ":";
  for (std::size_t k = 0; k < request.at.size(); ++k) {
    char number[32];
    std::snprintf(number, sizeof number, "%s%.17g", k ? "," : "", request.at[k]);
    at += number;
  }
  char width[32];
  std::snprintf(width, sizeof width, "%.17g", request.width);
  return lookup(model_file, {"--refine-at", at, "--refine-width", width},
                std::string(" (refined at ") + at + ", " + width + " m wide)");
}

CachedSid ModelCache::lookup(const std::string& model_file, const std::vector<std::string>& options, const std::string& what) {
  common::Sha256 key;
  key.update("isosid model cache 1\n");
  key.update(common::sha256_file(model_file) + "\n");  // the content, wherever the file lives
  key.update(prep_identity() + "\n");
  for (const std::string& option : options) key.update(option + "\n");
  const std::string stem = fs::path(model_file).filename().string();
  const fs::path file = fs::path(directory_) / (stem.substr(0, stem.find('.')) + "-" + key.hex_digest().substr(0, 20) + ".sid.h5");
  CachedSid out{file.string(), false, 0};
  std::error_code ec;
  if (fs::is_regular_file(file, ec)) {  // isosid-prep writes atomically: a file there is whole
    out.hit = true;
    ++hits_;
    return out;
  }
  fs::create_directories(directory_, ec);
  if (ec) throw format::InputError(directory_, "", "cannot create the model cache directory: " + ec.message());
  const auto start = std::chrono::steady_clock::now();
  run_prep(model_file, out.file, options, quiet_, what);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ++builds_;
  return out;
}

}  // namespace isosid::run

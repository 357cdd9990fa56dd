// The adaptive loop's SID cache; see model_cache.hpp.
#include "adapt/model_cache.hpp"

#include "isosid/common/sha256.hpp"
#include "isosid/format/error.hpp"
#include "scene/prep_process.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <deque>
#include <exception>
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

CachedSid ModelCache::coarse(const std::string& model_file) { return lookup({{model_file, {"--coarse"}, " (its coarse model)"}}).front(); }

CachedSid ModelCache::fine(const std::string& model_file, const RefinementRequest& request) { return fine({{model_file, request}}).front(); }

std::vector<CachedSid> ModelCache::fine(const std::vector<FineRequest>& requests) {
  std::vector<Request> asked;
  for (const FineRequest& r : requests) {
    std::string at = r.request.surface + ":";
    for (std::size_t k = 0; k < r.request.at.size(); ++k) {
      char number[32];
      std::snprintf(number, sizeof number, "%s%.17g", k ? "," : "", r.request.at[k]);
      at += number;
    }
    char width[32];
    std::snprintf(width, sizeof width, "%.17g", r.request.width);
    Request request{r.model_file, {"--refine-at", at, "--refine-width", width}, std::string(" (refined at ") + at + ", " + width + " m wide)"};
    if (r.request.contact_radius > 0) {
      char radius[32];
      std::snprintf(radius, sizeof radius, "%.17g", r.request.contact_radius);
      request.options.insert(request.options.end(), {"--contact-radius", radius});
      request.what.insert(request.what.size() - 1, std::string(", for a contact radius of ") + radius + " m");
    }
    asked.push_back(request);
  }
  return lookup(asked);
}

std::string ModelCache::cached_file(const Request& request) const {
  common::Sha256 key;
  key.update("isosid model cache 1\n");
  key.update(common::sha256_file(request.model_file) + "\n");  // the content, wherever the file lives
  key.update(prep_identity() + "\n");
  for (const std::string& option : request.options) key.update(option + "\n");
  const std::string stem = fs::path(request.model_file).filename().string();
  return (fs::path(directory_) / (stem.substr(0, stem.find('.')) + "-" + key.hex_digest().substr(0, 20) + ".sid.h5")).string();
}

std::vector<CachedSid> ModelCache::lookup(const std::vector<Request>& requests) {
  using Clock = std::chrono::steady_clock;
  std::vector<CachedSid> out;
  std::vector<std::size_t> missing;  // requests to build, each file once
  for (const Request& request : requests) {
    CachedSid sid{cached_file(request), false, 0};
    std::error_code ec;
    bool found = fs::is_regular_file(sid.file, ec);  // isosid-prep writes atomically: a file there is whole
    for (std::size_t m : missing) found = found || out[m].file == sid.file;
    sid.hit = found;
    if (found) ++hits_;
    else missing.push_back(out.size());
    out.push_back(sid);
  }
  if (missing.empty()) return out;
  std::error_code ec;
  fs::create_directories(directory_, ec);
  if (ec) throw format::InputError(directory_, "", "cannot create the model cache directory: " + ec.message());

  // one build per core; each build's assembly gets its share of the cores (an impact asks for
  // at most one model per body, two, so reading the builds in start order costs nothing here)
  const int cores = usable_cores();
  const std::size_t side_by_side = std::min(missing.size(), std::size_t(cores));
  const int threads = side_by_side > 1 ? std::max(1, cores / int(side_by_side)) : 0;
  struct Running {
    std::size_t index;
    PrepProcess process;
    Clock::time_point start;
  };
  std::deque<Running> running;
  std::exception_ptr failure;
  std::size_t next = 0;
  while (next < missing.size() || !running.empty()) {
    while (!failure && next < missing.size() && running.size() < side_by_side) {  // no new build after a failure
      const std::size_t i = missing[next++];
      const Request& r = requests[i];
      try {
        running.push_back({i, start_prep(r.model_file, out[i].file, r.options, quiet_, r.what, threads), Clock::now()});
      } catch (...) {
        failure = std::current_exception();
      }
    }
    if (running.empty()) break;
    Running done = std::move(running.front());  // output is passed on to its end, one build after the other
    running.pop_front();
    std::vector<PrepProcess*> beside;  // their output read ahead meanwhile
    for (Running& r : running) beside.push_back(&r.process);
    try {
      finish_prep(done.process, beside);
      // until this program had the SID: a build that ends before the one ahead of it waits for it
      out[done.index].seconds = std::chrono::duration<double>(Clock::now() - done.start).count();
      ++builds_;
    } catch (...) {
      if (!failure) failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);
  return out;
}

}  // namespace isosid::run

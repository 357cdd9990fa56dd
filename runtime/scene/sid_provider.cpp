// SID loading and rebuilding; see sid_provider.hpp.
#include "scene/sid_provider.hpp"

#include "isosid/common/file_lock.hpp"
#include "isosid/common/sha256.hpp"
#include "isosid/common/version.hpp"
#include "isosid/format/error.hpp"
#include "isosid/format/sid_io.hpp"
#include "scene/prep_process.hpp"
#include "scene/sid_digest.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>

namespace isosid::run {
namespace fs = std::filesystem;

namespace {
/// A Craig-Bampton SID from before isosid-prep marked the contact points its interface covers
/// (/contact/<name>/in_interface): without them a contact beyond the interface goes unreported.
bool lacks_interface_coverage(const format::Sid& sid) {
  if (format::reduction_method_named(sid.refmod.reduction_method) != format::ReductionMethod::CraigBampton) return false;
  return std::any_of(sid.contact_surfaces.begin(), sid.contact_surfaces.end(), [](const format::ContactSurface& c) { return c.in_interface.size() == 0; });
}

/// Whether the SID of `body` (the scene's flexible_body[index]) was built from its model file
/// as it is now: false where its provenance records the same file name but another content
/// (edited since, whatever the file times say). A SID whose provenance names another model
/// file is refused (rebuilding it would overwrite that model's SID).
bool built_from_model(const format::Sid& sid, const BodySpec& body, const Scene& scene, std::size_t index) {
  const format::Provenance& p = sid.provenance;
  if (p.model_file.empty() || p.model_sha256.empty()) return true;  // built in memory: nothing to compare
  const std::string built_from = fs::path(p.model_file).filename().string(), named = fs::path(body.model_file).filename().string();
  if (built_from != named)
    throw format::InputError(scene.file, "flexible_body[" + std::to_string(index) + "].sid",
                             body.sid_file + " was built from " + built_from + ", not " + named +
                                 " (name a SID file of its own for this model)");
  return p.model_sha256 == common::sha256_file(body.model_file);
}
}  // namespace

format::ReadOptions sid_read_options(const Scene& scene, const std::string& file) {
  format::ReadOptions options;
  options.visual = scene.output.paraview;
  options.probe = !sid_digest_matches(file);
  return options;
}

std::vector<format::Sid> load_sids(const Scene& scene, bool quiet) {
  std::vector<format::Sid> sids;
  for (const BodySpec& b : scene.bodies) {
    if (b.rigid) continue;  // rigid bodies have no SID
    const std::size_t index = sids.size();  // flexible_body[index] of the scene
    std::error_code ec;
    // `<sid>.lock` while this body's SID is checked, rebuilt and read: runs sharing a model (a
    // study's ranks, two isosid-run started together) read it side by side (shared) and build
    // it one at a time (exclusive), so that none reads another's half-decided SID or builds it
    // a second time
    std::optional<common::FileLock> lock;
    const bool from_model = !b.model_file.empty() && !b.adaptive;  // an adaptive body's SIDs come from the run's cache
    const auto stale = [&] {
      return !fs::exists(b.sid_file, ec) || fs::last_write_time(b.sid_file, ec) < fs::last_write_time(b.model_file, ec);
    };
    if (from_model) {
      lock.emplace(b.sid_file + ".lock", common::FileLock::Mode::Shared);
      if (stale()) {
        lock->make_exclusive();
        if (stale()) run_prep(b.model_file, b.sid_file, {}, quiet, "");
      }
    }
    sids.push_back(format::read_sid(b.sid_file, sid_read_options(scene, b.sid_file)));
    // (a run that finds it built from another model version or without its interface points
    // rebuilds it under the exclusive lock and reads its own build)
    if (from_model && !built_from_model(sids.back(), b, scene, index)) {
      lock->make_exclusive();
      run_prep(b.model_file, b.sid_file, {}, quiet, " (the SID there was built from another version of the model)");
      sids.back() = format::read_sid(b.sid_file, sid_read_options(scene, b.sid_file));
    }
    if (from_model && lacks_interface_coverage(sids.back())) {
      lock->make_exclusive();
      run_prep(b.model_file, b.sid_file, {}, quiet, " (the SID there does not record which contact points its interface covers)");
      sids.back() = format::read_sid(b.sid_file, sid_read_options(scene, b.sid_file));
    }
  }
  return sids;
}

SizedSid sized_sid(const Scene& scene, const BodySpec& body, double contact_radius, bool quiet) {
  char radius[32];
  std::snprintf(radius, sizeof radius, "%.17g", contact_radius);
  const std::string key = common::sha256_hex(common::sha256_file(body.model_file) + "\n" + radius + "\n" + common::version_line("isosid-prep"));
  const fs::path sid(body.sid_file);
  const fs::path cache = sid.parent_path() / ".isosid-cache";
  std::string stem = sid.filename().string();
  stem = stem.substr(0, stem.find('.'));
  const std::string file = (cache / (stem + "-" + key.substr(0, 16) + ".sid.h5")).string();
  std::error_code ec;
  fs::create_directories(cache, ec);
  const common::FileLock lock(file + ".lock", common::FileLock::Mode::Exclusive);
  if (!fs::exists(file, ec)) run_prep(body.model_file, file, {"--contact-radius", radius}, quiet, std::string(" for a contact radius of ") + radius);
  return {format::read_sid(file, sid_read_options(scene, file)), file};
}

}  // namespace isosid::run

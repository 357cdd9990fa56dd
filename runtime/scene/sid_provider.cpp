// SID loading and rebuilding; see sid_provider.hpp.
#include "scene/sid_provider.hpp"

#include "isosid/format/error.hpp"
#include "isosid/format/sid_io.hpp"
#include "scene/prep_process.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>

namespace isosid::run {
namespace fs = std::filesystem;

namespace {
/// A Craig-Bampton SID from before isosid-prep marked the contact points its interface covers
/// (/contact/<name>/in_interface): without them a contact beyond the interface goes unreported.
bool lacks_interface_coverage(const format::Sid& sid) {
  if (sid.refmod.reduction_method != "craig-bampton") return false;
  return std::any_of(sid.contact_surfaces.begin(), sid.contact_surfaces.end(), [](const format::ContactSurface& c) { return c.in_interface.size() == 0; });
}
}  // namespace

format::ReadOptions sid_read_options(const Scene& scene) {
  format::ReadOptions options;
  options.visual = scene.output.paraview;
  return options;
}

std::vector<format::Sid> load_sids(const Scene& scene, bool quiet) {
  std::vector<format::Sid> sids;
  for (const BodySpec& b : scene.bodies) {
    if (b.rigid) continue;  // rigid bodies have no SID
    std::error_code ec;
    if (!b.model_file.empty() && !b.adaptive) {  // an adaptive body's SIDs come from the run's cache, built for their request
      const bool stale = !fs::exists(b.sid_file, ec) || fs::last_write_time(b.sid_file, ec) < fs::last_write_time(b.model_file, ec);
      if (stale) run_prep(b.model_file, b.sid_file, {}, quiet, "");
    }
    sids.push_back(format::read_sid(b.sid_file, sid_read_options(scene)));
    if (!b.model_file.empty() && !b.adaptive && lacks_interface_coverage(sids.back())) {
      run_prep(b.model_file, b.sid_file, {}, quiet, " (the SID there does not record which contact points its interface covers)");
      sids.back() = format::read_sid(b.sid_file, sid_read_options(scene));
    }
  }
  return sids;
}

format::Sid rebuild_sid(const Scene& scene, const BodySpec& body, double contact_radius, bool quiet) {
  char radius[32];
  std::snprintf(radius, sizeof radius, "%.17g", contact_radius);
  run_prep(body.model_file, body.sid_file, {"--contact-radius", radius}, quiet, std::string(" for a contact radius of ") + radius);
  return format::read_sid(body.sid_file, sid_read_options(scene));
}

}  // namespace isosid::run

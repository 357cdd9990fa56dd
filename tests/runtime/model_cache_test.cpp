// The adaptive loop's SID cache ([R2] Sect. 4, docs/references.md): fine models refined where an
// impact happens, built once by isosid-prep and read back on a repeated request.
#include "adapt/model_cache.hpp"
#include "scene/prep_process.hpp"
#include "isosid/format/error.hpp"
#include "isosid/format/sid_io.hpp"
#include "support/run_program.hpp"

#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>

using namespace isosid;

namespace {

/// Gauss points of the sphere's contact surface whose tangential parameter (xi; the surface
/// is the side eta = 0) lies within `half` of `xi`.
int points_near(const format::Sid& sid, double xi, double half) {
  const format::ContactSurface& s = sid.contact_surfaces.at(0);
  int n = 0;
  for (Eigen::Index g = 0; g < s.points(); ++g) n += std::abs(s.parameter(g, 0) - xi) <= half;
  return n;
}

}  // namespace

TEST_CASE("model cache: a fine model is refined where asked, built once, and its transfer starts from the coarse model",
          "[runtime][unit][adaptive]") {
  ::setenv("ISOSID_PREP", ISOSID_PREP_EXE, 1);
  const test::ScratchDir dir("model_cache");
  const std::string model = dir.path("sphere.model.toml");
  std::filesystem::copy_file(std::string(ISOSID_MODELS_DIR) + "/sphere_axisym_thb.model.toml", model);
  run::ModelCache cache(dir.path("cache"), true);

  // two impact points on the lower arc, 0.5 mm wide regions (xi 0.05 is 2.4 mm from the pole)
  const run::RefinementRequest off_pole{"contact", {0.05}, 0.5e-3}, at_pole{"contact", {0.0}, 0.5e-3};
  const run::CachedSid first = cache.fine(model, off_pole);
  CHECK_FALSE(first.hit);
  CHECK(first.seconds > 0);
  const format::Sid fine = format::read_sid(first.file);
  const format::Sid pole = format::read_sid(cache.fine(model, at_pole).file);
  // the refinement follows the point: the 25 um elements put many more Gauss points within
  // 0.1 mm of it than the model refined at the other point does (the coarse elements there
  // are ~0.4 mm long, so without refinement at most a few points fall within)
  const double half = 0.1e-3 / (M_PI * 0.01 / 2);  // 0.1 mm as a parameter of the quarter arc
  CHECK(points_near(fine, 0.05, half) >= 4 * points_near(pole, 0.05, half));
  CHECK(points_near(pole, 0.0, half) >= 4 * points_near(fine, 0.0, half));

  // the same request again: read from the cache, the file untouched
  const auto stamp = std::filesystem::last_write_time(first.file);
  const run::CachedSid again = cache.fine(model, off_pole);
  CHECK(again.hit);
  CHECK(again.file == first.file);
  CHECK(std::filesystem::last_write_time(again.file) == stamp);
  CHECK(cache.hits() == 1);
  CHECK(cache.builds() == 2);

  // the coarse model it transfers from: the same model file, its normal modes only
  const run::CachedSid coarse_file = cache.coarse(model);
  const format::Sid coarse = format::read_sid(coarse_file.file);
  REQUIRE(fine.transfer.has_value());
  CHECK(fine.transfer->coarse_model_sha256 == coarse.provenance.model_sha256);
  CHECK(fine.transfer->coarse_to_fine.cols() == coarse.nq());
  CHECK(coarse.nq() < fine.nq());

  // another width, or a changed model file, is another request
  CHECK_FALSE(cache.fine(model, {"contact", {0.05}, 0.6e-3}).hit);
  std::ofstream(model, std::ios::app) << "\n# edited\n";
  CHECK_FALSE(cache.fine(model, off_pole).hit);
}

TEST_CASE("model cache: a request isosid-prep refuses is an input error naming the model file", "[runtime][unit][adaptive][bad-input]") {
  ::setenv("ISOSID_PREP", ISOSID_PREP_EXE, 1);
  const test::ScratchDir dir("model_cache_refused");
  run::ModelCache cache(dir.path("cache"), true);
  const std::string thb = std::string(ISOSID_MODELS_DIR) + "/sphere_axisym_thb.model.toml";
  const std::string graded = std::string(ISOSID_MODELS_DIR) + "/sphere_axisym.model.toml";
  const auto refused = [&](const std::string& model, const run::RefinementRequest& request, const std::string& problem) {
    try {
      cache.fine(model, request);
      FAIL("accepted");
    } catch (const format::InputError& e) {
      INFO(e.what());
      CHECK(std::string(e.what()).find(model) != std::string::npos);
      CHECK(std::string(e.what()).find(problem) != std::string::npos);
    }
  };
  refused(thb, {"contact", {1.5}, 0.5e-3}, "outside the parameter range");
  refused(thb, {"rim", {0.1}, 0.5e-3}, "no contact_surface named 'rim'");
  refused(thb, {"contact", {0.1, 0.2}, 0.5e-3}, "tangential parameter");
  refused(graded, {"contact", {0.1}, 0.5e-3}, "no [refinement.hierarchical]");
  // a region wider than the body would refine all of it (1 km on the 10 mm sphere: 7 GB)
  refused(thb, {"contact", {0.1}, 1e3}, "a refined region 1000 m wide exceeds the patch it refines");
  CHECK(cache.builds() == 0);
  const bool empty = !std::filesystem::exists(dir.path("cache")) || std::filesystem::is_empty(dir.path("cache"));
  CHECK(empty);  // nothing half-built is left for a later run to find
}

TEST_CASE("model cache: an impact's models are built side by side, each once, and equal those built alone",
          "[runtime][unit][adaptive]") {
  ::setenv("ISOSID_PREP", ISOSID_PREP_EXE, 1);
  const test::ScratchDir dir("model_cache_batch");
  const std::string model = std::string(ISOSID_MODELS_DIR) + "/sphere_axisym_thb.model.toml";
  const run::RefinementRequest off_pole{"contact", {0.05}, 0.5e-3}, at_pole{"contact", {0.0}, 0.5e-3};

  run::ModelCache batch(dir.path("batch"), true);
  const std::vector<run::CachedSid> sids = batch.fine({{model, off_pole}, {model, at_pole}, {model, off_pole}});
  REQUIRE(sids.size() == 3);
  CHECK_FALSE(sids[0].hit);
  CHECK_FALSE(sids[1].hit);
  CHECK(sids[2].hit);  // the same request twice in one batch: built once
  CHECK(sids[2].file == sids[0].file);
  CHECK(sids[0].file != sids[1].file);
  CHECK(batch.builds() == 2);

  // the same models built one at a time (another cache): the same SIDs. Side by side, each
  // build's assembly runs on its share of the cores, which changes the order of the element
  // sums: the frequencies and transfers agree to that round-off as the eigen solve carries it
  // (measured 1.1e-11 and 9.7e-11 relative, one thread against two), not bit for bit
  run::ModelCache alone(dir.path("alone"), true);
  for (std::size_t j = 0; j < 2; ++j) {
    const format::Sid a = format::read_sid(sids[j].file);
    const format::Sid b = format::read_sid(alone.fine(model, j == 0 ? off_pole : at_pole).file);
    REQUIRE(a.nq() == b.nq());
    const Eigen::VectorXd& fa = a.refmod.frequencies_hz;
    CHECK((fa - b.refmod.frequencies_hz).cwiseAbs().maxCoeff() <= 1e-8 * fa.cwiseAbs().maxCoeff());
    REQUIRE(a.transfer.has_value());
    REQUIRE(b.transfer.has_value());
    const Eigen::MatrixXd& ta = a.transfer->coarse_to_fine;
    CHECK((ta - b.transfer->coarse_to_fine).cwiseAbs().maxCoeff() <= 1e-8 * ta.cwiseAbs().maxCoeff());
  }
}

TEST_CASE("model cache: a refused request in a batch is thrown after the other builds have ended, whose models are kept",
          "[runtime][unit][adaptive][bad-input]") {
  ::setenv("ISOSID_PREP", ISOSID_PREP_EXE, 1);
  const test::ScratchDir dir("model_cache_batch_refused");
  const std::string model = std::string(ISOSID_MODELS_DIR) + "/sphere_axisym_thb.model.toml";
  if (run::usable_cores() < 2) {  // one build at a time: nothing starts after the refusal
    WARN("one core: builds are not side by side here");
    return;
  }
  run::ModelCache cache(dir.path("cache"), true);
  try {  // the refusal first: it is read first, while the good build is still running
    cache.fine({{model, {"contact", {1.5}, 0.5e-3}}, {model, {"contact", {0.05}, 0.5e-3}}});
    FAIL("accepted");
  } catch (const format::InputError& e) {
    INFO(e.what());
    CHECK(std::string(e.what()).find("outside the parameter range") != std::string::npos);
  }
  CHECK(cache.builds() == 1);
  // the good request's SID is whole and in the cache: asked again, it is a hit
  CHECK(cache.fine(model, {"contact", {0.05}, 0.5e-3}).hit);
}

TEST_CASE("a build waited for does not leave the one beside it blocked on its output", "[runtime][unit][adaptive]") {
  // Builds side by side are passed on one after the other, and one may wait for memory another
  // is about to take (preprocess's memory ledger). A stand-in for isosid-prep: the build of
  // "front" waits until the build of "beside" has printed 1 MB and ended; unread, "beside"
  // would block on its full pipe and neither would end.
  const test::ScratchDir dir("prep-output-beside");
  const std::string script = dir.path("prep.sh"), done = dir.path("beside-done");
  std::ofstream(script) << "#!/bin/sh\n"
                           "if [ \"$1\" = front ]; then\n"
                           "  i=0; while [ ! -e " << done << " ] && [ $i -lt 200 ]; do sleep 0.05; i=$((i+1)); done\n"
                           "  [ -e " << done << " ] || { echo 'isosid-prep: failed: beside never ended' >&2; exit 1; }\n"
                           "  echo 'front: built'; exit 0\n"
                           "fi\n"
                           "head -c 1000000 /dev/zero | tr '\\0' 'x' | fold -w 100 >&2\n"
                           "touch " << done << "\n";
  std::filesystem::permissions(script, std::filesystem::perms::owner_all);
  ::setenv("ISOSID_PREP", script.c_str(), 1);
  run::PrepProcess front = run::start_prep("front", "", {}, true, "");
  run::PrepProcess beside = run::start_prep("beside", "", {}, true, "");
  CHECK_NOTHROW(run::finish_prep(front, {&beside}));
  CHECK(beside.pending.size() > 65536);  // read while the front was waited for, beyond what a pipe holds
  CHECK_NOTHROW(run::finish_prep(beside));
  ::unsetenv("ISOSID_PREP");
}

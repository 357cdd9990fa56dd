// A run's outputs against their tables (output/output_layout): docs/outputs.md is the tables'
// markdown, as isosid-run --describe-outputs prints it. Runs of every kind (general and gap-space
// contact with a flexible target, Hertz contacts, joints, point and stress monitors, references,
// settings over the scene, an adaptive run with its phases) write nothing the tables do not hold,
// each with the table's type and units, and everything the tables mark "always". Between them
// they write every item of the tables, but for the few listed below that need a run to fail.
#include "isosid/format/hdf5_file.hpp"
#include "output/output_layout.hpp"
#include "scene_runner.hpp"
#include "support/impact_scene.hpp"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <hdf5.h>
#include <iterator>
#include <set>
#include <sstream>

using namespace isosid;
using nlohmann::json;
namespace outputs = run::outputs;

namespace {

/// Items written by no run of this test, with why; the test checks that none of them is written.
const std::set<std::string> kNotWritten = {
    "failure",                       // a failed run's (tests/runtime/runtime_test.cpp checks its exit and text)
    "results_h5_error",              // a run whose results.h5 cannot be written (the full-disk test)
    // an impact phase that met an error and went on at a lower penalty
    // (tests/runtime/adaptive_run_test.cpp runs one)
    "adaptive.phases[].error", "adaptive.phases[].penalty_lowered", "adaptive.phases[].penalty_lowered.error",
    "adaptive.phases[].penalty_lowered.to_n_m3", "adaptive.phases[].continued",
    "contacts[].hertz_estimate.contact_half_width_m",  // a line contact's (planar scenes)
};

/// The parent of a table path: "/bodies/<body>" of "/bodies/<body>/q", "contacts[]" of
/// "contacts[].name", "" at the top.
std::string parent_of(std::string_view path) {
  const std::size_t cut = path.find_last_of("/.");
  return cut == std::string_view::npos ? "" : std::string(path.substr(0, cut));
}

std::string last_name(std::string_view path) {
  const std::size_t cut = path.find_last_of("/.");
  return std::string(cut == std::string_view::npos ? path : path.substr(cut + 1));
}

struct Coverage {
  std::set<std::string> seen;  // table paths written by some run
};

/// The items under `parent` (a table path) that are always there, by their last name.
std::vector<const outputs::Item*> always_under(std::span<const outputs::Item> items, const std::string& parent) {
  std::vector<const outputs::Item*> out;
  for (const outputs::Item& i : items)
    if (i.when.empty() && parent_of(i.path) == parent) out.push_back(&i);
  return out;
}

// ---------------------------------------------------------------- results.h5

struct H5Walk {
  std::vector<std::pair<std::string, H5O_type_t>> objects;  // paths below the root
};

herr_t visit(hid_t, const char* name, const H5O_info_t* info, void* data) {
  if (std::string(name) != ".") static_cast<H5Walk*>(data)->objects.push_back({"/" + std::string(name), info->type});
  return 0;
}

unsigned dataset_type(hid_t file, const std::string& path) {
  const hid_t d = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
  const hid_t t = H5Dget_type(d), s = H5Dget_space(d);
  const H5T_class_t c = H5Tget_class(t);
  const int rank = H5Sget_simple_extent_ndims(s);
  H5Sclose(s), H5Tclose(t), H5Dclose(d);
  if (c == H5T_FLOAT) return outputs::Float64;
  if (c == H5T_INTEGER) return outputs::Integers;
  if (c == H5T_STRING) return rank == 0 ? outputs::Text : outputs::Texts;
  return 0;
}

std::string units_of(const format::h5::Reader& r, const std::string& path) {
  return r.has_attribute(path, "units") ? r.string_attribute(path, "units") : "";
}

bool units_allowed(std::string_view allowed, const std::string& units) {
  std::stringstream list{std::string(allowed)};
  for (std::string u; std::getline(list, u, '|');)
    if (u == units) return true;
  return allowed.empty() && units.empty();
}

void check_results(const std::string& file, Coverage& coverage) {
  INFO(file);
  const auto items = outputs::results_items();
  const format::h5::Reader reader(file);
  const hid_t h = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  REQUIRE(h >= 0);
  H5Walk walk;
  H5Ovisit2(h, H5_INDEX_NAME, H5_ITER_NATIVE, visit, &walk, H5O_INFO_BASIC);
  std::set<std::string> present;
  for (const auto& [path, type] : walk.objects) present.insert(path);
  auto check_always = [&](const std::string& concrete, const std::string& pattern) {
    for (const outputs::Item* child : always_under(items, pattern)) {
      const std::string name = last_name(child->path);
      if (name.front() == '<') {  // a list of named members: at least one
        bool any = false;
        for (const std::string& p : present) any = any || (parent_of(p) == concrete && outputs::find(items, p) == child);
        INFO("in " << concrete << ": no member " << child->path);
        CHECK(any);
      } else {
        INFO("missing " << concrete + "/" + name);
        CHECK(present.count(concrete + "/" + name) == 1);
      }
    }
  };
  check_always("", "");
  for (const auto& [path, type] : walk.objects) {
    INFO(path);
    const outputs::Item* item = outputs::find(items, path);
    CHECK(item != nullptr);
    if (!item) continue;
    coverage.seen.insert(std::string(item->path));
    if (type == H5O_TYPE_GROUP) {
      CHECK(item->type == outputs::Group);
      check_always(path, std::string(item->path));
    } else {
      CHECK((dataset_type(h, path) & item->type) != 0);
      CHECK(units_allowed(item->units, units_of(reader, path)));
    }
  }
  H5Fclose(h);
}

// ---------------------------------------------------------------- summary.json

unsigned json_type(const json& v) {
  switch (v.type()) {
    case json::value_t::null: return outputs::Null;
    case json::value_t::boolean: return outputs::Boolean;
    case json::value_t::number_integer:
    case json::value_t::number_unsigned: return outputs::Integer | outputs::Number;
    case json::value_t::number_float: return outputs::Number;
    case json::value_t::string: return outputs::String;
    case json::value_t::array: return outputs::Array;
    case json::value_t::object: return outputs::Object;
    default: return 0;
  }
}

void check_object(const json& object, const std::string& path, const std::string& pattern, Coverage& coverage) {
  const auto items = outputs::summary_items();
  for (const outputs::Item* child : always_under(items, pattern)) {
    const std::string name = last_name(child->path);
    if (name.front() == '<') continue;  // named members: as many as the scene has
    INFO("missing " << (path.empty() ? "" : path + ".") + name);
    CHECK(object.contains(name));
  }
  for (const auto& [key, value] : object.items()) {
    const std::string at = (path.empty() ? "" : path + ".") + key;
    INFO(at);
    const outputs::Item* item = outputs::find(items, at);
    CHECK(item != nullptr);
    if (!item) continue;
    coverage.seen.insert(std::string(item->path));
    CHECK((json_type(value) & item->type) != 0);
    if (value.is_object()) check_object(value, at, std::string(item->path), coverage);
    if (value.is_array())
      for (const json& entry : value)
        if (entry.is_object()) check_object(entry, at + "[]", std::string(item->path) + "[]", coverage);
  }
}

void check_summary(const std::string& file, Coverage& coverage) {
  INFO(file);
  std::ifstream in(file);
  const json summary = json::parse(in);
  check_object(summary, "", "", coverage);
}

/// The run's folder and its phases' folders, if any.
void check_run_folder(const std::string& folder, Coverage& coverage) {
  check_results(folder + "/results.h5", coverage);
  check_summary(folder + "/summary.json", coverage);
  const std::filesystem::path phases = std::filesystem::path(folder) / "phases";
  if (!std::filesystem::exists(phases)) return;
  for (const auto& phase : std::filesystem::directory_iterator(phases)) {
    if (std::filesystem::exists(phase.path() / "results.h5")) check_results((phase.path() / "results.h5").string(), coverage);
    if (std::filesystem::exists(phase.path() / "summary.json")) check_summary((phase.path() / "summary.json").string(), coverage);
  }
}

/// Two rigid spheres meeting by Hertz's law, a third hinged beside them, a reference value of 0.
std::string hertz_joint_scene() {
  return test::two_spheres(0.5, R"([[rigid_body]]
name = "c"
shape = "sphere"
radius = 0.01
density = 7850.0
position = [0.0, 0.1, 0.0]
[[joint]]
name = "hinge"
type = "revolute"
body = "c"
point = [0.0, 0.1, 0.0]
axis = [0.0, 0.0, 1.0]
[reference]
final_angular_velocity_rad_s = 0.0
)", "rtol = 1e-8\natol = 1e-13\n");
}

std::string read_text(const std::string& file) {
  std::ifstream in(file);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

}  // namespace

TEST_CASE("docs/outputs.md is the output tables' markdown, as isosid-run --describe-outputs prints it", "[runtime][outputs]") {
  CHECK(read_text(std::string(ISOSID_SOURCE_DIR) + "/docs/outputs.md") == outputs::markdown());
  const auto r = test::run_program(std::string(ISOSID_RUN_EXE) + " --describe-outputs");
  CHECK(r.exit_status == 0);
  CHECK(r.out == outputs::markdown());
}

TEST_CASE("the output tables match patterns by whole names", "[runtime][outputs][unit]") {
  const auto items = outputs::results_items();
  REQUIRE(outputs::find(items, "/bodies/sphere/q") != nullptr);
  CHECK(outputs::find(items, "/bodies/sphere/q")->path == "/bodies/<body>/q");
  CHECK(outputs::find(items, "/bodies/sphere/extra") == nullptr);
  CHECK(outputs::find(items, "/bodies/sphere") != nullptr);
  CHECK(outputs::find(items, "/bodies/a/b/q") == nullptr);  // a name is one segment
  const auto keys = outputs::summary_items();
  REQUIRE(outputs::find(keys, "contacts[].touches[].time_s") != nullptr);
  CHECK(outputs::find(keys, "contacts[].touches.time_s") == nullptr);
  CHECK(outputs::find(keys, "reference.peak_force_n.rel_error") != nullptr);
}

TEST_CASE("runs of every kind write what the output tables hold, and the tables hold nothing no run writes", "[runtime][outputs][outputs-coverage]") {
  const test::ScratchDir dir("output-layout");
  Coverage coverage;
  const std::string out = dir.path("out-s.scene.toml");
  // a flexible target: the sphere on the free beam, general (with point monitors on the beam)
  // and in gap space (impact modes)
  test::write_coarse_sphere_impactor(dir);
  std::ofstream(dir.path("beam.model.toml")) << test::free_beam_model();
  std::string monitors;
  for (const char* quantity : {"velocity", "position"})
    monitors += "[[monitor]]\nname = \"beam_" + std::string(quantity) + "\"\nbody = \"beam\"\nsurface = \"impact\"\nparameter = [0.5, 0.5]\n" +
                "quantity = \"" + quantity + "\"\n";
  REQUIRE(test::run_scene(dir, test::sphere_on_free_beam_scene("") + monitors).is_object());
  check_run_folder(out, coverage);
  REQUIRE(test::run_scene(dir, test::sphere_on_free_beam_scene("formulation = \"gap-space\"\n") + "[reference]\nsource = \"hertz\"\n").is_object());
  check_run_folder(out, coverage);
  // Hertz contacts, a joint
  REQUIRE(test::run_scene(dir, hertz_joint_scene()).is_object());
  check_run_folder(out, coverage);
  // scene A: the axisymmetric sphere's stress monitor and references, with a setting over the scene
  test::copy_model_file(dir, "sphere_hertz.scene.toml");
  test::copy_model_file(dir, "sphere_axisym.model.toml");
  const auto set = test::run_program("ISOSID_PREP=" + std::string(ISOSID_PREP_EXE) + " " + ISOSID_RUN_EXE + " -q " +
                                     dir.path("sphere_hertz.scene.toml") + " --set simulation.end_time=9e-5 -o " + dir.path("a"));
  INFO(set.err);
  REQUIRE(set.exit_status == 0);
  check_run_folder(dir.path("a"), coverage);
  // an adaptive run: its phases' folders too
  test::copy_model_file(dir, "sphere_axisym_thb.model.toml");
  REQUIRE(test::run_scene(dir, test::model_text("sphere_hertz_adaptive.scene.toml")).is_object());
  check_run_folder(out, coverage);

  for (const auto items : {outputs::results_items(), outputs::summary_items()})
    for (const outputs::Item& item : items) {
      INFO(item.path);
      CHECK(coverage.seen.count(std::string(item.path)) == (kNotWritten.count(std::string(item.path)) ? 0u : 1u));
    }
}

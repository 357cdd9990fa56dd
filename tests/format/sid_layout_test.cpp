// The layout table is the truth about SID files: a written SID holds exactly its items, the
// README shows exactly its markdown, and isosid-info --layout prints the same.
#include "isosid/format/sid_io.hpp"
#include "isosid/format/sid_layout.hpp"
#include "support/lumped_sid.hpp"
#include "support/run_program.hpp"

#include <catch2/catch.hpp>
#include <hdf5.h>

#include <fstream>
#include <regex>
#include <set>
#include <sstream>

using namespace isosid;
namespace layout = format::layout;

namespace {

/// Every group, dataset and attribute of an HDF5 file, as "path" or "path@attribute".
/// The `units` and `order` attributes every dataset / Taylor group carries are left out.
std::set<std::string> hdf5_objects(const std::string& file) {
  std::set<std::string> found;
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  REQUIRE(f >= 0);
  auto visit = [](hid_t root, const char* name, const H5O_info_t*, void* data) -> herr_t {
    auto& out = *static_cast<std::set<std::string>*>(data);
    const std::string path = std::string(name) == "." ? "/" : "/" + std::string(name);
    out.insert(path);
    auto attribute = [](hid_t, const char* attr, const H5A_info_t*, void* d) -> herr_t {
      auto& [set, object] = *static_cast<std::pair<std::set<std::string>*, std::string>*>(d);
      if (std::string(attr) != "units" && std::string(attr) != "order") set->insert(object + "@" + attr);
      return 0;
    };
    std::pair<std::set<std::string>*, std::string> context{&out, path};
    H5Aiterate_by_name(root, name, H5_INDEX_NAME, H5_ITER_INC, nullptr, attribute, &context, H5P_DEFAULT);
    return 0;
  };
  H5Ovisit2(f, H5_INDEX_NAME, H5_ITER_INC, visit, &found, H5O_INFO_BASIC);
  H5Fclose(f);
  found.erase("/");
  return found;
}

/// An item's path (and attribute) as a pattern: "<name>" any list member, "<d>" a direction.
std::regex item_pattern(const layout::Item& item) {
  std::string p = std::regex_replace(std::string(item.path), std::regex("<name>"), "[^/]+");
  p = std::regex_replace(p, std::regex("<d>"), "[0-9]+");
  if (!item.attribute.empty()) p += "@" + std::string(item.attribute);
  return std::regex(p);
}

/// A Taylor group's members (M0, M1) count as the group's.
std::string taylor_owner(const std::string& object) {
  static const std::regex member("(.*)/M[01]");
  std::smatch m;
  return std::regex_match(object, m, member) ? m[1].str() : object;
}

}  // namespace

TEST_CASE("a written SID holds exactly the items of the layout table", "[format][layout]") {
  const test::ScratchDir dir("layout");
  format::Sid sid = test::lumped_sid(test::random_lumped_body(12, 5, 4));
  sid.discretization = format::Discretization{Eigen::VectorXi::Constant(2, 8), Eigen::VectorXi::Constant(2, 20), 60, 1.5e-4};
  // as a body of two patches: materials, interfaces, and the patch of each surface and line
  sid.patches = {{"a", sid.material, {"xi1 b.xi0"}}, {"b", {7e10, 0.33, 2700}, {"xi0 a.xi1"}}};
  sid.contact_surfaces[0].patch = "a";
  sid.contact_surfaces[0].in_interface = Eigen::Vector4i(1, 1, 1, 0);  // as reduced by Craig-Bampton
  sid.stress_recovery[0].patch = "b";
  sid.refmod.section_translation = Eigen::MatrixXd::Constant(sid.nq(), 3, 0.25);  // a beam's modes' shares
  sid.refmod.long_axis = Eigen::Vector3d::UnitX();
  REQUIRE(sid.transfer);
  REQUIRE(!sid.master_patches.empty());
  REQUIRE(!sid.stress_recovery.empty());
  const std::string file = dir.path("all.sid.h5");
  format::write_sid(sid, file);

  const format::Sid back = format::read_sid(file);
  REQUIRE(back.patches.size() == 2);
  CHECK(back.patches[1].material.density == 2700);
  CHECK(back.patches[0].interfaces == std::vector<std::string>{"xi1 b.xi0"});
  CHECK(back.refmod.section_translation == sid.refmod.section_translation);
  CHECK(back.refmod.long_axis == sid.refmod.long_axis);
  CHECK(back.contact_surfaces[0].patch == "a");
  CHECK(back.contact_surfaces[0].in_interface == sid.contact_surfaces[0].in_interface);
  CHECK(back.stress_recovery[0].patch == "b");

  const std::set<std::string> objects = hdf5_objects(file);
  std::set<const layout::Item*> seen;
  for (const std::string& object : objects) {
    const layout::Item* match = nullptr;
    for (const layout::Item* item : layout::items())
      if (std::regex_match(taylor_owner(object), item_pattern(*item))) match = item;
    INFO(object);
    CHECK(match != nullptr);
    seen.insert(match);
  }
  // This SID has every optional part, so every item of the table occurs in it.
  for (const layout::Item* item : layout::items()) {
    INFO(item->path << " " << item->attribute);
    CHECK(seen.count(item) == 1);
  }
}

TEST_CASE("format/README.md shows the layout table as generated", "[format][layout]") {
  std::ifstream in(std::string(ISOSID_SOURCE_DIR) + "/format/README.md");
  REQUIRE(in);
  std::stringstream text;
  text << in.rdbuf();
  const std::string readme = text.str();
  const std::string begin_marker = "<!-- layout table:", end_marker = "<!-- end of layout table -->";
  const auto begin = readme.find(begin_marker);
  REQUIRE(begin != std::string::npos);
  const auto table_start = readme.find('\n', begin) + 1;
  const auto end = readme.find(end_marker, table_start);
  REQUIRE(end != std::string::npos);
  CHECK(readme.substr(table_start, end - table_start) == layout::markdown_table());
}

TEST_CASE("isosid-info --layout prints the layout table", "[format][layout][tools]") {
  const auto r = test::run_program(std::string(ISOSID_INFO_EXE) + " --layout");
  CHECK(r.exit_status == 0);
  CHECK(r.out == layout::markdown_table());
}

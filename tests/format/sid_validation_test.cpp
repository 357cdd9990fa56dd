// The reader refuses damaged or inconsistent SID files with an InputError that names the
// file, the dataset and the problem; it never crashes.
#include "isosid/format/error.hpp"
#include "isosid/format/sid_io.hpp"
#include "support/bad_input_cases.hpp"
#include "support/hdf5_tamper.hpp"
#include "support/lumped_sid.hpp"
#include "support/run_program.hpp"

#include <catch2/catch.hpp>
#include <functional>
#include <filesystem>
#include <fstream>

using namespace isosid;

namespace {
/// Writes a valid SID, applies `damage`, and returns the reader's message (empty if it accepted).
template <class Damage>
std::string message_after(const test::ScratchDir& dir, Damage damage) {
  const std::string file = dir.path("damaged.sid.h5");
  format::write_sid(test::lumped_sid(test::random_lumped_body(10, 4, 11)), file);
  damage(file);
  try {
    format::read_sid(file);
  } catch (const format::InputError& e) {
    CHECK(std::string(e.what()).find('\n') == std::string::npos);  // one line
    CHECK(e.file() == file);
    return e.what();
  }
  return "";
}

/// tests/bad_inputs/sids.toml: its cases of damage done to a valid SID.
toml::table damaged_sids() {
  toml::table t = test::read_bad_inputs("sids.toml");
  REQUIRE(t["case"].as_array());
  return t;
}

/// A matrix of doubles given by rows.
Eigen::MatrixXd matrix_of(const toml::array& rows) {
  const Eigen::Index n = Eigen::Index(rows.size()), m = Eigen::Index(rows.get(0)->as_array()->size());
  Eigen::MatrixXd a(n, m);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < m; ++j) a(i, j) = rows.get(std::size_t(i))->as_array()->get(std::size_t(j))->value<double>().value();
  return a;
}

/// Does to `file` the damage a case of sids.toml describes.
void damage(const std::string& file, const toml::table& c) {
  const std::string kind = c["damage"].value_or(std::string()), dataset = c["dataset"].value_or(std::string());
  const toml::node_view<const toml::node> value = c["value"];
  if (kind == "replace_dataset") {
    test::replace_dataset(file, dataset, matrix_of(*value.as_array()));
  } else if (kind == "replace_scalar") {
    test::replace_scalar(file, dataset, value.value<double>().value());
  } else if (kind == "replace_integer") {
    test::replace_integer(file, dataset, value.value<long long>().value());
  } else if (kind == "replace_integers") {
    Eigen::VectorXi v(Eigen::Index(value.as_array()->size()));
    for (Eigen::Index i = 0; i < v.size(); ++i) v(i) = value.as_array()->get(std::size_t(i))->value<int>().value();
    test::replace_integers(file, dataset, v);
  } else if (kind == "remove") {
    test::remove_object(file, dataset);
  } else if (kind == "set_attribute") {
    const std::string name = c["attribute"].value_or(std::string());
    if (value.is_string()) test::set_attribute(file, dataset, name, value.value<std::string>().value());
    else test::set_attribute(file, dataset, name, value.value<double>().value());
  } else if (kind == "flip_bit") {
    test::flip_stored_data_bit(file, dataset);
  } else {
    FAIL("sids.toml: unknown damage '" << kind << "'");
  }
}
}  // namespace

TEST_CASE("reader refuses each kind of bad SID with a message naming the dataset", "[format][validation]") {
  const test::ScratchDir dir("validation");
  using Catch::Matchers::Contains;

  SECTION("each damage of tests/bad_inputs/sids.toml") {
    const toml::table cases = damaged_sids();
    for (const toml::node& node : *cases["case"].as_array()) {
      const toml::table& c = *node.as_table();
      INFO(c["name"].value_or(std::string()));
      const auto m = message_after(dir, [&](const std::string& f) { damage(f, c); });
      REQUIRE(c["expect"].as_array());
      for (const toml::node& expected : *c["expect"].as_array()) CHECK_THAT(m, Contains(expected.value_or(std::string("(not a text)"))));
    }
  }
  SECTION("not an HDF5 file") {
    const std::string file = dir.path("text.sid.h5");
    std::ofstream(file) << "this is not HDF5\n";
    CHECK_THROWS_WITH(format::read_sid(file), Contains(file) && Contains("not an HDF5 file"));
  }
  SECTION("truncated file") {
    const std::string file = dir.path("whole.sid.h5"), cut = dir.path("cut.sid.h5");
    format::write_sid(test::lumped_sid(test::random_lumped_body(10, 4, 11)), file);
    for (double fraction : {0.1, 0.5, 0.9, 0.999}) {
      test::truncate_copy(file, cut, fraction);
      CHECK_THROWS_AS(format::read_sid(cut), format::InputError);
    }
  }
  SECTION("missing file") {
    CHECK_THROWS_WITH(format::read_sid(dir.path("nope.sid.h5")), Contains("file not found"));
  }
}

TEST_CASE("non-positive mass and other physics checks are refused before writing", "[format][validation]") {
  const test::ScratchDir dir("physics");
  using Catch::Matchers::Contains;
  format::Sid s = test::lumped_sid(test::random_lumped_body(10, 4, 5));
  const std::string file = dir.path("x.sid.h5");

  SECTION("mass") {
    s.refmod.mass = -1;
    CHECK_THROWS_WITH(format::write_sid(s, file), Contains("/refmod/mass") && Contains("must be positive"));
  }
  SECTION("NaN in a node") {
    s.nodes[0].phi(1, 1) = std::nan("");
    CHECK_THROWS_WITH(format::write_sid(s, file), Contains("/nodes/tip/phi") && Contains("non-finite"));
  }
  SECTION("contact normal not unit") {
    s.contact_surfaces[0].normal(0, 0) += 0.5;
    CHECK_THROWS_WITH(format::write_sid(s, file), Contains("/contact/face/normal") && Contains("unit"));
  }
  SECTION("M1 with the wrong number of slices") {
    s.J.M1.pop_back();
    CHECK_THROWS_WITH(format::write_sid(s, file), Contains("/terms/J/M1") && Contains("expected nq = 4"));
  }
  SECTION("frequencies out of order") {
    s.refmod.frequencies_hz.reverseInPlace();
    CHECK_THROWS_WITH(format::write_sid(s, file), Contains("/refmod/frequencies_hz") && Contains("not ascending"));
  }
  SECTION("contact element index beyond the body's elements") {
    s.discretization = format::Discretization{};
    s.discretization->elements_per_level = Eigen::VectorXi::Constant(1, 8);
    s.discretization->functions_per_level = Eigen::VectorXi::Constant(1, 20);
    s.discretization->free_dofs = 40;
    s.contact_surfaces[0].element(1) = 1 << 30;
    CHECK_THROWS_WITH(format::write_sid(s, file), Contains("/contact/face/element") && Contains("beyond the body's 8 elements"));
  }
  SECTION("interface flags that are not 0 or 1, or not one per point") {
    s.contact_surfaces[0].in_interface = Eigen::Vector4i(1, 0, 2, 1);
    CHECK_THROWS_WITH(format::write_sid(s, file), Contains("/contact/face/in_interface") && Contains("must be 0 or 1"));
    s.contact_surfaces[0].in_interface = Eigen::Vector3i(1, 0, 1);
    CHECK_THROWS_WITH(format::write_sid(s, file), Contains("/contact/face/in_interface") && Contains("one entry per point"));
  }
  SECTION("contact point outside its side's parameter range") {
    s.contact_surfaces[0].parameter(2, 0) = 1.7;  // the side spans xi in [0, 1]
    CHECK_THROWS_WITH(format::write_sid(s, file), Contains("/contact/face/parameter") && Contains("point 2: xi = 1.7") &&
                                                       Contains("outside the side's range [0, 1] (/master/face)"));
  }
  SECTION("contact point off its side") {
    s.contact_surfaces[0].parameter(3, 2) = 0.25;  // zeta0: every point has zeta = 0
    CHECK_THROWS_WITH(format::write_sid(s, file), Contains("/contact/face/parameter") && Contains("point 3 is not on side zeta0"));
  }
  SECTION("contact side that is not a side") {
    s.contact_surfaces[0].side = "bottom";
    CHECK_THROWS_WITH(format::write_sid(s, file), Contains("/contact/face") && Contains("'bottom' is not a side"));
  }
  SECTION("a contact surface on a patch the SID does not have") {
    s.patches = {{"a", s.material, {}}, {"b", s.material, {}}};
    s.contact_surfaces[0].patch = "c";
    CHECK_THROWS_WITH(format::write_sid(s, file), Contains("/contact/face") && Contains("names patch 'c'"));
  }
  SECTION("an interface that names no patch side") {
    s.patches = {{"a", s.material, {"xi1 nowhere.xi0"}}, {"b", s.material, {}}};
    CHECK_THROWS_WITH(format::write_sid(s, file), Contains("/patches/a/interfaces") && Contains("'xi1 nowhere.xi0'"));
  }
  SECTION("a patch material out of range") {
    s.patches = {{"a", {2e11, 0.7, 7800}, {}}};
    CHECK_THROWS_WITH(format::write_sid(s, file), Contains("/patches/a/poisson_ratio"));
  }
  SECTION("Poisson ratio") {
    s.material.poisson_ratio = 0.5;
    CHECK_THROWS_WITH(format::write_sid(s, file), Contains("/body/poisson_ratio"));
  }
  CHECK_FALSE(std::filesystem::exists(file));
}

TEST_CASE("a dataset of the wrong rank is refused with its shape", "[format][validation]") {
  const test::ScratchDir dir("rank");
  const std::string file = dir.path("m.sid.h5");
  format::write_sid(test::lumped_sid(test::random_lumped_body(10, 4, 5)), file);
  test::replace_dataset(file, "/refmod/mass", Eigen::MatrixXd::Constant(1, 1, 2.0));
  CHECK_THROWS_WITH(format::read_sid(file), Catch::Matchers::Contains("/refmod/mass") &&
                                                Catch::Matchers::Contains("expected a scalar, found shape (1, 1)"));
}

TEST_CASE("isosid-info exits 2 with one line for every damaged SID", "[format][validation][tools]") {
  const test::ScratchDir dir("damaged-cli");
  const std::vector<std::function<void(const std::string&)>> damages = {
      [](const std::string& f) { test::replace_integer(f, "/isosid/version", 2); },
      [](const std::string& f) { test::remove_object(f, "/terms/Me/M0"); },
      [](const std::string& f) { test::replace_dataset(f, "/terms/Ke/M0", Eigen::MatrixXd::Identity(2, 2)); },
      [](const std::string& f) { test::replace_scalar(f, "/refmod/mass", std::nan("")); },
      [](const std::string& f) { test::replace_scalar(f, "/refmod/mass", -1.0); },
      [](const std::string& f) {
        Eigen::MatrixXd me = Eigen::MatrixXd::Identity(4, 4);
        me(0, 1) = 1;
        test::replace_dataset(f, "/terms/Me/M0", me);
      },
      [&](const std::string& f) { test::truncate_copy(f, f + ".cut", 0.6), std::filesystem::rename(f + ".cut", f); },
  };
  for (std::size_t k = 0; k < damages.size(); ++k) {
    const std::string file = dir.path("d" + std::to_string(k) + ".sid.h5");
    format::write_sid(test::lumped_sid(test::random_lumped_body(10, 4, 11)), file);
    damages[k](file);
    const auto r = test::run_program(std::string(ISOSID_INFO_EXE) + " " + file);
    INFO("damage " << k << ": " << r.err);
    CHECK(r.exit_status == 2);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK(r.err.find(file) != std::string::npos);
  }
}

TEST_CASE("interface flags present but empty, or other than 0 and 1, are refused", "[format][validation]") {
  // an empty dataset would read as absent (as in a SID of another reduction), which the
  // validator lets pass: the reader refuses it
  using Catch::Matchers::Contains;
  const test::ScratchDir dir("interface-flags");
  const std::string file = dir.path("flags.sid.h5");
  format::Sid sid = test::lumped_sid(test::random_lumped_body(10, 4, 11));
  sid.contact_surfaces[0].in_interface = Eigen::Vector4i(1, 1, 0, 0);
  const std::vector<std::pair<Eigen::VectorXi, std::string>> cases{{Eigen::VectorXi(0), "one entry per point expected"},
                                                                    {Eigen::Vector4i(1, 2, 0, 0), "entries must be 0 or 1"}};
  for (const auto& [flags, problem] : cases) {
    INFO(problem);
    format::write_sid(sid, file);
    test::replace_integers(file, "/contact/face/in_interface", flags);
    CHECK_THROWS_WITH(format::read_sid(file), Contains("/contact/face/in_interface") && Contains(problem));
  }
}

// A model or scene file that exists but is no regular file (a FIFO, a folder, a symbolic-link
// loop) is refused at once and named for what it is, not reported missing or waited on.
#include "isosid/common/toml_fields.hpp"
#include "isosid/format/error.hpp"
#include "support/run_program.hpp"

#include <catch2/catch.hpp>
#include <chrono>
#include <filesystem>
#include <sys/stat.h>

using namespace isosid;
namespace fs = std::filesystem;

TEST_CASE("TOML files that are FIFOs, folders or link loops are named for what they are", "[common][toml]") {
  const test::ScratchDir dir("toml-file-kind");
  REQUIRE(::mkfifo(dir.path("f.scene.toml").c_str(), 0600) == 0);
  fs::create_directory(dir.path("d.scene.toml"));
  fs::create_symlink("b.toml", dir.path("a.toml"));
  fs::create_symlink("a.toml", dir.path("b.toml"));
  const auto start = std::chrono::steady_clock::now();
  CHECK_THROWS_WITH(common::parse_toml_file(dir.path("f.scene.toml")), dir.path("f.scene.toml") + ": is a FIFO, not a file");
  CHECK_THROWS_WITH(common::parse_toml_file(dir.path("d.scene.toml")), dir.path("d.scene.toml") + ": is a directory, not a file");
  CHECK_THROWS_WITH(common::parse_toml_file(dir.path("a.toml")), dir.path("a.toml") + ": too many levels of symbolic links");
  CHECK_THROWS_WITH(common::parse_toml_file(dir.path("none.toml")), dir.path("none.toml") + ": file not found");
  CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(1));  // the FIFO was not opened
}

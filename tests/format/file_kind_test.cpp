// Paths that exist but are no regular file (FIFOs, folders, sockets, symbolic-link loops and
// dangling links) are named for what they are, as inputs and as outputs; a FIFO given as a
// SID is refused at once instead of blocking its reader.
#include "isosid/format/error.hpp"
#include "isosid/format/file_kind.hpp"
#include "isosid/format/sid_io.hpp"
#include "support/run_program.hpp"

#include <catch2/catch.hpp>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

using namespace isosid;
using Catch::Matchers::Contains;
namespace fs = std::filesystem;

namespace {
/// A folder holding one of each kind of path the programs may be given.
struct SpecialFiles {
  test::ScratchDir dir{"file-kind"};
  SpecialFiles() {
    std::ofstream(dir.path("regular")) << "text";
    REQUIRE(::mkfifo(dir.path("fifo").c_str(), 0600) == 0);
    fs::create_directory(dir.path("folder"));
    fs::create_symlink("loop_b", dir.path("loop_a"));
    fs::create_symlink("loop_a", dir.path("loop_b"));
    fs::create_symlink("nothing", dir.path("dangling"));
    fs::create_symlink("regular", dir.path("link_to_regular"));
    fs::create_symlink("fifo", dir.path("link_to_fifo"));
  }
};
}  // namespace

TEST_CASE("inputs that are no regular file are named for what they are", "[format][file-kind]") {
  const SpecialFiles f;
  CHECK(format::input_file_problem(f.dir.path("regular")).empty());
  CHECK(format::input_file_problem(f.dir.path("link_to_regular")).empty());
  CHECK(format::input_file_problem(f.dir.path("missing")) == "file not found");
  CHECK(format::input_file_problem(f.dir.path("regular/below")) == "file not found");
  CHECK(format::input_file_problem(f.dir.path("fifo")) == "is a FIFO, not a file");
  CHECK(format::input_file_problem(f.dir.path("link_to_fifo")) == "is a FIFO, not a file");
  CHECK(format::input_file_problem(f.dir.path("folder")) == "is a directory, not a file");
  CHECK(format::input_file_problem(f.dir.path("loop_a")) == "too many levels of symbolic links");
  CHECK(format::input_file_problem(f.dir.path("dangling")) == "is a symbolic link to a missing file");
  CHECK_THROWS_WITH(format::require_input_file(f.dir.path("fifo")), f.dir.path("fifo") + ": is a FIFO, not a file");
}

TEST_CASE("a socket is no input and no output", "[format][file-kind]") {
  const test::ScratchDir dir("file-kind-socket");
  const std::string path = dir.path("socket");
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  REQUIRE(path.size() < sizeof address.sun_path);
  std::strcpy(address.sun_path, path.c_str());
  const int s = ::socket(AF_UNIX, SOCK_STREAM, 0);
  REQUIRE(s >= 0);
  REQUIRE(::bind(s, reinterpret_cast<const sockaddr*>(&address), sizeof address) == 0);
  CHECK(format::input_file_problem(path) == "is a socket, not a file");
  CHECK(format::output_file_problem(path) == "is a socket, not a file");
  ::close(s);
}

TEST_CASE("an output may be nothing yet or a regular file, nothing else", "[format][file-kind]") {
  const SpecialFiles f;
  for (const char* fine : {"missing", "regular", "link_to_regular"}) CHECK(format::output_file_problem(f.dir.path(fine)).empty());
  CHECK(format::output_file_problem(f.dir.path("fifo")) == "is a FIFO, not a file");
  CHECK(format::output_file_problem(f.dir.path("link_to_fifo")) == "is a FIFO, not a file");
  CHECK(format::output_file_problem(f.dir.path("folder")) == "is a directory, not a file");
  CHECK(format::output_file_problem(f.dir.path("loop_a")) == "too many levels of symbolic links");
  CHECK(format::output_file_problem(f.dir.path("dangling")) == "is a symbolic link to a missing file");
  CHECK_THROWS_AS(format::require_output_file(f.dir.path("fifo")), format::InputError);
}

TEST_CASE("a SID that is a FIFO, a folder or a link loop is refused at once, not probed", "[format][file-kind]") {
  const SpecialFiles f;
  for (const char* name : {"fifo", "link_to_fifo", "folder", "loop_a"}) {
    INFO(name);
    const auto start = std::chrono::steady_clock::now();
    CHECK_THROWS_AS(format::read_sid(f.dir.path(name)), format::InputError);
    CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(2));  // the probe would wait 10 s on a FIFO
  }
  CHECK_THROWS_WITH(format::read_sid(f.dir.path("fifo")), Contains("is a FIFO, not a file"));
}

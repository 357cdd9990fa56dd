// An interrupted or failed SID write leaves nothing at the target path (and keeps an older
// file); an output replaces nothing but a regular file.
#include "isosid/format/atomic_output.hpp"
#include "isosid/format/sid_io.hpp"
#include "support/lumped_sid.hpp"
#include "support/run_program.hpp"

#include <catch2/catch.hpp>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace isosid;
namespace fs = std::filesystem;

namespace {
std::size_t files_in(const std::string& dir) {
  return std::size_t(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}
}  // namespace

TEST_CASE("a write that fails part-way leaves no file and no temporary behind", "[format][atomic]") {
  const test::ScratchDir dir("atomic");
  const std::string target = dir.path("body.sid.h5");
  format::WriteOptions abort_at_contact;
  abort_at_contact.on_part = [](const std::string& part) {
    if (part == "contact") throw std::runtime_error("disk full (simulated)");
  };
  const format::Sid sid = test::lumped_sid(test::random_lumped_body(10, 4, 2));
  CHECK_THROWS_WITH(format::write_sid(sid, target, abort_at_contact), "disk full (simulated)");
  CHECK_FALSE(fs::exists(target));
  CHECK(files_in(dir.dir()) == 0);
}

TEST_CASE("a failed rewrite keeps the previous file intact", "[format][atomic]") {
  const test::ScratchDir dir("atomic-keep");
  const std::string target = dir.path("body.sid.h5");
  const format::Sid old_sid = test::lumped_sid(test::random_lumped_body(10, 4, 2));
  format::write_sid(old_sid, target);
  format::WriteOptions abort_at_terms;
  abort_at_terms.on_part = [](const std::string& part) {
    if (part == "terms") throw std::runtime_error("interrupted");
  };
  CHECK_THROWS(format::write_sid(test::lumped_sid(test::random_lumped_body(10, 4, 9)), target, abort_at_terms));
  const format::Sid back = format::read_sid(target);
  CHECK(back.Ct.M0 == old_sid.Ct.M0);
  CHECK(files_in(dir.dir()) == 1);
}

TEST_CASE("a writer killed mid-write leaves nothing at the target path", "[format][atomic]") {
  const test::ScratchDir dir("atomic-kill");
  const std::string target = dir.path("body.sid.h5");
  const format::Sid sid = test::lumped_sid(test::random_lumped_body(40, 12, 3));
  int ready[2];
  REQUIRE(::pipe(ready) == 0);
  const pid_t child = ::fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    format::WriteOptions stall;
    stall.on_part = [&](const std::string& part) {
      if (part == "contact") {  // half the file is written: tell the parent, then wait to be killed
        const char byte = 1;
        (void)!::write(ready[1], &byte, 1);
        ::pause();
      }
    };
    format::write_sid(sid, target, stall);
    ::_exit(0);
  }
  char byte = 0;
  REQUIRE(::read(ready[0], &byte, 1) == 1);
  ::kill(child, SIGKILL);
  int status = 0;
  ::waitpid(child, &status, 0);
  ::close(ready[0]);
  ::close(ready[1]);
  CHECK(WIFSIGNALED(status));
  CHECK_FALSE(fs::exists(target));
}

TEST_CASE("writing into a missing folder is a one-line input error", "[format][atomic]") {
  const format::Sid sid = test::lumped_sid(test::random_lumped_body(6, 2, 2));
  CHECK_THROWS_WITH(format::write_sid(sid, "/nonexistent-isosid-folder/x.sid.h5"),
                    Catch::Matchers::Contains("output folder") && Catch::Matchers::Contains("does not exist"));
}

TEST_CASE("a signal while an output is being written removes its temporary file", "[format][atomic][signal]") {
  // in a child: an output half written to its temporary file, then SIGTERM; the handler of
  // remove_temporaries_on_signals must unlink it and exit 128 + 15 (what isosid-prep does when
  // killed midway; the kill cannot be timed to land in its write from outside)
  const test::ScratchDir dir("atomic-signal");
  const std::string target = dir.path("out.sid.h5");
  const pid_t child = fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    format::remove_temporaries_on_signals("test");
    format::AtomicOutput out(target);
    std::ofstream(out.temp_path()) << "half of it";
    std::raise(SIGTERM);
    _exit(0);  // not reached
  }
  int status = 0;
  REQUIRE(waitpid(child, &status, 0) == child);
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 128 + SIGTERM);
  CHECK(std::filesystem::is_empty(dir.dir()));  // neither the target nor a temporary file
}

TEST_CASE("an output never replaces a FIFO, a folder or a dangling link, and writes through a link to a file", "[format][atomic]") {
  const test::ScratchDir dir("atomic-special");
  REQUIRE(::mkfifo(dir.path("fifo").c_str(), 0600) == 0);
  fs::create_symlink("fifo", dir.path("link_to_fifo"));
  fs::create_symlink("nothing", dir.path("dangling"));
  fs::create_directory(dir.path("folder"));
  for (const char* name : {"fifo", "link_to_fifo", "dangling", "folder"}) {
    INFO(name);
    CHECK_THROWS_WITH(format::write_text_atomically(dir.path(name), "text"),
                      Catch::Matchers::Contains("an output replaces only a regular file"));
  }
  CHECK(fs::is_fifo(dir.path("fifo")));
  CHECK(fs::is_symlink(dir.path("link_to_fifo")));
  CHECK(fs::is_symlink(dir.path("dangling")));
  CHECK(fs::is_directory(dir.path("folder")));

  std::ofstream(dir.path("real")) << "old";
  fs::create_symlink("real", dir.path("link_to_real"));
  format::write_text_atomically(dir.path("link_to_real"), "new");
  CHECK(fs::is_symlink(dir.path("link_to_real")));
  std::ifstream real(dir.path("real"));
  CHECK(std::string(std::istreambuf_iterator<char>(real), {}) == "new");
  CHECK(files_in(dir.dir()) == 6);  // no temporary file left
}

TEST_CASE("a FIFO that appears at the target while the output is written is not replaced", "[format][atomic]") {
  const test::ScratchDir dir("atomic-late-fifo");
  const std::string target = dir.path("out.txt");
  format::AtomicOutput out(target);
  std::ofstream(out.temp_path()) << "text";
  REQUIRE(::mkfifo(target.c_str(), 0600) == 0);
  CHECK_THROWS_WITH(out.commit(), Catch::Matchers::Contains("is a FIFO, not a file"));
  CHECK(fs::is_fifo(target));
}

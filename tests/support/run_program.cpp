// Running programs and scratch folders for tests; see run_program.hpp.
#include "support/run_program.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

namespace isosid::test {
namespace fs = std::filesystem;

ScratchDir::ScratchDir(const std::string& label) {
  std::random_device rd;
  dir_ = (fs::temp_directory_path() / ("isosid-" + label + "-" + std::to_string(::getpid()) + "-" + std::to_string(rd())))
             .string();
  fs::create_directories(dir_);
}

ScratchDir::~ScratchDir() {
  std::error_code ec;
  fs::remove_all(dir_, ec);
}

ProgramResult run_program(const std::string& command) {
  const ScratchDir scratch("run");
  const std::string out = scratch.path("out"), err = scratch.path("err");
  ProgramResult r;
  const int status = std::system((command + " >" + out + " 2>" + err).c_str());
  r.exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  auto slurp = [](const std::string& p) {
    std::ifstream f(p);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
  };
  r.out = slurp(out);
  r.err = slurp(err);
  return r;
}

}  // namespace isosid::test

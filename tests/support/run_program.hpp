// Test support: run a program, capture its exit status and output, and make scratch folders.
#pragma once
#include <string>

namespace isosid::test {

struct ProgramResult {
  int exit_status = -1;
  std::string out, err;
};

/// Runs `command` through the shell, capturing stdout and stderr separately.
ProgramResult run_program(const std::string& command);

/// A fresh, empty folder under the system's temporary directory, removed on destruction.
class ScratchDir {
public:
  explicit ScratchDir(const std::string& label);
  ~ScratchDir();
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  std::string path(const std::string& name) const { return dir_ + "/" + name; }
  const std::string& dir() const { return dir_; }

private:
  std::string dir_;
};

}  // namespace isosid::test

// Command-line parsing shared by the isosid programs: help exits 0, a usage error exits 2
// with one line (the convention for bad input).
#pragma once
#include "isosid/common/cli_guard.hpp"

#include <CLI/CLI.hpp>
#include <iostream>
#include <optional>

namespace isosid::common {

/// Parses argv; returns an exit status if the program should stop now (help or usage error).
inline std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) {
      std::cout << app.help();
      return 0;
    }
    std::cerr << app.get_name() << ": error: " << e.what() << " (see --help)\n";
    return kExitBadInput;
  }
  return std::nullopt;
}

}  // namespace isosid::common

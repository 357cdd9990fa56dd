// Command-line parsing shared by the isosid programs: help and --version exit 0, a usage
// error exits 2 with one line (the convention for bad input).
#pragma once
#include "isosid/common/cli_guard.hpp"
#include "isosid/common/version.hpp"

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <string>

namespace isosid::common {

/// For tolerances: a finite number >= 0. CLI11's range checks let "nan" through (every
/// comparison with it is false), and print "inf"'s refusal against a 310-digit bound.
inline const CLI::Validator kFiniteNonNegative{[](std::string& text) {
                                                 char* end = nullptr;
                                                 const double value = std::strtod(text.c_str(), &end);
                                                 if (text.empty() || *end != '\0' || !std::isfinite(value) || value < 0)
                                                   return "must be a finite number >= 0, not '" + text + "'";
                                                 return std::string();
                                               },
                                               "FINITE >= 0"};

/// Adds --version and parses argv; returns an exit status if the program should stop now
/// (help, version or usage error).
inline std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv) {
  app.set_version_flag("--version", version_line(app.get_name()), "print the program's version and exit");
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForVersion& e) {
    std::cout << e.what() << "\n";
    return 0;
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

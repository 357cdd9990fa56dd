// Writes the lumped-mass example SID used by the tests, so a user can inspect the format
// (`scripts/demo` does this until the preprocessor writes real bodies).
#include "isosid/format/cli_guard.hpp"
#include "isosid/format/sid_io.hpp"
#include "support/lumped_sid.hpp"

#include <iostream>

int main(int argc, char** argv) {
  return isosid::format::run_guarded("isosid-example-sid", [&] {
    if (argc != 2) {
      std::cerr << "usage: isosid-example-sid OUT.sid.h5\n";
      return isosid::format::kExitBadInput;
    }
    isosid::format::write_sid(isosid::test::lumped_sid(isosid::test::random_lumped_body(24, 8, 1)), argv[1]);
    return 0;
  });
}

// Bad inputs kept as data in tests/bad_inputs: files of cases, each a base text (a valid model or
// scene the test names), edited, and the message a program must refuse it with (sids.toml, damage
// done to a SID file, is read by the SID reader's test).
#pragma once
#include <toml++/toml.h>

#include <map>
#include <string>
#include <vector>

namespace isosid::test {

struct BadInputCase {
  std::string label;     ///< "<file> case N", for the test's report
  std::string text;      ///< the edited input
  std::string expected;  ///< what the one line of the refusal must contain
};

/// tests/bad_inputs/`file`, parsed; throws std::runtime_error naming it if it does not parse.
toml::table read_bad_inputs(const std::string& file);

/// The cases of tests/bad_inputs/`file`. A case names its base by `base` (else `default_base`):
/// a text of `bases`, or of the file's own [base] table. It replaces the first occurrence of
/// each `edits` pair's first string by its second, in order, and appends `append`. Throws
/// std::runtime_error for a file it cannot read, a base it does not find, or an edit whose
/// string the text does not hold.
std::vector<BadInputCase> bad_input_cases(const std::string& file, const std::map<std::string, std::string>& bases,
                                          const std::string& default_base);

}  // namespace isosid::test

// Bad inputs kept as data; see bad_input_cases.hpp.
#include "support/bad_input_cases.hpp"

#include <stdexcept>

namespace isosid::test {

namespace {
std::string bad_inputs_path(const std::string& file) { return std::string(ISOSID_BAD_INPUTS_DIR) + "/" + file; }
}  // namespace

toml::table read_bad_inputs(const std::string& file) {
  try {
    return toml::parse_file(bad_inputs_path(file));
  } catch (const toml::parse_error& e) {
    throw std::runtime_error(bad_inputs_path(file) + ": " + std::string(e.description()));
  }
}

std::vector<BadInputCase> bad_input_cases(const std::string& file, const std::map<std::string, std::string>& bases,
                                          const std::string& default_base) {
  const std::string path = bad_inputs_path(file);
  const toml::table table = read_bad_inputs(file);
  const toml::array* cases = table["case"].as_array();
  if (!cases || cases->empty()) throw std::runtime_error(path + ": no [[case]]");
  std::vector<BadInputCase> out;
  for (std::size_t i = 0; i < cases->size(); ++i) {
    BadInputCase result;
    result.label = file + " case " + std::to_string(i + 1);
    const auto fail = [&](const std::string& problem) { throw std::runtime_error(path + ": " + result.label + ": " + problem); };
    if (!cases->get(i)->is_table()) fail("not a table");
    const toml::table& c = *cases->get(i)->as_table();
    const std::string base = c["base"].value_or(default_base);
    if (const auto found = bases.find(base); found != bases.end())
      result.text = found->second;
    else if (const auto text = table["base"][base].value<std::string>())
      result.text = *text;
    else
      fail("no base text '" + base + "'");
    if (const toml::array* edits = c["edits"].as_array())
      for (const toml::node& edit : *edits) {
        const toml::array* pair = edit.as_array();
        if (!pair || pair->size() != 2 || !pair->get(0)->is_string() || !pair->get(1)->is_string())
          fail("an edit is not a pair of strings [from, to]");
        const std::string from = pair->get(0)->value_or(std::string()), to = pair->get(1)->value_or(std::string());
        const std::size_t at = result.text.find(from);
        if (from.empty() || at == std::string::npos) fail("the text has no '" + from + "'");
        result.text.replace(at, from.size(), to);
      }
    result.text += c["append"].value_or(std::string());
    result.expected = c["expect"].value_or(std::string());
    if (result.expected.empty()) fail("no expect");
    out.push_back(std::move(result));
  }
  return out;
}

}  // namespace isosid::test

// The study's table; see study_table.hpp.
#include "study_table.hpp"

#include "isosid/format/atomic_output.hpp"
#include "isosid/format/hdf5_file.hpp"

#include <Eigen/Dense>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

namespace isosid::sweep {
namespace fs = std::filesystem;

namespace {

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

/// A JSON value as a table cell: numbers with all their digits, strings as they are, null empty.
std::string cell(const nlohmann::json& v) {
  if (v.is_null()) return "";
  if (v.is_string()) return v.get<std::string>();
  if (v.is_number_float()) {
    char text[32];
    return std::string(text, std::to_chars(text, text + sizeof text, v.get<double>()).ptr);  // shortest exact
  }
  return v.dump();
}

/// The SHA-256 of a row's inputs as "role=hash; ...".
std::string inputs_text(const nlohmann::json& row) {
  std::string out;
  for (const nlohmann::json& i : row["inputs"])
    out += (out.empty() ? "" : "; ") + i.value("role", std::string()) + "=" + i.value("sha256", std::string());
  return out;
}

/// A setting's value text as a number where it is one, else the text.
nlohmann::json setting_cell(const nlohmann::json& text) {
  if (!text.is_string()) return text;
  const std::string& t = text.get_ref<const std::string&>();
  double v = 0;
  const auto [end, error] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (error == std::errc() && end == t.data() + t.size()) return v;
  return text;
}

struct Column {
  std::string name;
  std::vector<nlohmann::json> values;
};

std::vector<Column> columns_of(const Study& study, const std::vector<std::string>& collect, const std::vector<nlohmann::json>& rows) {
  std::vector<Column> out;
  auto add = [&](const std::string& name, auto get) {
    Column c{name, {}};
    for (const nlohmann::json& r : rows) c.values.push_back(get(r));
    out.push_back(std::move(c));
  };
  add("case", [](const nlohmann::json& r) { return r["case"]; });
  add("status", [](const nlohmann::json& r) { return r["status"]; });
  add("exit_class", [](const nlohmann::json& r) { return r["exit_class"]; });
  add("message", [](const nlohmann::json& r) { return r["message"]; });
  for (const Parameter& p : study.parameters)
    for (const std::string& key : p.keys)
      add(key, [&](const nlohmann::json& r) { return setting_cell(r["settings"].value(key, nlohmann::json())); });
  for (const std::string& path : collect)
    add(path, [&](const nlohmann::json& r) { return r["collected"].contains(path) ? r["collected"][path] : nlohmann::json(); });
  add("wall_time_s", [](const nlohmann::json& r) { return r["wall_time_s"]; });
  add("cpu_time_s", [](const nlohmann::json& r) { return r["cpu_time_s"]; });
  add("program_version", [](const nlohmann::json& r) { return r["program_version"]; });
  add("inputs_sha256", [](const nlohmann::json& r) { return nlohmann::json(inputs_text(r)); });
  return out;
}

bool numeric(const Column& c) {
  bool any = false;
  for (const nlohmann::json& v : c.values) {
    if (v.is_null()) continue;
    if (!v.is_number()) return false;
    any = true;
  }
  return any;
}

}  // namespace

std::string case_folder(const std::string& dir, int index) {
  char name[32];
  std::snprintf(name, sizeof name, "%06d", index);
  return (fs::path(dir) / "cases" / name).string();
}

std::optional<nlohmann::json> read_row(const std::string& dir, int index) {
  std::ifstream in(fs::path(case_folder(dir, index)) / "row.json");
  if (!in) return std::nullopt;
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;  // never written whole (rows are renamed into place): run it again
  }
}

void write_row(const std::string& dir, const nlohmann::json& row) {
  const std::string folder = case_folder(dir, row["case"].get<int>());
  fs::create_directories(folder);
  format::write_text_atomically((fs::path(folder) / "row.json").string(), row.dump(2) + "\n");
}

void write_table(const std::string& dir, const Study& study, const std::vector<std::string>& collect,
                 const std::vector<nlohmann::json>& rows) {
  const std::vector<Column> columns = columns_of(study, collect, rows);
  std::ostringstream csv;
  for (std::size_t j = 0; j < columns.size(); ++j) csv << (j ? "," : "") << csv_field(columns[j].name);
  csv << "\n";
  for (std::size_t i = 0; i < rows.size(); ++i) {
    for (std::size_t j = 0; j < columns.size(); ++j) csv << (j ? "," : "") << csv_field(cell(columns[j].values[i]));
    csv << "\n";
  }
  format::write_text_atomically((fs::path(dir) / "study.csv").string(), csv.str());

  format::AtomicOutput out((fs::path(dir) / "study.h5").string());
  {
    format::h5::Writer w(out.temp_path());
    w.string("/study_file", study.file);
    w.string("/scene_file", study.scene_file);
    w.group("/columns");
    std::vector<std::string> order;
    for (const Column& c : columns) {
      // a column's name may hold dots, never '/' (a dataset of its own, not a path)
      std::string name = c.name;
      for (char& ch : name)
        if (ch == '/') ch = '|';
      order.push_back(name);
      const std::string path = "/columns/" + name;
      if (numeric(c)) {
        Eigen::VectorXd v(Eigen::Index(c.values.size()));
        for (std::size_t i = 0; i < c.values.size(); ++i)
          v(Eigen::Index(i)) = c.values[i].is_number() ? c.values[i].get<double>() : std::numeric_limits<double>::quiet_NaN();
        w.vector(path, v, "");
      } else {
        std::vector<std::string> text;
        for (const nlohmann::json& v : c.values) text.push_back(cell(v));
        w.strings(path, text);
      }
    }
    w.strings("/column_order", order);
    w.close();
  }
  out.commit();
}

}  // namespace isosid::sweep

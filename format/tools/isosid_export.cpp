// isosid-export: writes a SID in another tool's format (the classic ASCII SID_FEM, MBSim's
// flexible FFR body HDF5). Exit 0 written, 2 bad input (unknown format, unwritable path,
// the SID itself as output, a SID the format cannot hold).
#include "isosid/common/cli_parse.hpp"
#include "isosid/format/file_kind.hpp"
#include "isosid/format/sid_export.hpp"
#include "isosid/format/sid_io.hpp"

#include <filesystem>
#include <iostream>
#include <map>

int main(int argc, char** argv) {
  using namespace isosid::format;
  return isosid::common::run_guarded("isosid-export", [&] {
    CLI::App app{"Writes a SID file in another multibody tool's format: sid-fem (the classic ASCII standard input data,\n"
                 "as the Modelica EMBS library reads it) or mbsim-h5 (MBSim's flexible FFR body input).",
                 "isosid-export"};
    std::string file, format, output;
    app.add_option("sid", file, "SID file (.sid.h5)")->required();
    const std::map<std::string, std::string> extension = {{"sid-fem", ".SID_FEM"}, {"mbsim-h5", ".mbsim.h5"}};
    app.add_option("--format", format, "sid-fem or mbsim-h5")->required()->check(CLI::IsMember({"sid-fem", "mbsim-h5"}));
    app.add_option("-o,--output", output, "output file (default: the SID's name with .SID_FEM or .mbsim.h5)");
    if (auto status = isosid::common::parse_command_line(app, argc, argv)) return *status;
    const Sid sid = read_sid(file);
    if (output.empty()) {
      const std::size_t dot = file.rfind(".sid.h5");
      output = (dot == std::string::npos ? file : file.substr(0, dot)) + extension.at(format);
    }
    require_output_file(output);
    if (std::filesystem::exists(output) && std::filesystem::equivalent(output, file))
      throw InputError(output, "--output", "is the SID itself: choose another file");
    const ExportFormat kind = format == "sid-fem" ? ExportFormat::SidFem : ExportFormat::MbsimH5;
    check_exportable(sid, file, kind);
    if (kind == ExportFormat::SidFem)
      write_sid_fem(sid, output);
    else
      write_mbsim_h5(sid, output);
    std::cerr << "isosid-export: " << sid.body_name << " (nq = " << sid.nq() << ", " << sid.nodes.size() << " nodes) -> " << output
              << "\n";
    return 0;
  });
}

/// `geardyn report` (report_command.h): checks the folder, then hands over to Python.

#include "report_command.h"

#include <iostream>
#include <string>
#include <vector>

#include "command.h"
#include "plotting.h"

namespace geardyn::cli {

ReportCommand::ReportCommand(CLI::App& app) {
  sub_ = app.add_subcommand(
      "report",
      "one self-contained HTML report of a result folder: headline numbers, the resolved "
      "configuration and interactive figures (plotly.js embedded; no network needed)");
  sub_->add_option("results_dir", folder_, "a result folder written by a geardyn command")
      ->required();
  sub_->add_option("--out,-o", out_, "HTML file to write (default: RESULTS_DIR/report.html)")
      ->check([](const std::string& value) {
        return value.empty() ? std::string("--out needs a file name (an empty path was given)")
                             : std::string();
      });
  sub_->add_flag("--quiet,-q", quiet_, "print nothing but warnings and errors");
}

std::optional<int> ReportCommand::runIfParsed() const {
  if (!sub_->parsed()) return std::nullopt;
  std::error_code ec;
  if (!std::filesystem::is_directory(folder_, ec)) {
    std::cerr << "geardyn report: I/O error: results_dir = " << folder_ << ": "
              << (std::filesystem::exists(folder_, ec) ? "not a folder" : "no such folder") << "\n";
    return kExitIoFailure;
  }
  if (!std::filesystem::is_regular_file(folder_ / "summary.json", ec)) {
    std::cerr << "geardyn report: error: results_dir = " << folder_
              << ": no summary.json; give a folder written by a geardyn command (e.g. "
                 "results/<config stem>/)\n";
    return kExitBadInput;
  }
  std::vector<std::string> args{folder_.string()};
  if (!out_.empty()) args.insert(args.end(), {"--out", out_.string()});
  if (quiet_) args.push_back("--quiet");
  const int code = runPythonModule("geardyn.report", args);
  if (code < 0) return kExitIoFailure;
  return code;
}

}  // namespace geardyn::cli

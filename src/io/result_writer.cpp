#include "geardyn/io/result_writer.h"

#include <chrono>
#include <ctime>
#include <fstream>

#include "geardyn/io/atomic_file.h"
#include "geardyn/version.h"

namespace geardyn::io {
namespace {

std::string utcNow() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof(text), "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

}  // namespace

ResultWriter::ResultWriter(std::filesystem::path folder) : folder_(std::move(folder)) {
  // A folder that holds an earlier run's results: remove the files that run listed in its
  // summary (only those: a folder is never emptied blindly), so that no stale table or plot of
  // another configuration sits beside the new ones. The summary goes last.
  const std::filesystem::path summary = folder_ / "summary.json";
  std::error_code ec;
  if (!std::filesystem::is_regular_file(summary, ec)) return;
  std::ifstream in(summary);
  const auto previous = nlohmann::ordered_json::parse(in, nullptr, false);
  if (previous.is_discarded() || !previous.contains("files") || !previous["files"].is_array())
    return;
  for (const auto& name : previous["files"]) {
    if (!name.is_string()) continue;
    const std::filesystem::path file(name.get<std::string>());
    if (file.has_parent_path() || file.filename() == "summary.json") continue;  // plain names only
    std::filesystem::remove(folder_ / file, ec);
  }
  std::filesystem::remove(summary, ec);
}

void ResultWriter::writeCsv(const std::string& name, const CsvTable& table) {
  writeText(name, table.toString());
}

void ResultWriter::writeText(const std::string& name, const std::string& content) {
  writeFileAtomic(folder_ / name, content);
  files_.push_back(name);
}

std::filesystem::path ResultWriter::writeSummary(const RunSummary& summary) {
  const std::filesystem::path path = folder_ / "summary.json";
  writeFileAtomic(path, summaryJson(summary, files_).dump(2) + "\n");
  return path;
}

nlohmann::ordered_json summaryJson(const RunSummary& summary,
                                   const std::vector<std::string>& files) {
  nlohmann::ordered_json json;
  json["geardyn_version"] = kVersion;
  json["command"] = summary.command;
  json["status"] = summary.status;
  json["created_utc"] = utcNow();
  json["config_file"] = summary.config_source;
  json["seed"] = summary.seed ? nlohmann::ordered_json(*summary.seed) : nullptr;
  json["warnings"] = summary.warnings;
  json["results"] = summary.results;
  json["files"] = files;
  json["config"] = summary.config;
  return json;
}

}  // namespace geardyn::io

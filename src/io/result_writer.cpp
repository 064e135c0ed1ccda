#include "geardyn/io/result_writer.h"

#include <chrono>
#include <ctime>

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

ResultWriter::ResultWriter(std::filesystem::path folder) : folder_(std::move(folder)) {}

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

#include "geardyn/io/result_writer.h"

#include <fmt/format.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <ctime>
#include <fstream>

#include "geardyn/error.h"
#include "geardyn/io/atomic_file.h"
#include "geardyn/stiffness/foundation_fit_note.h"
#include "geardyn/version.h"

namespace geardyn::io {
namespace fs = std::filesystem;
namespace {

constexpr std::string_view kStagingPrefix = ".partial-";
std::atomic<unsigned long> staging_counter{0};

std::string utcNow() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof(text), "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

[[noreturn]] void fail(const std::string& what, const fs::path& path, const std::error_code& ec) {
  throw IoError(fmt::format("cannot {} {}: {}", what, path.string(), ec.message()));
}

/// The plain file names a summary.json lists (none when it is absent or unreadable).
std::vector<std::string> listedFiles(const fs::path& summary) {
  std::vector<std::string> names;
  std::error_code ec;
  if (!fs::is_regular_file(summary, ec)) return names;
  std::ifstream in(summary);
  const auto json = nlohmann::ordered_json::parse(in, nullptr, false);
  if (json.is_discarded() || !json.contains("files") || !json["files"].is_array()) return names;
  for (const auto& name : json["files"]) {
    if (!name.is_string()) continue;
    const fs::path file(name.get<std::string>());
    if (file.has_parent_path() || file.filename() == "summary.json") continue;  // plain names only
    names.push_back(file.string());
  }
  return names;
}

/// Removes the staging folders of runs whose process is gone (killed before their commit).
void removeAbandonedStaging(const fs::path& folder) {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    const std::string name = entry.path().filename().string();
    if (!name.starts_with(kStagingPrefix)) continue;
    const long pid = std::strtol(name.c_str() + kStagingPrefix.size(), nullptr, 10);
    if (pid <= 0 || pid == ::getpid() || ::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH)
      continue;
    std::error_code ignored;
    fs::remove_all(entry.path(), ignored);
  }
}

}  // namespace

ResultWriter::ResultWriter(fs::path folder) : folder_(std::move(folder)) {
  std::error_code ec;
  // The outermost folder this writer creates, removed again (when empty) by a failed run.
  for (fs::path p = folder_; !p.empty() && !fs::exists(p, ec); p = p.parent_path()) {
    created_root_ = p;
    if (p == p.parent_path()) break;
  }
  fs::create_directories(folder_, ec);
  if (ec) fail("create folder", folder_, ec);
  removeAbandonedStaging(folder_);
  staging_ = folder_ / fmt::format("{}{}-{}", kStagingPrefix, ::getpid(), staging_counter++);
  fs::create_directory(staging_, ec);
  if (ec) {
    discard();
    fail("create folder", staging_, ec);
  }
}

ResultWriter::~ResultWriter() {
  if (!committed_) discard();
}

fs::path ResultWriter::pathFor(const std::string& name) const {
  return (committed_ ? folder_ : staging_) / name;
}

void ResultWriter::writeCsv(const std::string& name, const CsvTable& table) {
  writeText(name, table.toString());
}

void ResultWriter::writeText(const std::string& name, const std::string& content) {
  writeFileAtomic(pathFor(name), content, committed_ && durable_);
  files_.push_back(name);
}

void ResultWriter::commit() {
  // The previous run's summary goes first: from here until the new summary is written the folder
  // does not look finished. Then its files (only those it lists), then the new files move in.
  const fs::path summary = folder_ / "summary.json";
  const std::vector<std::string> previous = listedFiles(summary);
  std::error_code ec;
  fs::remove(summary, ec);
  // All of them, also those about to be replaced: a rename onto an existing file makes ext4
  // write the new file's data out first (auto_da_alloc), measured 6–8 ms a file (issue 22).
  for (const auto& name : previous) fs::remove(folder_ / name, ec);
  durable_ = static_cast<double>(std::clock()) / CLOCKS_PER_SEC >= kDurableAfter;
  if (durable_) {
    for (const auto& name : files_) syncToDisk(staging_ / name);
  }
  for (const auto& name : files_) {
    fs::rename(staging_ / name, folder_ / name, ec);
    if (ec) fail("move the result file into place:", staging_ / name, ec);
  }
  fs::remove_all(staging_, ec);
  if (durable_) syncToDisk(folder_);
  committed_ = true;
}

void ResultWriter::discard() noexcept {
  std::error_code ec;
  if (!staging_.empty()) fs::remove_all(staging_, ec);
  if (created_root_.empty()) return;
  for (fs::path p = folder_; fs::is_empty(p, ec) && !ec; p = p.parent_path()) {
    if (!fs::remove(p, ec) || p == created_root_) break;
  }
}

fs::path ResultWriter::writeSummary(const RunSummary& summary) {
  if (!committed_) commit();
  const fs::path path = folder_ / "summary.json";
  writeFileAtomic(path, summaryJson(summary, files_).dump(2) + "\n", durable_);
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
  json["wall_time_s"] = summary.wall_time_s;
  json["numerical_failure"] = summary.numerical_failure;
  json["warnings"] = summary.warnings;
  // The meshes whose fillet-foundation fit is extrapolated (issue #34): the command line
  // prints one line for all of them.
  nlohmann::ordered_json fits = nlohmann::ordered_json::array();
  for (const std::string& w : summary.warnings) {
    if (const auto fit = parseFoundationFitWarning(w)) {
      fits.push_back({{"mesh", fit->subject},
                      {"members", fit->members},
                      {"mean_stiffness_change", fit->mean_stiffness_change},
                      {"coefficients", fit->detail}});
    }
  }
  json["foundation_fit_extrapolated"] = std::move(fits);
  json["results"] = summary.results;
  json["files"] = files;
  json["config"] = summary.config;
  return json;
}

}  // namespace geardyn::io

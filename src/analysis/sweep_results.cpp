/// Study definition, journal and result files of `geardyn sweep` (see sweep_io.h).

#include "geardyn/analysis/sweep_results.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <atomic>
#include <cmath>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

#include "geardyn/config/did_you_mean.h"
#include "geardyn/config/sweep_config.h"
#include "geardyn/error.h"
#include "geardyn/io/atomic_file.h"

namespace geardyn::analysis {
namespace fs = std::filesystem;

nlohmann::json SweepCaseRecord::toJson() const {
  nlohmann::json out = nlohmann::json::array();
  for (double x : outputs) out.push_back(std::isfinite(x) ? nlohmann::json(x) : nlohmann::json());
  return {{"case", index},    {"status", status}, {"seed", seed},
          {"values", values}, {"outputs", out},   {"message", message}};
}

SweepCaseRecord SweepCaseRecord::fromJson(const nlohmann::json& j) {
  SweepCaseRecord r;
  r.index = j.at("case").get<long long>();
  r.status = j.at("status").get<std::string>();
  r.seed = j.at("seed").get<std::uint64_t>();
  for (const auto& v : j.at("values")) r.values.push_back(v);
  for (const auto& v : j.at("outputs"))
    r.outputs.push_back(v.is_null() ? std::numeric_limits<double>::quiet_NaN() : v.get<double>());
  r.message = j.at("message").get<std::string>();
  return r;
}

SweepJournal::SweepJournal(const fs::path& path, const std::string& fingerprint, bool resume) {
  const std::string header = nlohmann::json({{"geardyn_sweep_journal", fingerprint}}).dump();
  std::string kept = header + "\n";
  if (resume) {
    if (!fs::exists(path))
      throw InputError("--resume", path.string(), "a sweep journal to resume (none found)");
    std::ifstream in(path);
    std::string line;
    bool first = true;
    while (std::getline(in, line)) {
      if (in.eof() && !line.empty()) break;  // no newline: cut by a kill, dropped
      nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
      if (first) {
        if (j.is_discarded() || j.value("geardyn_sweep_journal", std::string()) != fingerprint)
          throw InputError("--resume", path.string(),
                           "the journal of this very study (the study or its base configuration "
                           "changed since; run without --resume to start again)");
        first = false;
        continue;
      }
      if (j.is_discarded()) continue;
      previous_.push_back(SweepCaseRecord::fromJson(j));
      kept += line + "\n";
    }
  }
  // Rewrite the journal with the kept lines (atomically), then append to it.
  io::writeFileAtomic(path, kept);
  fd_ = ::open(path.c_str(), O_WRONLY | O_APPEND);
  if (fd_ < 0) throw IoError("cannot open " + path.string());
}

SweepJournal::~SweepJournal() {
  if (fd_ >= 0) ::close(fd_);
}

void SweepJournal::append(const SweepCaseRecord& record) {
  const std::string line = record.toJson().dump() + "\n";
  std::size_t done = 0;
  while (done < line.size()) {
    const ssize_t n = ::write(fd_, line.data() + done, line.size() - done);
    if (n < 0) throw IoError("cannot append to the sweep journal");
    done += static_cast<std::size_t>(n);
  }
  ::fdatasync(fd_);
}

double outputValue(const nlohmann::json& results, const std::string& pointer, bool* ok) {
  *ok = false;
  try {
    const nlohmann::json& v = results.at(nlohmann::json::json_pointer(pointer));
    if (v.is_boolean()) {
      *ok = true;
      return v.get<bool>() ? 1.0 : 0.0;
    }
    if (v.is_number()) {
      *ok = true;
      return v.get<double>();
    }
  } catch (const std::exception&) {
  }
  return std::numeric_limits<double>::quiet_NaN();
}

io::CsvTable sweepTable(const config::SweepDefinition& study,
                        const std::vector<SweepCaseRecord>& records) {
  std::vector<std::string> columns{"case", "status", "seed"};
  for (const auto& p : study.parameters) columns.push_back(p.key);
  for (const auto& o : study.outputs) columns.push_back(o.name);
  columns.push_back("message");
  io::CsvTable table(columns);
  for (const auto& r : records) {
    std::vector<io::CsvCell> row{r.index, r.status, std::to_string(r.seed)};
    for (const auto& v : r.values) {
      if (v.is_number())
        row.push_back(v.get<double>());
      else if (v.is_boolean())
        row.push_back(v.get<bool>() ? "true" : "false");
      else
        row.push_back(v.get<std::string>());
    }
    for (double x : r.outputs) row.push_back(x);
    row.push_back(r.message);
    table.addRow(row);
  }
  return table;
}

}  // namespace geardyn::analysis

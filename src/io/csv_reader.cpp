#include "geardyn/io/csv_reader.h"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "geardyn/did_you_mean.h"
#include "geardyn/error.h"

namespace geardyn::io {
namespace {

std::vector<std::string> splitLine(const std::string& line, char delimiter) {
  std::vector<std::string> cells;
  std::string cell;
  bool quoted = false;
  for (char c : line) {
    if (c == '"') {
      quoted = !quoted;
    } else if (c == delimiter && !quoted) {
      cells.push_back(cell);
      cell.clear();
    } else if (c != '\r') {
      cell += c;
    }
  }
  cells.push_back(cell);
  return cells;
}

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t");
  const auto last = s.find_last_not_of(" \t");
  return first == std::string::npos ? std::string() : s.substr(first, last - first + 1);
}

}  // namespace

NumericCsv::NumericCsv(const std::filesystem::path& file, const std::string& key)
    : source_(file.string()) {
  std::ifstream in(file);
  if (!in) throw InputError(key, source_, "cannot be opened (no such file?)");
  std::string line;
  if (!std::getline(in, line)) throw InputError(key, source_, "is empty: expected a header row");
  if (line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);  // UTF-8 byte-order mark (Excel)
  // European spreadsheets write "t;x1" with decimal commas ("0,5"); tabs are common too.
  if (line.find(',') == std::string::npos) {
    if (line.find(';') != std::string::npos)
      delimiter_ = ';';
    else if (line.find('\t') != std::string::npos)
      delimiter_ = '\t';
  }
  for (const auto& name : splitLine(line, delimiter_)) names_.push_back(trim(name));
  for (const auto& name : names_) data_[name];
  std::size_t row = 1;
  while (std::getline(in, line)) {
    ++row;
    if (trim(line).empty()) continue;
    const auto cells = splitLine(line, delimiter_);
    if (cells.size() != names_.size()) {
      const bool other =
          delimiter_ == ',' && names_.size() == 1 && line.find_first_of(";\t") != std::string::npos;
      throw InputError(key, fmt::format("{} row {}", source_, row),
                       fmt::format("has {} cells, the header {}{}", cells.size(), names_.size(),
                                   other ? " (the delimiter is not a comma?)" : ""));
    }
    for (std::size_t c = 0; c < cells.size(); ++c) {
      std::string text = trim(cells[c]);
      if (delimiter_ == ';') std::replace(text.begin(), text.end(), ',', '.');  // decimal comma
      char* end = nullptr;
      errno = 0;
      const double value = std::strtod(text.c_str(), &end);
      if (text.empty() || end != text.c_str() + text.size()) {
        // A column of text (e.g. a model name) is kept out of the numeric table.
        data_[names_[c]].push_back(NAN);
        continue;
      }
      if (!std::isfinite(value)) {
        throw InputError(key, fmt::format("{} row {}, column {}", source_, row, names_[c]),
                         fmt::format("holds {}: measured data must be finite (remove or repair the "
                                     "sample)",
                                     text));
      }
      data_[names_[c]].push_back(value);
    }
    ++rows_;
  }
}

const std::vector<double>& NumericCsv::column(const std::string& name,
                                              const std::string& key) const {
  const auto it = data_.find(name);
  if (it == data_.end()) {
    std::string hint;
    if (auto match = closestMatch(name, names_))
      hint = fmt::format("; did you mean \"{}\"?", *match);
    std::string all;
    for (const auto& n : names_) all += (all.empty() ? "" : ", ") + n;
    throw InputError(key, "\"" + name + "\"",
                     fmt::format("no such column in {}{} (columns: {})", source_, hint, all));
  }
  for (std::size_t r = 0; r < it->second.size(); ++r) {
    if (std::isnan(it->second[r])) {
      throw InputError(key, fmt::format("{} row {}, column {}", source_, r + 2, name),
                       "is not a number");
    }
  }
  return it->second;
}

}  // namespace geardyn::io

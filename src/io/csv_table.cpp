#include "geardyn/io/csv_table.h"

#include <fmt/format.h>

#include <stdexcept>

namespace geardyn::io {
namespace {

std::string quoted(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

struct CellText {
  std::string operator()(double value) const { return fmt::format("{:.17g}", value); }
  std::string operator()(long long value) const { return std::to_string(value); }
  std::string operator()(const std::string& value) const { return quoted(value); }
};

}  // namespace

CsvTable::CsvTable(std::vector<std::string> columns) : columns_(std::move(columns)) {}

void CsvTable::addRow(std::vector<CsvCell> row) {
  if (row.size() != columns_.size()) {
    throw std::invalid_argument(
        fmt::format("CsvTable::addRow: {} cells for {} columns", row.size(), columns_.size()));
  }
  rows_.push_back(std::move(row));
}

std::string CsvTable::toString() const {
  std::string out;
  for (std::size_t i = 0; i < columns_.size(); ++i) {
    if (i) out += ',';
    out += quoted(columns_[i]);
  }
  out += '\n';
  for (const auto& row : rows_) {
    for (std::size_t i = 0; i < row.size(); ++i) {
      if (i) out += ',';
      out += std::visit(CellText{}, row[i]);
    }
    out += '\n';
  }
  return out;
}

}  // namespace geardyn::io

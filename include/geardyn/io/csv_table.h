#pragma once
/// \file
/// A small CSV table for result files: a header row of column names (with units in the names,
/// e.g. "base_radius_m") and rows of numbers or text. Numbers are written with 17 significant
/// digits so that they read back bit for bit.

#include <string>
#include <variant>
#include <vector>

namespace geardyn::io {

using CsvCell = std::variant<double, long long, std::string>;

class CsvTable {
 public:
  explicit CsvTable(std::vector<std::string> columns);

  /// Appends a row; throws std::invalid_argument if its length differs from the header's.
  void addRow(std::vector<CsvCell> row);

  const std::vector<std::string>& columns() const noexcept { return columns_; }
  std::size_t rows() const noexcept { return rows_.size(); }
  /// Row `i` (< rows()), one cell per column.
  const std::vector<CsvCell>& row(std::size_t i) const { return rows_.at(i); }
  /// RFC 4180 text: comma separated, text quoted when it holds a comma, quote or newline.
  std::string toString() const;

 private:
  std::vector<std::string> columns_;
  std::vector<std::vector<CsvCell>> rows_;
};

}  // namespace geardyn::io

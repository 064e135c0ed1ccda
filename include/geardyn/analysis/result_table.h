#pragma once
/// \file
/// A result table held by columns: each column is one contiguous array of numbers (double or
/// integer) or of text, so that Python can view a numeric column as a numpy array without a
/// copy (python/bind_analysis.cpp). Column names carry their unit as in the CSV files
/// (e.g. "base_radius_m"); written as CSV it is cell for cell the io::CsvTable it came from.

#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "geardyn/io/csv_table.h"

namespace geardyn::analysis {

/// One column: reals, integers or text.
using ResultColumn =
    std::variant<std::vector<double>, std::vector<std::int64_t>, std::vector<std::string>>;

class ResultTable {
 public:
  ResultTable() = default;
  /// Columns of `table`: all-integer cells give an integer column, numbers (real or integer)
  /// a real column, anything holding text a text column (numbers as the CSV writes them).
  explicit ResultTable(const io::CsvTable& table);

  const std::vector<std::string>& names() const noexcept { return names_; }
  const std::vector<ResultColumn>& columns() const noexcept { return columns_; }
  std::size_t rows() const noexcept { return rows_; }
  /// The column called `name`; throws std::out_of_range naming it when there is none.
  const ResultColumn& column(const std::string& name) const;

  /// The table as CSV cells again (for io::ResultWriter).
  io::CsvTable toCsv() const;

 private:
  std::vector<std::string> names_;
  std::vector<ResultColumn> columns_;
  std::size_t rows_ = 0;
};

}  // namespace geardyn::analysis

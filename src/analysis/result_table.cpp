#include "geardyn/analysis/result_table.h"

#include <fmt/format.h>

#include <stdexcept>

namespace geardyn::analysis {
namespace {

/// A cell as the CSV writer prints it (src/io/csv_table.cpp), without quoting.
std::string cellText(const io::CsvCell& cell) {
  if (const auto* d = std::get_if<double>(&cell)) return fmt::format("{:.17g}", *d);
  if (const auto* i = std::get_if<long long>(&cell)) return std::to_string(*i);
  return std::get<std::string>(cell);
}

}  // namespace

ResultTable::ResultTable(const io::CsvTable& table) : names_(table.columns()), rows_(table.rows()) {
  columns_.reserve(names_.size());
  for (std::size_t c = 0; c < names_.size(); ++c) {
    bool text = false, integer = true;
    for (std::size_t r = 0; r < rows_; ++r) {
      const auto& cell = table.row(r)[c];
      text = text || std::holds_alternative<std::string>(cell);
      integer = integer && std::holds_alternative<long long>(cell);
    }
    if (text) {
      std::vector<std::string> values(rows_);
      for (std::size_t r = 0; r < rows_; ++r) values[r] = cellText(table.row(r)[c]);
      columns_.emplace_back(std::move(values));
    } else if (integer && rows_ > 0) {
      std::vector<std::int64_t> values(rows_);
      for (std::size_t r = 0; r < rows_; ++r) values[r] = std::get<long long>(table.row(r)[c]);
      columns_.emplace_back(std::move(values));
    } else {
      std::vector<double> values(rows_);
      for (std::size_t r = 0; r < rows_; ++r) {
        const auto& cell = table.row(r)[c];
        values[r] = std::holds_alternative<double>(cell)
                        ? std::get<double>(cell)
                        : static_cast<double>(std::get<long long>(cell));
      }
      columns_.emplace_back(std::move(values));
    }
  }
}

const ResultColumn& ResultTable::column(const std::string& name) const {
  for (std::size_t c = 0; c < names_.size(); ++c) {
    if (names_[c] == name) return columns_[c];
  }
  throw std::out_of_range(fmt::format("result table has no column '{}'", name));
}

io::CsvTable ResultTable::toCsv() const {
  io::CsvTable table(names_);
  for (std::size_t r = 0; r < rows_; ++r) {
    std::vector<io::CsvCell> row;
    row.reserve(columns_.size());
    for (const auto& column : columns_) {
      std::visit(
          [&](const auto& values) {
            using T = typename std::decay_t<decltype(values)>::value_type;
            if constexpr (std::is_same_v<T, std::int64_t>) {
              row.emplace_back(static_cast<long long>(values[r]));
            } else {
              row.emplace_back(values[r]);
            }
          },
          column);
    }
    table.addRow(std::move(row));
  }
  return table;
}

}  // namespace geardyn::analysis

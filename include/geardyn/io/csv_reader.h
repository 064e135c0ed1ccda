#pragma once
/// \file
/// Reading numeric CSV tables (measured signals, curves written by other commands): a header
/// row of column names, then rows of numbers. Every value must be finite; a NaN, an empty cell
/// or text where a number is expected is an InputError naming the file, the row and the column.

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace geardyn::io {

class NumericCsv {
 public:
  /// Reads `file`; `key` names the configuration key that gave the path (for messages).
  NumericCsv(const std::filesystem::path& file, const std::string& key);

  const std::vector<std::string>& columns() const noexcept { return names_; }
  std::size_t rows() const noexcept { return rows_; }
  /// The delimiter found in the header: ',' unless the header has none and has ';' (then
  /// decimal commas are read too) or a tab.
  char delimiter() const noexcept { return delimiter_; }
  /// The values of a column; InputError (with a did-you-mean) if there is no such column.
  const std::vector<double>& column(const std::string& name, const std::string& key) const;

 private:
  std::string source_;
  std::vector<std::string> names_;
  std::map<std::string, std::vector<double>> data_;
  std::size_t rows_ = 0;
  char delimiter_ = ',';
};

}  // namespace geardyn::io

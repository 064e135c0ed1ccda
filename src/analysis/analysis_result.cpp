#include "geardyn/analysis/analysis_result.h"

#include <fmt/format.h>

#include <stdexcept>

namespace geardyn::analysis {

AnalysisResult::AnalysisResult(std::string command, const config::Config& config,
                               const AnalysisContext& context) {
  summary.command = std::move(command);
  summary.config_source = context.config_source;
  summary.config = config.resolved();
}

void AnalysisResult::addTable(std::string name, const io::CsvTable& table) {
  table_names.push_back(std::move(name));
  tables.emplace_back(table);
}

const ResultTable& AnalysisResult::table(const std::string& name) const {
  for (std::size_t i = 0; i < table_names.size(); ++i) {
    if (table_names[i] == name || table_names[i] == name + ".csv") return tables[i];
  }
  throw std::out_of_range(fmt::format("the {} result has no table '{}'", summary.command, name));
}

void writeAnalysisResult(const AnalysisResult& result, io::ResultWriter& writer) {
  for (std::size_t i = 0; i < result.tables.size(); ++i) {
    writer.writeCsv(result.table_names[i], result.tables[i].toCsv());
  }
  for (const auto& file : result.files) {
    file.write(writer.pathFor(file.name));
    writer.recordFile(file.name);
  }
}

}  // namespace geardyn::analysis

/// The in-memory result of an analysis: columnar tables that write back cell for cell as the
/// io::CsvTable they came from, typed columns, and runAnalysis over a configuration.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "geardyn/analysis/analyses.h"
#include "geardyn/config/config.h"
#include "geardyn/error.h"

namespace geardyn::analysis {
namespace {

TEST(ResultTable, ColumnsAreTypedAndWriteBackCellForCell) {
  io::CsvTable csv({"name", "count", "value_m", "mixed"});
  csv.addRow({std::string("a,b"), 3LL, 0.1, 2LL});
  csv.addRow({std::string("c"), -7LL, 1e-300, 2.5});
  csv.addRow({std::string("d"), 0LL, std::numeric_limits<double>::quiet_NaN(), std::string("")});
  const ResultTable table(csv);
  ASSERT_EQ(table.rows(), 3u);
  EXPECT_TRUE(std::holds_alternative<std::vector<std::string>>(table.column("name")));
  EXPECT_EQ(std::get<std::vector<std::int64_t>>(table.column("count")),
            (std::vector<std::int64_t>{3, -7, 0}));
  const auto& value = std::get<std::vector<double>>(table.column("value_m"));
  EXPECT_EQ(value[1], 1e-300);
  EXPECT_TRUE(std::isnan(value[2]));
  // A column with text in it is text: its numbers as the CSV writer prints them.
  EXPECT_EQ(std::get<std::vector<std::string>>(table.column("mixed")),
            (std::vector<std::string>{"2", "2.5", ""}));
  EXPECT_EQ(table.toCsv().toString(), csv.toString());
  EXPECT_THROW(table.column("missing"), std::out_of_range);
}

TEST(ResultTable, MixedIntegerAndRealCellsMakeARealColumn) {
  io::CsvTable csv({"x"});
  csv.addRow({1LL});
  csv.addRow({0.5});
  const ResultTable table(csv);
  EXPECT_EQ(std::get<std::vector<double>>(table.column("x")), (std::vector<double>{1.0, 0.5}));
  EXPECT_EQ(table.toCsv().toString(), csv.toString());  // "1" either way
}

TEST(RunAnalysis, GeometryInMemoryWithItsSummaryAndTables) {
  const char* toml = R"(
[pinion]
teeth = 25
module = 3e-3
face_width = 0.02
[gear]
teeth = 30
module = 3e-3
face_width = 0.02
)";
  const config::Config config = config::parseConfig(toml, "test", analysisSchema("geometry"));
  AnalysisContext context;
  context.config_source = "test.toml";
  const AnalysisResult result = runAnalysis("geometry", config, context);
  EXPECT_EQ(result.summary.command, "geometry");
  EXPECT_EQ(result.summary.config_source, "test.toml");
  EXPECT_EQ(result.summary.config, config.resolved());
  EXPECT_FALSE(result.summary.numerical_failure);
  EXPECT_GT(result.summary.wall_time_s, 0.0);
  EXPECT_NEAR(result.summary.results["contact_ratio_transverse"].get<double>(), 1.6325826, 1e-7);
  const auto& radius = std::get<std::vector<double>>(result.table("gears").column("base_radius_m"));
  ASSERT_EQ(radius.size(), 2u);
  EXPECT_NEAR(radius[0], 0.5 * 3e-3 * 25 * std::cos(20.0 * M_PI / 180.0), 1e-15);
  EXPECT_NE(result.report.find("contact ratio"), std::string::npos);
}

TEST(RunAnalysis, UnknownAnalysisNamesTheCloseOne) {
  try {
    analysisSchema("simulat");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "analysis");
    EXPECT_NE(e.allowed().find("did you mean 'simulate'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace geardyn::analysis

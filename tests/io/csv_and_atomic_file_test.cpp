#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "geardyn/error.h"
#include "geardyn/io/atomic_file.h"
#include "geardyn/io/csv_table.h"

namespace geardyn::io {
namespace {

std::string readAll(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(CsvTable, WritesRoundTrippableNumbersAndQuotesText) {
  CsvTable table({"name", "count", "value_m"});
  table.addRow({std::string("a,b"), 3LL, 0.1});
  table.addRow({std::string("say \"hi\""), -1LL, 1.0 / 3.0});
  EXPECT_EQ(table.toString(),
            "name,count,value_m\n\"a,b\",3,0.10000000000000001\n"
            "\"say \"\"hi\"\"\",-1,0.33333333333333331\n");
  EXPECT_EQ(std::stod("0.33333333333333331"), 1.0 / 3.0);
  EXPECT_THROW(table.addRow({1.0}), std::invalid_argument);
}

TEST(AtomicFile, WritesCreatesFoldersAndLeavesNoTemporary) {
  const auto folder = std::filesystem::temp_directory_path() / "geardyn_atomic_test" / "deep";
  std::filesystem::remove_all(folder.parent_path());
  writeFileAtomic(folder / "out.txt", "first");
  writeFileAtomic(folder / "out.txt", "second, replacing the first");
  EXPECT_EQ(readAll(folder / "out.txt"), "second, replacing the first");
  int entries = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(folder)) ++entries;
  EXPECT_EQ(entries, 1);  // no temporary left behind
  std::filesystem::remove_all(folder.parent_path());
}

TEST(AtomicFile, UnwritableTargetIsAnIoError) {
  // A path below a regular file cannot be created.
  const auto file = std::filesystem::temp_directory_path() / "geardyn_atomic_blocker";
  writeFileAtomic(file, "x");
  EXPECT_THROW(writeFileAtomic(file / "sub" / "out.txt", "y"), IoError);
  std::filesystem::remove(file);
}

}  // namespace
}  // namespace geardyn::io

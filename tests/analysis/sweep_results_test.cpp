// The sweep journal: records survive a kill (a cut last line is dropped), a journal of another
// study is refused, records round-trip with NaN outputs.

#include "geardyn/analysis/sweep_results.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "geardyn/config/sweep_config.h"
#include "geardyn/error.h"

namespace geardyn::analysis {
namespace {

namespace fs = std::filesystem;

SweepCaseRecord record(long long i) {
  SweepCaseRecord r;
  r.index = i;
  r.status = i == 1 ? "max_periods" : "ok";
  r.values = {1.5 * i, "api"};
  r.outputs = {0.1 * i, std::nan("")};
  r.seed = 1234567890123ULL + i;
  r.message = i == 1 ? "no steady state" : "";
  return r;
}

TEST(SweepJournal, KeepsWholeRecordsAndDropsACutLine) {
  const fs::path dir = fs::temp_directory_path() / "geardyn_journal_test";
  fs::create_directories(dir);
  const fs::path path = dir / "sweep_journal.jsonl";
  {
    SweepJournal j(path, "abc", false);
    for (int i = 0; i < 3; ++i) j.append(record(i));
  }
  {  // a kill in the middle of the fourth line
    std::ofstream out(path, std::ios::app);
    out << R"({"case":3,"status":"ok","se)";
  }
  SweepJournal resumed(path, "abc", true);
  ASSERT_EQ(resumed.previous().size(), 3u);
  for (int i = 0; i < 3; ++i) {
    const SweepCaseRecord& r = resumed.previous()[i];
    EXPECT_EQ(r.index, i);
    EXPECT_EQ(r.status, record(i).status);
    EXPECT_EQ(r.seed, record(i).seed);
    EXPECT_EQ(r.values, record(i).values);
    EXPECT_DOUBLE_EQ(r.outputs[0], 0.1 * i);
    EXPECT_TRUE(std::isnan(r.outputs[1]));
  }
  resumed.append(record(3));
  SweepJournal again(path, "abc", true);
  EXPECT_EQ(again.previous().size(), 4u);  // the cut line is gone, the new one is whole
  EXPECT_THROW(SweepJournal(path, "another study", true), InputError);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace geardyn::analysis

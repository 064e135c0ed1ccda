/// One line per kind of warning (issue #33 item 4): kinds are the texts after "<subject>: "
/// with their numbers masked; notes keep their prefix.

#include "geardyn/analysis/warning_groups.h"

#include <gtest/gtest.h>

namespace geardyn::analysis {
namespace {

TEST(WarningGroups, SameKindOnSeveralComponentsIsOneLineNamingThem) {
  const std::vector<std::string> warnings = {
      "note: meshes.stage1 (potential_energy model): fit extrapolated (M* = 1.04): +0.73 %",
      "bearings.a: the axial and tilt terms act only with full DOFs",
      "note: meshes.stage2 (potential_energy model): fit extrapolated (M* = 1.1e+00): -1.2 %",
      "bearings.b: the axial and tilt terms act only with full DOFs",
      "bearings.a: the axial and tilt terms act only with full DOFs",  // exact repeat: dropped
      "no frequency-domain comparison: too many harmonics",
      "no frequency-domain comparison: too many harmonics"};
  const auto lines = groupedWarnings(warnings);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0], warnings[0] +
                          " (the same for 1 more: meshes.stage2 (potential_energy model); each "
                          "in summary.json)");
  EXPECT_EQ(lines[1], warnings[1] + " (the same for 1 more: bearings.b; each in summary.json)");
  EXPECT_EQ(lines[2], warnings[5]);
  EXPECT_TRUE(isNote(lines[0]));
  EXPECT_FALSE(isNote(lines[1]));
}

TEST(WarningGroups, DifferentTextsOrNumbersInWordsStayApart) {
  // "stage1" and "stage2" are subjects; the kinds differ in a word, not only in a number.
  const auto lines = groupedWarnings({"meshes.a: radial_stiffness 1e+20 N/m capped",
                                      "meshes.b: axial_stiffness 1e+20 N/m capped",
                                      "meshes.c: radial_stiffness 2.5e+19 N/m capped"});
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_NE(lines[0].find("the same for 1 more: meshes.c"), std::string::npos);
  EXPECT_EQ(lines[1], "meshes.b: axial_stiffness 1e+20 N/m capped");
}

TEST(WarningGroups, OneSubjectWithOtherValuesIsNeverHidden) {
  // Two Newmark checks of one analysis ("time") differ only in their numbers: both are shown.
  const auto lines =
      groupedWarnings({"time: differs by 12 % at 1500 rpm", "time: differs by 7 % at 1800 rpm",
                       "other: differs by 3 % at 2000 rpm"});
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0],
            "time: differs by 12 % at 1500 rpm (the same for 1 more: other; each in summary.json)");
  EXPECT_EQ(lines[1], "time: differs by 7 % at 1800 rpm");
}

TEST(WarningGroups, LongListsAreCut) {
  std::vector<std::string> warnings;
  for (int i = 0; i < 12; ++i) warnings.push_back("b" + std::to_string(i) + ": capped at 5 N/m");
  const auto lines = groupedWarnings(warnings, 3);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0],
            "b0: capped at 5 N/m (the same for 11 more: b1, b2, b3, …; each in summary.json)");
}

}  // namespace
}  // namespace geardyn::analysis

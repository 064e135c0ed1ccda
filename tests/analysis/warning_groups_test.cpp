/// One line per kind of warning (issue #33 item 4): kinds are the texts after "<subject>: "
/// with their numbers masked; notes keep their prefix.

#include "geardyn/analysis/warning_groups.h"

#include <gtest/gtest.h>

#include "geardyn/notes.h"
#include "geardyn/stiffness/foundation_fit_note.h"

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

// Issue #34: the two-stage reducer's notes (as PotentialEnergyMeshStiffness raises them, put in
// context by the gearbox reader) are one line naming both meshes and the larger change of k̄,
// -3.09 % of stage2, not the first mesh's -1.17 %; a note of another kind keeps its place.
TEST(WarningGroups, FoundationFitNotesOfAllMeshesAreOneLineWithTheLargestChange) {
  const std::string stage1 = inContext(
      "meshes.stage1 (fourier model)",
      foundationFitWarning("pinion: M* = 1.0435 (data 1.08 to 3.29), P* = 2.3487 (data 2.56 to "
                           "13.47)",
                           -0.0117));
  const std::string stage2 = inContext(
      "meshes.stage2 (fourier model)",
      foundationFitWarning("pinion: M* = 1.0302 (data 1.08 to 3.29); gear: L* = 6.9 (data 6.82 "
                           "to 6.94)",
                           -0.0309));
  const auto lines = groupedWarnings({"bearings.a: capped at 5 N/m", stage1, stage2});
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0], "bearings.a: capped at 5 N/m");
  EXPECT_EQ(lines[1],
            "note: Sainsot's (2004) fillet-foundation fit is extrapolated for 2 meshes "
            "(meshes.stage1 (fourier model): pinion; meshes.stage2 (fourier model): pinion and "
            "gear): held at its data range the mean mesh stiffness changes by up to -3.09 % "
            "(meshes.stage2 (fourier model)), so read k̄ as uncertain by up to that much; each "
            "mesh's coefficients in summary.json (foundation_fit_extrapolated)");
  // One note alone is printed as raised.
  EXPECT_EQ(groupedWarnings({stage1}), std::vector<std::string>{stage1});
}

TEST(WarningGroups, FoundationFitNoteParsesBack) {
  const auto fit = parseFoundationFitWarning(
      inContext("meshes.m (potential_energy model)",
                foundationFitWarning("gear: M* = 1.07 (data 1.08 to 3.29)", 0.0123)));
  ASSERT_TRUE(fit);
  EXPECT_EQ(fit->subject, "meshes.m (potential_energy model)");
  EXPECT_EQ(fit->members, std::vector<std::string>{"gear"});
  EXPECT_EQ(fit->detail, "gear: M* = 1.07 (data 1.08 to 3.29)");
  EXPECT_DOUBLE_EQ(fit->mean_stiffness_change, 0.0123);  // printed to 1e-4, exact here
  const auto pair = parseFoundationFitWarning(foundationFitWarning("pinion: P* = 2.4", -0.02));
  ASSERT_TRUE(pair);
  EXPECT_EQ(pair->subject, "");
  EXPECT_FALSE(parseFoundationFitWarning("meshes.m: capped at 5 N/m"));
}

}  // namespace
}  // namespace geardyn::analysis

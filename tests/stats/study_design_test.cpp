// Parameter-study designs: grid order and counts, zipped lists, random draws that depend only on
// (seed, case index) and follow their distributions.

#include "geardyn/stats/study_design.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include "geardyn/error.h"

namespace geardyn {
namespace {

StudyParameter values(std::string key, std::vector<nlohmann::json> v) {
  StudyParameter p;
  p.key = std::move(key);
  p.values = std::move(v);
  return p;
}

TEST(StudyDesign, GridIsFullFactorialWithTheLastParameterFastest) {
  const std::vector<StudyParameter> ps{values("a", {1, 2, 3}), values("b", {"x", "y"})};
  ASSERT_EQ(studyCaseCount(StudyDesign::kGrid, ps, 0), 6);
  const std::vector<std::pair<int, std::string>> expected{{1, "x"}, {1, "y"}, {2, "x"},
                                                          {2, "y"}, {3, "x"}, {3, "y"}};
  for (long long i = 0; i < 6; ++i) {
    const StudyCase c = studyCase(StudyDesign::kGrid, ps, i, 7);
    EXPECT_EQ(c.values[0].get<int>(), expected[i].first);
    EXPECT_EQ(c.values[1].get<std::string>(), expected[i].second);
  }
}

TEST(StudyDesign, ZipNeedsEqualLengths) {
  std::vector<StudyParameter> ps{values("a", {1, 2, 3}), values("b", {4, 5, 6})};
  ASSERT_EQ(studyCaseCount(StudyDesign::kZip, ps, 0), 3);
  EXPECT_EQ(studyCase(StudyDesign::kZip, ps, 2, 1).values[1].get<int>(), 6);
  ps[1].values.pop_back();
  try {
    studyCaseCount(StudyDesign::kZip, ps, 0);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "study.parameters.b");
  }
}

std::vector<StudyParameter> randomParameters() {
  StudyParameter n, u, t, l = values("list", {"api", "step", "fourier"});
  n.key = "normal", n.distribution = StudyDistribution::kNormal, n.mean = 2.0, n.std = 0.5;
  u.key = "uniform", u.distribution = StudyDistribution::kUniform, u.min = -1.0, u.max = 3.0;
  t.key = "truncated", t.distribution = StudyDistribution::kTruncatedNormal, t.mean = 0.0,
  t.std = 1.0, t.min = -0.5, t.max = 2.0;
  return {n, u, t, l};
}

// A case's draws depend only on (seed, index): computing it alone, in another order or as part
// of a resumed subset gives the same bits.
TEST(StudyDesign, RandomCasesDependOnlyOnSeedAndIndex) {
  const auto ps = randomParameters();
  const StudyCase alone = studyCase(StudyDesign::kRandom, ps, 41, 2024);
  for (long long i = 50; i >= 0; --i) {
    const StudyCase c = studyCase(StudyDesign::kRandom, ps, i, 2024);
    if (i == 41) {
      for (std::size_t k = 0; k < ps.size(); ++k) EXPECT_EQ(c.values[k], alone.values[k]);
      EXPECT_EQ(c.seed, alone.seed);
    }
  }
  EXPECT_NE(studyCase(StudyDesign::kRandom, ps, 41, 2025).values[0], alone.values[0]);
  std::set<std::uint64_t> seeds;
  for (long long i = 0; i < 100000; ++i) seeds.insert(caseSeed(2024, i));
  EXPECT_EQ(seeds.size(), 100000u);
}

// 40,000 draws: sample means within 4 standard errors, bounds respected, every list value drawn
// with its 1/3 share (±4 standard errors).
TEST(StudyDesign, RandomDrawsFollowTheirDistributions) {
  const auto ps = randomParameters();
  const int n = 40000;
  double sn = 0, sn2 = 0, su = 0;
  std::map<std::string, int> counts;
  double tmin = 1e9, tmax = -1e9, st = 0;
  for (int i = 0; i < n; ++i) {
    const StudyCase c = studyCase(StudyDesign::kRandom, ps, i, 99);
    const double x = c.values[0].get<double>(), u = c.values[1].get<double>();
    const double t = c.values[2].get<double>();
    sn += x, sn2 += x * x, su += u, st += t;
    ASSERT_GE(u, -1.0);
    ASSERT_LT(u, 3.0);
    tmin = std::min(tmin, t), tmax = std::max(tmax, t);
    ++counts[c.values[3].get<std::string>()];
  }
  const double mean = sn / n, std = std::sqrt(sn2 / n - mean * mean);
  EXPECT_NEAR(mean, 2.0, 4 * 0.5 / std::sqrt(n));
  EXPECT_NEAR(std, 0.5, 0.01);
  EXPECT_NEAR(su / n, 1.0, 4 * (4.0 / std::sqrt(12.0)) / std::sqrt(n));
  EXPECT_GE(tmin, -0.5);
  EXPECT_LE(tmax, 2.0);
  // Mean of N(0,1) truncated to [-0.5, 2]: (φ(-0.5) − φ(2)) / (Φ(2) − Φ(-0.5)).
  auto phi = [](double x) { return std::exp(-x * x / 2) / std::sqrt(2 * M_PI); };
  auto Phi = [](double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); };
  const double truncated_mean = (phi(-0.5) - phi(2.0)) / (Phi(2.0) - Phi(-0.5));
  EXPECT_NEAR(st / n, truncated_mean, 4 * 0.7 / std::sqrt(n));
  for (const auto& [name, count] : counts)
    EXPECT_NEAR(count, n / 3.0, 4 * std::sqrt(n * (1.0 / 3) * (2.0 / 3))) << name;
}

TEST(StudyDesign, RejectsInconsistentDefinitions) {
  StudyParameter p;
  p.key = "x", p.distribution = StudyDistribution::kUniform, p.min = 2, p.max = 1;
  EXPECT_THROW(p.validate(StudyDesign::kRandom), InputError);
  EXPECT_THROW(p.validate(StudyDesign::kGrid), InputError);  // distributions need random
  p.distribution = StudyDistribution::kTruncatedNormal, p.mean = 0, p.std = 1, p.min = 10,
  p.max = 11;
  EXPECT_THROW(p.validate(StudyDesign::kRandom), InputError);  // nothing to draw
  EXPECT_THROW(studyCaseCount(StudyDesign::kRandom, {values("a", {1})}, 0), InputError);
}

}  // namespace
}  // namespace geardyn

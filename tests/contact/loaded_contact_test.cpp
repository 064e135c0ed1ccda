/// Loaded tooth contact analysis: unmodified teeth reproduce the potential-energy mesh
/// stiffness, loads balance and respect the separations, a long tip relief designed for F₀
/// flattens the loaded STE at F₀ (Harris), and crowned helical slices converge.

#include "geardyn/contact/loaded_contact.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "geardyn/solvers/time_response.h"
#include "geardyn/stats/load_statistics.h"
#include "geardyn/stiffness/mesh_stiffness_summary.h"
#include "support/reference_pairs.h"

namespace geardyn {
namespace {

std::shared_ptr<const PotentialEnergyMeshStiffness> peModel(double helix_deg, int slices) {
  PotentialEnergyOptions o;
  o.slices = slices;
  return std::make_shared<const PotentialEnergyMeshStiffness>(
      GearPair(testing::visnadiPairSpec(helix_deg)), o);
}

TEST(LoadedContact, UnmodifiedTeethReproduceThePotentialEnergyStiffness) {
  // δ = F / k and dF/dδ = F/δ = k(φ) at every position, spur and sliced helical (1e-9).
  for (const auto& [helix, slices] : {std::pair{0.0, 1}, std::pair{5.0, 20}}) {
    const auto k = peModel(helix, helix > 0 ? slices : 0);
    const LoadedToothContact contact(k, {}, slices);
    for (int i = 0; i < 97; ++i) {
      const double phase = i / 97.0;
      const auto p = contact.solve(phase, 2000.0);
      const double expected = k->stiffness(phase);
      EXPECT_NEAR(p.tangent, expected, 1e-9 * expected) << helix << " " << phase;
      EXPECT_NEAR(p.secant, expected, 1e-9 * expected);
      EXPECT_NEAR(p.ste, 2000.0 / expected, 1e-9 * 2000.0 / expected);
      double total = 0.0;
      for (int j = 0; j < contact.pairCount(); ++j) {
        total += p.pair_loads[j];
        EXPECT_NEAR(p.pair_loads[j], 2000.0 * k->pairStiffness(phase, j) / expected, 1e-6);
      }
      EXPECT_NEAR(total, 2000.0, 1e-9);
    }
  }
}

TEST(LoadedContact, SampledMeanStiffnessMissesThePeriodMeanByTheQuadratureErrorOfItsJumps) {
  // `ltca` reports the mean tangent stiffness as the average of its N evenly spaced positions
  // φ_i = i/N; `stiffness` integrates k(φ) over the period between its discontinuities. Without
  // modifications both average the same k(φ) (previous test), so the gap is the rectangle
  // rule's error on a curve with jumps J_j at φ_j: Σ_j J_j (t_j − 1/2) / N with t_j = frac(N φ_j)
  // (a sample on a jump takes k(φ_j): k(φ_j) − (k(φ_j⁺) + k(φ_j⁻))/2 instead), plus O(1/N²).
  // docs/theory/loaded_contact.md, "Mean stiffness: ltca and stiffness".
  const auto k = peModel(0.0, 0);
  const LoadedToothContact contact(k, {}, 1);
  const double exact = summarizeMeshStiffness(*k, 0).mean;
  constexpr double kSide = 1e-12;  // one-sided limits at a jump
  std::vector<double> gaps;
  for (int n : {200, 400, 800, 3200}) {
    double mean = 0.0;
    for (const auto& p : contact.sweep(3000.0, n)) mean += p.tangent / n;
    double predicted = 0.0;
    for (double a : k->discontinuities()) {
      const double right = k->stiffness(a + kSide),
                   left = k->stiffness(std::fmod(a - kSide + 1, 1));
      const double t = n * a - std::floor(n * a);
      predicted += (t < 1e-9 || t > 1 - 1e-9) ? (k->stiffness(a) - 0.5 * (right + left)) / n
                                              : (right - left) * (t - 0.5) / n;
    }
    // Measured: the O(1/N²) remainder is 4e-7 of the mean at N = 200.
    EXPECT_NEAR(mean - exact, predicted, 1e-6 * exact) << n << " positions";
    gaps.push_back((mean - exact) / exact);
  }
  // The ltca default (200 positions) sits 0.114 % above the period mean; 3200 positions 0.011 %.
  EXPECT_NEAR(gaps[0], 1.136e-3, 0.005e-3);
  EXPECT_NEAR(gaps[3], 1.077e-4, 0.005e-4);
}

TEST(LoadedContact, LoadsBalanceAndRespectTheSeparations) {
  const auto k = peModel(0.0, 0);
  PairModifications m = designedTipRelief(*k, 3000.0, true, ReliefShape::kLinear);
  const LoadedToothContact contact(k, m, 1);
  for (double force : {0.0, 100.0, 3000.0, 9000.0}) {
    for (int i = 0; i < 50; ++i) {
      const auto p = contact.solve(i / 50.0, force);
      double total = 0.0;
      for (double load : p.pair_loads) {
        EXPECT_GE(load, 0.0);
        total += load;
      }
      EXPECT_NEAR(total, force, 1e-9 * std::max(force, 1.0));
      EXPECT_GE(p.ste, p.no_load_te - 1e-15);
      if (force == 0.0) EXPECT_EQ(p.ste, p.no_load_te);
    }
  }
  // At the start of the path the entering pair carries the full gear-tip relief C: under a load
  // below the one that closes C it carries nothing.
  const auto first = contact.solve(1e-6, 100.0);
  EXPECT_EQ(first.pair_loads[0], 0.0);
  EXPECT_NEAR(first.pair_loads[1], 100.0, 1e-9);
}

TEST(LoadedContact, SymmetricDesignGivesASymmetricStaticTransmissionError) {
  // Equal gears (25/25) with equal tip reliefs: the STE is symmetric about mid-period.
  GearPairSpec spec = testing::visnadiPairSpec();
  spec.gear.teeth = 25;
  const auto k = std::make_shared<const PotentialEnergyMeshStiffness>(GearPair(spec));
  const LoadedToothContact contact(k, designedTipRelief(*k, 2000.0, true, ReliefShape::kLinear), 1);
  // The two-pair zones mirror each other about the middle of the single-pair zone: φ ↔ φ₀ − φ
  // with φ₀ = (ε − 1) (the two-pair zone of one pitch), modulo one period.
  const double eps = k->contactRatio();
  for (int i = 1; i < 20; ++i) {
    const double a = 0.37 * i / 20.0;
    const double b = std::fmod(eps - 1.0 - a + 2.0, 1.0);
    EXPECT_NEAR(contact.solve(a, 1500.0).ste, contact.solve(b, 1500.0).ste, 1e-10) << a;
  }
}

TEST(LoadedContact, LongReliefFlattensTheSteAtItsDesignLoadAndHarrisMinimumIsThere) {
  const auto k = peModel(0.0, 0);
  const double f0 = 3000.0;
  const LoadedToothContact plain(k, {}, 1);
  const LoadedToothContact relieved(k, designedTipRelief(*k, f0, true, ReliefShape::kLinear), 1);
  const auto base = harrisMap(plain, {f0}, 200).front();
  std::vector<double> loads;
  for (int i = 1; i <= 20; ++i) loads.push_back(f0 * 0.1 * i);  // 0.1 F₀ … 2 F₀
  const auto map = harrisMap(relieved, loads, 200);
  const auto best = std::min_element(map.begin(), map.end(), [](const auto& a, const auto& b) {
    return a.peak_to_peak < b.peak_to_peak;
  });
  std::printf(
      "ptp STE at F0: unmodified %.4g um, long relief %.4g um (ratio %.3g); Harris "
      "minimum at %.4g N (F0 = %.4g N)\n",
      1e6 * base.peak_to_peak, 1e6 * map[9].peak_to_peak, map[9].peak_to_peak / base.peak_to_peak,
      best->force, f0);
  EXPECT_LT(map[9].peak_to_peak, 0.25 * base.peak_to_peak);
  EXPECT_NEAR(best->force, f0, 0.1 * f0 + 1e-9);  // within one load step
}

TEST(LoadedContact, CrownedHelicalConvergesWithSlices) {
  // Loaded STE of a crowned 5° helical pair: the change from n to 2n slices falls at least
  // first order (midpoint slices of a piecewise-smooth integrand).
  PairModifications m;
  m.pinion.crowning = 5e-6;
  std::vector<double> ste;
  for (int n : {10, 20, 40, 80, 160}) {
    const LoadedToothContact c(peModel(5.0, n), m, n);
    ste.push_back(c.solve(0.3, 4000.0).ste);
  }
  for (std::size_t i = 2; i < ste.size(); ++i) {
    const double previous = std::abs(ste[i - 1] - ste[i - 2]),
                 change = std::abs(ste[i] - ste[i - 1]);
    EXPECT_LT(change, 0.75 * previous + 1e-15) << i;
  }
  EXPECT_LT(std::abs(ste[4] - ste[3]), 1e-3 * ste[4]);
}

}  // namespace
}  // namespace geardyn

namespace geardyn {
namespace {

TEST(LoadStatistics, GelmansSignChangeAcrossTheDesignLoadAndTheSimulatedMeanForce) {
  // Long linear tip relief designed for F₀: r_ke > 0 and R (eq. 11) > 1 below F₀, r_ke < 0 and
  // R < 1 above; R → 1 near F₀. And the SDOF model with these tables (K tangent, E = δ − F/K)
  // has a simulated mean of K x equal to L_d (Gelman eq. 1 averaged over a period).
  const auto k =
      std::make_shared<const PotentialEnergyMeshStiffness>(GearPair(testing::visnadiPairSpec()));
  const double f0 = 3000.0;
  const LoadedToothContact c(k, designedTipRelief(*k, f0, true, ReliefShape::kLinear), 1);
  double k_bar = 0.0;
  const auto stats =
      meanExcitationAgainstLoad(c, f0, {0.25, 0.5, 0.75, 1.0, 1.25, 1.5}, 400, &k_bar);
  for (const auto& s : stats) {
    std::printf("a = %.2f: r_ke = %+.3f, R(eq. 7) = %.4f, R(eq. 11) = %.4f, dm1(e_f) = %+.4f\n",
                s.a, s.statistics.r_ke, s.statistics.ratio, s.statistics.ratio_eq11,
                s.statistics.delta_m1_ef);
  }
  for (const auto& s : stats) {
    if (s.a < 1.0) {
      EXPECT_GT(s.statistics.r_ke, 0.0) << s.a;
      EXPECT_GT(s.statistics.ratio_eq11, 1.0) << s.a;
    }
    if (s.a > 1.2) {
      EXPECT_LT(s.statistics.r_ke, 0.0) << s.a;
      EXPECT_LT(s.statistics.ratio_eq11, 1.0) << s.a;
    }
  }
  EXPECT_NEAR(stats[3].statistics.ratio_eq11, 1.0, 0.02);  // at F₀

  // Simulated mean dynamic excitation at a = 0.5, below resonance (m from the Visnadi gears).
  // Well damped and below the parametric tongues (f_m = 2 f_n / n), so a periodic steady state
  // exists; the identity mean(K x) = L_d holds at any speed.
  const double mass = 1.0, fm = 0.05 * std::sqrt(k_bar / mass) / (2 * M_PI);
  const GearPairModel model(gearPairModelAtLoad(
      stats[1], 0.5 * f0, mass, 0.2 * 2 * std::sqrt(k_bar * mass), fm, k->contactRatio()));
  TimeResponseOptions o;
  o.method = TimeIntegrator::kDormandPrince;  // rtol 1e-9: periods agree to ~1e-8
  o.steps_per_period = 4000;                  // the sampled mean of K x: O(h²) at the kinks of K
  o.output_points_per_period = 4000;
  o.steady_tolerance = 1e-7;
  const TimeResponse r = solveTimeResponse(model, o);
  ASSERT_TRUE(r.converged()) << r.message;
  double mean_kx = 0.0;
  for (std::size_t j = 0; j < r.t.size(); ++j) mean_kx += model.stiffness(r.t[j]) * r.x[j];
  mean_kx /= static_cast<double>(r.t.size());
  // L_d of the model's continuous tables (exact integration; the 400 samples' mean differs by
  // O(h²) where the tangent stiffness jumps within a table interval: 2e-4 here).
  const double predicted = meanExcitationFromModel(model, f0).dynamic_mean_excitation * f0;
  EXPECT_NEAR(predicted / (stats[1].statistics.dynamic_mean_excitation * f0), 1.0, 1e-3);
  std::printf("a = 0.5: simulated mean of K x = %.6g N, statistical L_d = %.6g N\n", mean_kx,
              predicted);
  EXPECT_NEAR(mean_kx / predicted, 1.0, 2e-7);
}

}  // namespace
}  // namespace geardyn

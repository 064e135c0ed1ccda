/// Loaded tooth contact across the face (issue 36): the lead modifications and the mesh
/// misalignment as separations across the face, the load distribution and K_Hβ against
/// ISO 6336-1:2006 §7.6 (Method C, eqs. 39–41: a linear mismatch F_βy on a face of uniform mesh
/// stiffness c_γβ), the optimal crowning under a misalignment, and the slices' convergence.

#include "geardyn/contact/face_load.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geardyn/error.h"
#include "support/reference_pairs.h"

namespace geardyn {
namespace {

std::shared_ptr<const PotentialEnergyMeshStiffness> faceLoadPeModel(double helix_deg, int slices) {
  PotentialEnergyOptions o;
  o.slices = helix_deg > 0 ? slices : 0;
  return std::make_shared<const PotentialEnergyMeshStiffness>(
      GearPair(testing::visnadiPairSpec(helix_deg)), o);
}

// Without lead modifications and misalignment the slices' separations are the profile terms
// and the crowning alone, as before the lead terms existed: every slice's separation equals the
// former formula (written out here) to round-off, so the ltca results do too.
TEST(FaceLoad, NoMisalignmentNoLeadModificationIsTheFormerContact) {
  const auto k = faceLoadPeModel(5.0, 20);
  PairModifications m;
  m.pinion.tip = {8e-6, 2e-3, ReliefShape::kParabolic};
  m.gear.root = {3e-6, 1e-3, ReliefShape::kLinear};
  m.pinion.crowning = 4e-6, m.gear.crowning = 1e-6;
  m.gear.profile_slope_error = 2e-6;
  const LoadedToothContact contact(k, m, 20);
  const double b = k->faceWidth(), s0 = k->contactStart(), s1 = k->contactEnd();
  int compared = 0;
  for (int i = 0; i < 50; ++i) {
    const double phase = i / 50.0;
    for (int j = 0; j < contact.pairCount(); ++j) {
      double s_pair = 0.0;
      if (!k->pairSection(phase, j, s_pair)) continue;
      for (int n = 0; n < 20; ++n) {
        double stiffness = 0.0, g = 0.0;
        contact.slice(phase, j, n, stiffness, g);
        if (stiffness == 0.0) continue;
        const double s = s_pair + (n + 0.5) / 20 * k->stagger(), z = ((n + 0.5) / 20 - 0.5) * b;
        const double t = (s - s0) / (s1 - s0) - 0.5;
        const double former = m.pinion.tip.at(s1 - s) + m.pinion.root.at(s - s0) +
                              m.gear.tip.at(s - s0) + m.gear.root.at(s1 - s) +
                              (m.pinion.crowning + m.gear.crowning) * (2 * z / b) * (2 * z / b) +
                              m.pinion.profile_slope_error * t - m.gear.profile_slope_error * t;
        EXPECT_NEAR(g, former, 1e-9 * 8e-6);
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 1000);
  // And the face loads sum to the pair loads.
  const auto p = contact.solve(0.3, 3000.0);
  double face = 0.0, pairs = 0.0;
  for (double v : p.face_loads) face += v;
  for (double v : p.pair_loads) pairs += v;
  EXPECT_NEAR(face, pairs, 1e-9 * pairs);
}

/// c_γβ of the unmodified spur pair: the mean tangent stiffness over the sampled positions per
/// unit face width [N/m²], and its largest instantaneous value.
void meshStiffnessPerWidth(const LoadedToothContact& c, int positions, double& mean, double& max) {
  mean = 0.0, max = 0.0;
  for (const auto& p : c.sweep(1000.0, positions)) {
    mean += p.tangent / positions;
    max = std::max(max, p.tangent);
  }
  mean /= c.stiffness().faceWidth(), max /= c.stiffness().faceWidth();
}

// ISO 6336-1:2006 eq. (41): a linear mismatch F_βy with the contact across the whole face gives
// the line load c_γβ (δ − g(z)), linear in z, and K_Hβ = 1 + F_βy c_γβ b / (2 F_m). The slices
// are springs of one stiffness per unit width (spur) at each phase, so the cycle-mean line load
// is linear with the slope of the mean c_γβ: the formula holds to round-off when the contact
// spans the face at every phase (F/(c_max b) > F_βy). Tolerance 1 % as the issue asks; measured
// 1e-12.
TEST(FaceLoad, LinearMismatchWithFullContactMatchesIso6336Eq41) {
  const int slices = 40, positions = 64;
  const auto k = faceLoadPeModel(0.0, 0);
  double c_mean = 0.0, c_max = 0.0;
  meshStiffnessPerWidth(LoadedToothContact(k, {}, slices), positions, c_mean, c_max);
  const double b = k->faceWidth();
  for (double fma : {5e-6, 20e-6}) {
    PairModifications m;
    m.misalignment = fma;
    const LoadedToothContact contact(k, m, slices);
    for (double ratio : {0.1, 0.3}) {  // F_βy c_γβ b / (2 F): K_Hβ = 1.1, 1.3
      const double force = fma * c_mean * b / (2 * ratio);
      ASSERT_GT(force / (c_max * b), fma) << "full contact at every phase";
      const auto d = faceLoadDistribution(contact, force, positions);
      const double iso = 1 + fma * c_mean * b / (2 * force);
      EXPECT_NEAR(d.k_hbeta, iso, 0.01 * iso) << fma << " " << ratio;
      EXPECT_NEAR(d.k_hbeta, iso, 1e-9 * iso);
      EXPECT_GT(d.centre_of_load, 0.0) << "f_ma > 0 loads the +z end";
      EXPECT_EQ(d.loaded_fraction, 1.0);
      RecordProperty("k_hbeta_" + std::to_string(ratio), std::to_string(d.k_hbeta));
    }
  }
}

// ISO 6336-1:2006 eqs. (39), (40): when F_βy c_γβ b / (2 F_m) ≥ 1 the contact covers
// b_cal = b sqrt(2 F_m / (F_βy c_γβ b)) of the face and K_Hβ = sqrt(2 F_βy c_γβ b / F_m): a
// triangle of line load. At each phase, with that phase's c(φ) (all slices in contact carry
// the one stiffness per width of the pairs in contact), against the instantaneous peak over
// mean. The slices sample the triangle at their centres (midpoint rule, the kink where
// contact ends inside a slice): O(1/N²); 40 slices: measured < 0.3 %. Tolerance 1 %.
TEST(FaceLoad, LinearMismatchWithPartialContactMatchesIso6336Eq39) {
  const int slices = 40, positions = 32;
  const auto k = faceLoadPeModel(0.0, 0);
  const double b = k->faceWidth(), fma = 30e-6;
  PairModifications m;
  m.misalignment = fma;
  const LoadedToothContact contact(k, m, slices);
  const LoadedToothContact unmodified(k, {}, slices);
  double worst = 0.0;
  for (double ratio : {1.5, 3.0, 6.0}) {  // F_βy c b / (2F): K_Hβ = sqrt(4 ratio) = 2.4 .. 4.9
    double c_mean = 0.0, c_max = 0.0;
    meshStiffnessPerWidth(unmodified, positions, c_mean, c_max);
    const double force = fma * c_mean * b / (2 * ratio);
    const auto d = faceLoadDistribution(contact, force, positions);
    for (int i = 0; i < positions; ++i) {
      const double c = unmodified.solve(d.points[i].phase, force).tangent / b;  // c(φ)
      const double iso = std::sqrt(2 * fma * c * b / force);
      const double measured = faceLoadFactor(d.line_load[i]);
      ASSERT_GT(iso, 2.0);
      EXPECT_NEAR(measured, iso, 0.01 * iso) << ratio << " phase " << d.points[i].phase;
      worst = std::max(worst, std::abs(measured / iso - 1));
      // The loaded width b_cal/b = sqrt(2 F / (F_βy c b)), eq. (40).
      int loaded = 0;
      for (double w : d.line_load[i]) loaded += w > 0.0 ? 1 : 0;
      EXPECT_NEAR(static_cast<double>(loaded) / slices, std::sqrt(2 * force / (fma * c * b)),
                  1.0 / slices + 1e-12);
    }
    // The cycle mean against eq. (39) with the cycle-mean c_γβ: the peak of the mean is the
    // mean of sqrt(c(φ)), which differs from sqrt(mean c) by the spread of c over the cycle
    // (Jensen): measured 0.6 % for this spur pair (ε_α = 1.6), tolerance 1 %.
    const double iso_mean = std::sqrt(2 * fma * c_mean * b / force);
    EXPECT_NEAR(d.k_hbeta, iso_mean, 0.01 * iso_mean) << ratio;
    RecordProperty("cycle_mean_error_" + std::to_string(ratio),
                   std::to_string(d.k_hbeta / iso_mean - 1));
  }
  RecordProperty("worst_relative_error", std::to_string(worst));
}

// Crowning C_β (separation C_β (2z/b)²) against a misalignment f_ma with the contact across the
// face: the line load is c (δ − 4 C_β z²/b² + f_ma z/b) with mean c (δ − C_β/3) = F/b, its peak
// inside the face when C_β ≥ f_ma/4, so K_Hβ − 1 = c b (C_β/3 + f_ma²/(16 C_β)) / F, smallest at
// C_β* = √3 f_ma / 4 (docs/theory/gear_whine.md). A crowning sweep finds its minimum there, and
// K_Hβ(C_β*) = 1 + c f_ma b / (2√3 F) within 1 % (slices sample the parabola's vertex: O(1/N²)).
TEST(FaceLoad, CrowningSweepIsLowestAtTheOptimumForTheMisalignment) {
  const int slices = 40, positions = 32;
  const auto k = faceLoadPeModel(0.0, 0);
  const double b = k->faceWidth(), fma = 20e-6;
  double c_mean = 0.0, c_max = 0.0;
  meshStiffnessPerWidth(LoadedToothContact(k, {}, slices), positions, c_mean, c_max);
  const double force = 2.5 * fma * c_max * b;  // full contact up to C_β = 2 f_ma
  const double optimum = std::sqrt(3.0) / 4 * fma;
  std::vector<double> sweep{0.0, 0.2 * fma, optimum, 0.7 * fma, fma, 1.5 * fma}, k_hb;
  for (double crowning : sweep) {
    PairModifications m;
    m.misalignment = fma;
    m.pinion.crowning = crowning;
    k_hb.push_back(
        faceLoadDistribution(LoadedToothContact(k, m, slices), force, positions).k_hbeta);
  }
  const auto best = std::min_element(k_hb.begin(), k_hb.end()) - k_hb.begin();
  EXPECT_EQ(sweep[best], optimum);
  const double expected = 1 + c_mean * fma * b / (2 * std::sqrt(3.0) * force);
  EXPECT_NEAR(k_hb[best], expected, 0.01 * expected);
  // The uncrowned pair: eq. (41) again.
  EXPECT_NEAR(k_hb[0], 1 + c_mean * fma * b / (2 * force), 1e-9);
}

// Helix slope and misalignment are the same separation with opposite signs: f_Hβ = f_ma
// cancels it (the lead correction of a known deflection), and the end relief and a lead error
// table enter as tabulated separations.
TEST(FaceLoad, HelixSlopeCompensatesMisalignmentAndTablesInterpolate) {
  const auto k = faceLoadPeModel(0.0, 0);
  PairModifications m;
  m.misalignment = 12e-6;
  m.gear.helix_slope = 12e-6;
  const LoadedToothContact compensated(k, m, 20), perfect(k, {}, 20);
  for (int i = 0; i < 16; ++i) {
    const double phase = i / 16.0;
    EXPECT_NEAR(compensated.solve(phase, 2000.0).ste, perfect.solve(phase, 2000.0).ste, 1e-18);
  }
  PairModifications t;
  const double b = k->faceWidth();
  t.pinion.lead_error_positions = {-0.5 * b, 0.0, 0.5 * b};
  t.pinion.lead_errors = {2e-6, 0.0, 4e-6};
  t.gear.end_relief = {5e-6, 0.25 * b, ReliefShape::kLinear};
  EXPECT_NEAR(t.leadSeparation(-0.25 * b, b), 1e-6, 1e-18);
  EXPECT_NEAR(t.leadSeparation(0.25 * b, b), 2e-6, 1e-18);
  EXPECT_NEAR(t.leadSeparation(0.5 * b, b), 4e-6 + 5e-6, 1e-18);
  EXPECT_NEAR(t.leadSeparation(-0.375 * b, b), 1.5e-6 + 2.5e-6, 1e-18);
  t.pinion.lead_errors.pop_back();
  EXPECT_THROW(LoadedToothContact(k, t, 20), InputError);
}

// Slices: K_Hβ and the mean loaded STE of a crowned (6 µm), misaligned (15 µm) pair at 4 kN as
// the slices double, 10 → 160. Spur: the mean STE converges at second order once the slices
// resolve the loaded zone (measured orders 3.6, 1.0, 2.06; asserted > 1.5 at 40-80-160); K_Hβ
// is the largest slice's line load, so it moves by the sampling of the crowned peak between
// slice centres: within 5e-5 from 40 slices on, not monotone (asserted 2e-4). Helical (15°):
// the contact lines end inside slices and the potential-energy stiffness takes the same
// slices: K_Hβ and the STE change by 1e-4 and 1.6e-4 from 80 to 160 slices (asserted 2e-3).
TEST(FaceLoad, SlicesConvergeWithMeasuredOrder) {
  const auto sweep = [](double helix, std::vector<double>& khb, std::vector<double>& ste) {
    for (int n : {10, 20, 40, 80, 160}) {
      PairModifications m;
      m.misalignment = 15e-6;
      m.pinion.crowning = 6e-6;
      const LoadedToothContact contact(faceLoadPeModel(helix, n), m, n);
      const auto d = faceLoadDistribution(contact, 4000.0, 32);
      khb.push_back(d.k_hbeta);
      double mean = 0.0;
      for (const auto& p : d.points) mean += p.ste / static_cast<double>(d.points.size());
      ste.push_back(mean);
    }
  };
  const auto order = [](const std::vector<double>& v, std::size_t i) {
    return std::log2(std::abs(v[i] - v[i - 1]) / std::abs(v[i + 1] - v[i]));
  };
  std::vector<double> khb, ste, khb_helical, ste_helical;
  sweep(0.0, khb, ste);
  sweep(15.0, khb_helical, ste_helical);
  for (std::size_t i = 0; i < khb.size(); ++i) {
    RecordProperty("spur_khb_" + std::to_string(i), fmt::format("{:.9g}", khb[i]));
    RecordProperty("spur_ste_" + std::to_string(i), fmt::format("{:.9g}", ste[i]));
    RecordProperty("helical_khb_" + std::to_string(i), fmt::format("{:.9g}", khb_helical[i]));
    RecordProperty("helical_ste_" + std::to_string(i), fmt::format("{:.9g}", ste_helical[i]));
  }
  for (std::size_t i = 1; i + 1 < khb.size(); ++i) {
    RecordProperty("spur_order_khb_" + std::to_string(i), fmt::format("{:.3f}", order(khb, i)));
    RecordProperty("spur_order_ste_" + std::to_string(i), fmt::format("{:.3f}", order(ste, i)));
  }
  EXPECT_GT(order(ste, 3), 1.5);
  EXPECT_LT(std::abs(khb[4] - khb[3]), 2e-4 * khb[4]);
  EXPECT_LT(std::abs(khb[4] - khb[2]), 2e-4 * khb[4]);
  EXPECT_LT(std::abs(khb_helical[4] - khb_helical[3]), 2e-3 * khb_helical[4]);
  EXPECT_LT(std::abs(ste_helical[4] - ste_helical[3]), 2e-3 * ste_helical[4]);
}

}  // namespace
}  // namespace geardyn

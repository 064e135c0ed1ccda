/// DTE identification under measurement noise (Rao 2023 §4.7, Tables 4.3–4.4): one 15 s
/// Dormand–Prince run of Table 4.1, then white Gaussian noise of 1 % and 5 % (level × std of
/// each channel, seeded), full spectra by exact bins, and both estimators.
///   - three-step: its errors are printed next to the thesis's (k_m −96 %/−99 %, e_m 1.8/10 %,
///     TE −4…−16 %, TE phase up to 103 %, runouts ≈ 1 %); the test checks the qualitative
///     finding (k_m collapses, the runouts survive).
///   - joint over 50 seeds at 5 %, with a weak prior on k_m from the gear geometry (ISO 6336
///     c_γα b = 1.75e8 N/m for the rig's m = 2 mm, b = 10 mm set; relative sd 1):
///     median |error| ≤ 3 % (or 0.2 µm) for TE amplitudes, ≤ 0.05 rad for the TE phases of
///     harmonics ≥ 10 µm, ≤ 2 % for runouts and e_m; the 95 % intervals hold the truth in ≥ 90 %
///     of the seeds for every parameter; k_m is flagged not identifiable exactly when its
///     interval is wider than ±50 %. Without the prior the TE amplitudes are biased by the
///     unresolved k_m (printed; see the issue note).

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <thread>

#include "geardyn/config/rotor_gearbox.h"
#include "geardyn/identify/dte_identification.h"
#include "geardyn/signal/gear_whirl.h"
#include "geardyn/solvers/rotor_response.h"
#include "geardyn/solvers/train_periodic_record.h"

namespace geardyn {
namespace {

struct Simulated {
  LateralRotorSpec truth = raoTable41Spec();
  std::array<std::vector<double>, 4> clean;
  double sample_rate = 0.0, first_time = 0.0;
};

const Simulated& simulated() {
  static const Simulated s = [] {
    Simulated out;
    // The thesis's 15 s record of the rotor: its gearbox (config/rotor_gearbox.h) from rest.
    std::vector<std::string> warnings;
    const GearTrainModel train(config::lateralRotorGearTrain(out.truth, "test", warnings));
    const TrainRecord r =
        recordTrainFromRest(train, train.inputSpeed(), config::lateralRotorProbeDofs(train),
                            LateralRotorModel(out.truth).commonPeriod(), TrainRecordOptions{});
    for (int c = 0; c < 4; ++c)
      for (long long k = r.window_begin; k < r.window_end; ++k)
        out.clean[c].push_back(r.displacement(k, c));
    out.sample_rate = r.sample_rate;
    out.first_time = r.t[r.window_begin];
    return out;
  }();
  return s;
}

MeasuredWhirlPeaks noisyPeaks(double level, std::uint64_t seed) {
  const Simulated& s = simulated();
  auto channels = s.clean;
  std::mt19937_64 rng(seed);
  for (auto& c : channels) addRelativeNoise(c, level, rng);
  const GearWhirlSetup setup{s.truth.pinion_speed, s.truth.pinion_teeth, s.truth.gear_teeth, 5};
  const GearPairSpectrum spectrum =
      analyseGearPairRecord(channels, s.sample_rate, s.first_time, 0.0, setup, {});
  MeasuredWhirlPeaks m;
  m.pinion_speed = s.truth.pinion_speed;
  m.peaks = spectrum.peaks;
  m.coefficient_sigma = spectrum.coefficient_sigma;
  return m;
}

/// Named scalar views of an identification and of the truth.
struct Entry {
  std::string name;
  double truth;
  bool phase;
  std::function<const IdentifiedValue&(const DteIdentification&)> get;
};

std::vector<Entry> entries(const LateralRotorSpec& t) {
  std::vector<Entry> e = {
      {"k_m", t.mesh_stiffness, false, [](const auto& r) -> auto& {return r.mesh_stiffness;
}
}  // namespace
, {"e_m", t.mean_te, false, [](const auto& r) -> auto& {return r.mean_te;
}  // namespace geardyn
}
, {"c_m", t.mesh_damping, false, [](const auto& r) -> auto& {return r.mesh_damping;
}
}
, {"e_p", t.pinion_runout, false, [](const auto& r) -> auto& {return r.pinion_runout.amplitude;
}
}
, {"phi_p", t.pinion_runout_phase, true, [](const auto& r) -> auto& {return r.pinion_runout.phase;
}
}
, {"e_g", t.gear_runout, false, [](const auto& r) -> auto& {return r.gear_runout.amplitude;
}
}
, {"phi_g", t.gear_runout_phase, true, [](const auto& r) -> auto& {return r.gear_runout.phase;
}
}
,
}
;
for (std::size_t i = 0; i < t.te_x.size(); ++i) {
    e.push_back({fmt::format("TE_x{}", i + 1), t.te_x[i].amplitude, false,
                 [i](const auto& r) -> auto& { return r.te_x[i].amplitude;
}
});
    e.push_back({fmt::format("phi_x{}", i + 1), t.te_x[i].phase, true,
                 [i](const auto& r) -> auto& { return r.te_x[i].phase;
    }
    });
    e.push_back({fmt::format("TE_y{}", i + 1), t.te_y[i].amplitude, false,
                 [i](const auto& r) -> auto& { return r.te_y[i].amplitude;
    }
    });
    e.push_back({fmt::format("phi_y{}", i + 1), t.te_y[i].phase, true,
                 [i](const auto& r) -> auto& { return r.te_y[i].phase;
    }
    });
    }
    return e;
    }

    double errorOf(const Entry& e, double value) {
      return e.phase ? std::remainder(value - e.truth, 2 * M_PI) : value / e.truth - 1.0;
    }

    double median(std::vector<double> v) {
      std::sort(v.begin(), v.end());
      return v[v.size() / 2];
    }

    TEST(DteIdentificationNoise, ThreeStepAgainstTheThesisTables) {
      const auto& truth = simulated().truth;
      IdentificationOptions o;
      o.method = IdentificationMethod::kThreeStep;
      std::printf(
          "three-step, signed errors (%% for magnitudes, %% of the phase as in the thesis):\n");
      for (double level : {0.01, 0.05}) {
        const auto r = identifyDte(truth, {noisyPeaks(level, 1)}, o);
        std::printf("  noise %.0f %%:", 100 * level);
        for (const auto& e : entries(truth)) {
          if (e.name.find('3') != std::string::npos || e.name.find('4') != std::string::npos)
            continue;
          std::printf(" %s %+.3g", e.name.c_str(), 100 * (e.get(r).value / e.truth - 1.0));
        }
        std::printf("\n");
        // The thesis's finding: k_m collapses (−96 %/−99 %), the runouts survive (≈ 1 %).
        EXPECT_LT(r.mesh_stiffness.value / truth.mesh_stiffness - 1.0, -0.5);
        EXPECT_LT(std::abs(r.pinion_runout.amplitude.value / truth.pinion_runout - 1.0), 0.02);
        EXPECT_LT(std::abs(r.gear_runout.amplitude.value / truth.gear_runout - 1.0), 0.02);
      }
      std::printf(
          "  thesis (Table 4.3, 660 rpm): 1 %%: k_m -96 e_m 1.8 TE_x -12 TE_y -14 phi_x 13 "
          "phi_y -5 e_p 0.2 e_g 0.1; 5 %%: k_m -99 e_m 10 TE_x -4.1 TE_y -16 phi_x 103 "
          "phi_y -52 e_p 1.1 e_g 0.7\n");
    }

    void jointStudy(const IdentificationOptions& o, bool check) {
      const auto& truth = simulated().truth;
      const auto list = entries(truth);
      const int seeds = 50;
      std::vector<std::vector<double>> errors(list.size());
      std::vector<int> covered(list.size(), 0);
      int flagged_consistently = 0;
      // The seeds on every core (the analysis and the estimator are re-entrant).
      std::vector<DteIdentification> results(seeds);
      {
        const unsigned workers = std::max(1u, std::thread::hardware_concurrency());
        std::vector<std::thread> pool;
        for (unsigned w = 0; w < workers; ++w) {
          pool.emplace_back([&, w] {
            for (int seed = static_cast<int>(w); seed < seeds; seed += static_cast<int>(workers))
              results[seed] = identifyDte(truth, {noisyPeaks(0.05, 1001 + seed)}, o);
          });
        }
        for (auto& t : pool) t.join();
      }
      for (const auto& r : results) {
        for (std::size_t k = 0; k < list.size(); ++k) {
          const auto& v = list[k].get(r);
          errors[k].push_back(std::abs(errorOf(list[k], v.value)));
          const double lo = v.low, hi = v.high;
          if (list[k].phase ? std::abs(std::remainder(list[k].truth - 0.5 * (lo + hi), 2 * M_PI)) <=
                                  0.5 * (hi - lo)
                            : (lo <= list[k].truth && list[k].truth <= hi))
            ++covered[k];
        }
        const auto& k = r.mesh_stiffness;
        const bool wide = !std::isfinite(k.high) || (k.high - k.low) / 2.0 > 0.5 * k.value;
        if (wide == !k.identifiable) ++flagged_consistently;
      }
      for (std::size_t k = 0; k < list.size(); ++k) {
        const auto& e = list[k];
        const double med = median(errors[k]);
        std::printf("  %-7s median |error| %9.3g%s, 95 %% interval covers %2d/%d\n", e.name.c_str(),
                    e.phase ? med : 100 * med, e.phase ? " rad" : " %  ", covered[k], seeds);
        if (!check) continue;
        EXPECT_GE(covered[k], 45) << e.name;  // ≥ 90 %
        if (e.name.rfind("TE_", 0) == 0) {
          EXPECT_TRUE(med <= 0.03 || med * e.truth <= 0.2e-6) << e.name << " " << med;
        } else if (e.name.rfind("phi_x", 0) == 0 || e.name.rfind("phi_y", 0) == 0) {
          const int h = e.name.back() - '0';
          const double amplitude =
              e.name[4] == 'x' ? truth.te_x[h - 1].amplitude : truth.te_y[h - 1].amplitude;
          if (amplitude >= 10e-6) EXPECT_LE(med, 0.05) << e.name;
        } else if (e.name == "e_p" || e.name == "e_g" || e.name == "e_m") {
          EXPECT_LE(med, 0.02) << e.name;
        }
      }
      std::printf("  k_m identifiability flag consistent with its ±50 %% interval in %d/%d seeds\n",
                  flagged_consistently, seeds);
      if (check) EXPECT_EQ(flagged_consistently, seeds);
    }

    TEST(DteIdentificationNoise, JointWithAGeometryPriorOnTheMeshStiffness) {
      IdentificationOptions o;
      // ISO 6336-1 c_γα b of the rig gear set (Table 5.1): what prior.mesh_stiffness_from =
      // "iso6336" gives for examples/identify_rao2023_table41.toml (checked by a CLI test).
      o.mesh_stiffness.value = 1.7524e8;
      o.mesh_stiffness.relative_sd = 1.0;
      std::printf("joint, 5 %% noise, 50 seeds, k_m prior 1.75e8 N/m (ISO 6336, relative sd 1):\n");
      jointStudy(o, true);
    }

    TEST(DteIdentificationNoise, JointWithoutPriorIsReported) {
      std::printf("joint, 5 %% noise, 50 seeds, no k_m prior:\n");
      jointStudy(IdentificationOptions{}, false);
    }

    }  // namespace
    }  // namespace geardyn

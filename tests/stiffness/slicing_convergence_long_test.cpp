// Label long (opt-in): the convergence order of helical slicing towards the exact face integral.
#include <gtest/gtest.h>

#include <cmath>

#include "geardyn/stiffness/potential_energy_stiffness.h"
#include "support/reference_pairs.h"

namespace geardyn {
namespace {

double maxRelativeError(const GearPair& pair, const PotentialEnergyMeshStiffness& exact,
                        int slices) {
  PotentialEnergyOptions options;
  options.slices = slices;
  options.table_points = 4097;
  const PotentialEnergyMeshStiffness sliced(pair, options);
  double error = 0.0;
  for (int i = 0; i < 20000; ++i) {
    const double phase = (i + 0.5) / 20000;
    error = std::max(error, std::abs(sliced.stiffness(phase) / exact.stiffness(phase) - 1));
  }
  return error;
}

TEST(PotentialEnergyLong, SlicingConvergesAtFirstOrder) {
  // Each slice switches on and off abruptly, so the sliced curve has jumps of size O(1/n): the
  // maximum error halves when the slices double (first order), down to 1e-4 at 4096 slices.
  const GearPair pair(testing::visnadiPairSpec(5.0));
  PotentialEnergyOptions exact_options;
  exact_options.table_points = 4097;
  const PotentialEnergyMeshStiffness exact(pair, exact_options);
  double previous = maxRelativeError(pair, exact, 64);
  for (int slices : {128, 256, 512, 1024, 2048, 4096}) {
    const double error = maxRelativeError(pair, exact, slices);
    EXPECT_NEAR(previous / error, 2.0, 0.35) << slices << " slices";
    previous = error;
  }
  EXPECT_LT(previous, 2e-4);
}

}  // namespace
}  // namespace geardyn

/// Craig–Bampton against CalculiX's own eigenvalues on the example's box housing (issue #37,
/// validation; label `long`): the two-stage reducer's gmsh box (35 k DOFs, C3D10, six seats,
/// feet held), its full model's lowest modes by ccx *FREQUENCY with the six seats tied by
/// *RIGID BODY against the reduction's, below the cut-off and as modes are added.

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <map>
#include <numbers>

#include "geardyn/io/calculix_deck.h"
#include "geardyn/models/housing_superelement.h"
#include "models/housing_beam_deck.h"
#include "models/housing_ccx_modes.h"

namespace geardyn {
namespace {

namespace fs = std::filesystem;

TEST(HousingValidationLong, BoxCraigBamptonAgainstCcxFrequency) {
  testing::TempDir dir;
  fs::path deck_path = GEARDYN_HOUSING_DECK;
  if (!fs::exists(deck_path)) {  // the example's fixture has not run: mesh it here
    deck_path = dir.path / "box.inp";
    const std::string command = "/usr/bin/python3 " +
                                fs::path(GEARDYN_HOUSING_DECK)
                                    .parent_path()
                                    .parent_path()
                                    .append("housing_box_gmsh.py")
                                    .string() +
                                " " + deck_path.string() + " --size 0.03 > /dev/null";
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
  }
  const io::CalculixDeck deck = io::readCalculixDeck(deck_path.string(), "housing.deck");
  std::vector<HousingNodeSet> seats;
  std::map<std::string, std::vector<int>> tied;
  for (const char* s :
       {"INPUT_A", "INPUT_B", "INTERMEDIATE_A", "INTERMEDIATE_B", "OUTPUT_A", "OUTPUT_B"}) {
    seats.push_back({s, deck.nsets.at(s)});
    tied[s] = deck.nsets.at(s);
  }
  constexpr int kFull = 10;
  auto start = std::chrono::steady_clock::now();
  const std::vector<double> full =
      testing::ccxFrequenciesHz(deck_path, deck.nodes, tied, {}, kFull, dir.path);
  ASSERT_EQ(full.size(), static_cast<std::size_t>(kFull));
  std::printf("ccx *FREQUENCY, %d modes: %.1f s\n", kFull,
              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());

  start = std::chrono::steady_clock::now();
  const io::FeMatrices fe = io::runCalculix(deck_path.string(), "housing.deck");
  CraigBamptonOptions options;
  options.modes = 64;
  const ReducedHousing red = reduceHousing(fe, deck.nodes, seats, {}, options);
  std::printf("%zu DOFs: assembly and reduction with %d modes %.1f s\n", fe.dofs.size(),
              options.modes,
              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());

  auto frequencies = [&](Eigen::Index modes) {
    const Eigen::Index n = red.interfaceDofs() + modes;
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(red.K.topLeftCorner(n, n),
                                                                 red.M.topLeftCorner(n, n));
    return Eigen::VectorXd(es.eigenvalues().cwiseMax(0.0).cwiseSqrt() / (2 * std::numbers::pi));
  };
  // The cut-off rule: twice the highest frequency of interest (the tenth mode): the modes kept
  // are the fixed-interface modes below it (truncating the 64 is the reduction with that
  // cut-off). Measured: the first three within 4e-4, the tenth 2.3 % high: the box's walls are
  // plates whose modes the seat rings' constraint modes and 20 fixed-interface modes span
  // poorly; the 0.1 % for every mode below the cut-off is not what this rule gives
  // (docs/theory/housing_superelement.md, validation).
  const double cutoff = 2.0 * full[kFull - 1];
  const Eigen::Index kept = (red.mode_frequencies_hz.array() < cutoff).count();
  ASSERT_LT(kept, options.modes) << "64 modes reach beyond the cut-off";
  const Eigen::VectorXd f = frequencies(kept);
  for (int i = 0; i < kFull; ++i) {
    const double error = f[i] / full[i] - 1.0;
    std::printf("cut-off %.0f Hz (%ld modes): mode %d %.7g Hz, ccx %.7g Hz, error %.2e\n", cutoff,
                static_cast<long>(kept), i + 1, f[i], full[i], error);
    EXPECT_GE(error, -1e-6) << "mode " << i + 1;  // Rayleigh–Ritz: from above
    EXPECT_LT(error, i < 3 ? 1e-3 : 3e-2) << "mode " << i + 1;
  }
  // As modes are added the worst error of the ten falls (measured 1.1, 0.57, 7.1e-2, 4.2e-2,
  // 2.0e-2, 3.7e-3 with 2 ... 64 modes).
  double previous = std::numeric_limits<double>::infinity();
  for (Eigen::Index m : {2, 4, 8, 16, 32, 64}) {
    const Eigen::VectorXd fm = frequencies(m);
    double worst = 0.0;
    for (int i = 0; i < kFull; ++i) worst = std::max(worst, std::abs(fm[i] / full[i] - 1.0));
    std::printf("%2ld fixed-interface modes (to %.0f Hz): worst error of the ten %.3e\n",
                static_cast<long>(m), red.mode_frequencies_hz[m - 1], worst);
    EXPECT_LT(worst, previous) << m << " modes";
    previous = worst;
  }
  EXPECT_LT(previous, 5e-3) << "64 modes";
}

}  // namespace
}  // namespace geardyn

/// A flexible housing in the gearbox file (issue #37): [housing] read, reduced by ccx and
/// Craig–Bampton, joined to the train; bad input names its key or set; the forced response's
/// exact condensation of the housing against the whole block; reciprocity of the housing's FRFs.
/// These tests run ccx (calculix-ccx, scripts/setup.sh) and skip, saying so, without it.

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <complex>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "geardyn/config/gearbox_config.h"
#include "geardyn/config/gearbox_housing.h"
#include "geardyn/error.h"
#include "geardyn/solvers/detail/harmonic_blocks.h"
#include "geardyn/solvers/detail/housing_condensation.h"
#include "geardyn/solvers/train_modal.h"
#include "geardyn/solvers/train_response.h"
#include "geardyn/system/train_housing.h"
#include "models/housing_beam_deck.h"
#include "support/numeric_assertions.h"

namespace geardyn {
namespace {

namespace fs = std::filesystem;
using Complex = std::complex<double>;

bool haveCcx() {
  return std::system("command -v ccx > /dev/null 2>&1") == 0;
}

#define SKIP_WITHOUT_CCX()                                                                \
  if (!haveCcx()) {                                                                       \
    std::fprintf(stderr, "SKIPPED: ccx (calculix-ccx) is not installed; run setup.sh\n"); \
    GTEST_SKIP() << "ccx (calculix-ccx) is not installed";                                \
  }

using testing::TempDir;

/// A clamped steel beam (0.4 m, 20 × 20 mm, 10 × 2 × 2 C3D20) as the housing: seat
/// PINION_BEARING its tip face, GEAR_BEARING its middle cross-section (unless `without_gear_seat`),
/// response points P1 and P2 the section centres at a quarter and three quarters of its length.
fs::path writeHousingDeck(const fs::path& folder, bool without_gear_seat = false,
                          const std::string& extra = "") {
  testing::BeamDeck b;
  b.length = 0.4;
  b.width = b.height = 0.02;
  b.nx = 10;
  b.ny = b.nz = 2;
  const fs::path path = folder / "housing.inp";
  testing::writeBeamDeck(b, path);
  const int gx = 2 * b.nx + 1, gy = 2 * b.ny + 1, gz = 2 * b.nz + 1;
  auto id = [&](int i, int j, int k) { return 1 + i + gx * (j + gy * k); };
  std::ofstream out(path, std::ios::app);
  auto face = [&](const char* name, int i) {
    out << "*NSET, NSET=" << name << "\n";
    for (int k = 0; k < gz; ++k)
      for (int j = 0; j < gy; ++j)
        if ((j % 2) + (k % 2) <= 1) out << id(i, j, k) << ",\n";
  };
  face("PINION_BEARING", gx - 1);
  if (!without_gear_seat) face("GEAR_BEARING", 2 * (b.nx / 2));
  out << "*NSET, NSET=P1\n" << id(2 * (b.nx / 4), gy / 2, gz / 2) << "\n";
  out << "*NSET, NSET=P2\n" << id(2 * (3 * b.nx / 4), gy / 2, gz / 2) << "\n";
  out << extra;
  return path;
}

/// A spur pair on two bearings to the housing, planar, with [housing] `housing` appended.
std::string gearbox(const std::string& housing) {
  return R"([gearbox]
name = "pair in a beam"
dofs = "planar"
[shafts.pinion]
section_lengths = [0.1]
outer_diameters = [0.03]
[shafts.wheel]
section_lengths = [0.1]
outer_diameters = [0.05]
[gears.z1]
shaft = "pinion"
teeth = 20
module = 2e-3
face_width = 0.02
bore_diameter = 0.02
[gears.z2]
shaft = "wheel"
teeth = 40
module = 2e-3
face_width = 0.02
bore_diameter = 0.03
[meshes.m]
gears = ["z1", "z2"]
damping_ratio = 0.05
te_amplitudes = [2e-6, 1e-6]
[bearings.pinion_bearing]
shaft = "pinion"
kyy = 1e8
kzz = 1e8
cyy = 300.0
czz = 300.0
[bearings.gear_bearing]
shaft = "wheel"
kyy = 3e8
kzz = 3e8
cyy = 500.0
czz = 500.0
[operating_point]
input = "pinion"
speed_rpm = 3000.0
torque = 50.0
output = "wheel"
[housing]
)" + housing;
}

std::string housingKeys(const fs::path& deck, const std::string& more = "") {
  return "deck = \"" + deck.string() + "\"\nunits = \"si\"\npoints = [\"P1\", \"P2\"]\n" +
         "stiffness_proportional_damping = 1e-5\n" + more;
}

/// The spec of `text` with its housing attached (cut-off 2 × 3 kHz unless the file sets one).
GearTrainSpec housedSpec(const std::string& text, const fs::path& folder) {
  const config::Config c =
      config::parseConfig(text, (folder / "gearbox.toml").string(), config::gearboxSchema());
  std::vector<std::string> warnings;
  GearTrainSpec spec = config::gearTrainFromConfig(c, warnings);
  config::attachHousing(c, spec, 6000.0, 0.0);
  return spec;
}

/// "key | message" of the InputError `text` raises, "(accepted)" otherwise.
std::string errorOf(const std::string& text, const fs::path& folder) {
  try {
    housedSpec(text, folder);
  } catch (const InputError& e) {
    return e.key() + " | " + e.what();
  }
  return "(accepted)";
}

TEST(HousingGearbox, JoinsTheBearingsToTheirSeatsAndNamesHousingModes) {
  SKIP_WITHOUT_CCX();
  TempDir dir;
  const fs::path deck = writeHousingDeck(dir.path);
  const GearTrainModel model(housedSpec(gearbox(housingKeys(deck)), dir.path));
  ASSERT_GE(model.housingFirstDof(), 0);
  const ReducedHousing& h = model.spec().housing->reduced;
  EXPECT_EQ(h.seats, (std::vector<std::string>{"pinion_bearing", "gear_bearing"}));
  EXPECT_EQ(model.dofCount() - model.housingFirstDof(), h.K.rows());
  EXPECT_GT(h.mode_frequencies_hz.size(), 0);
  EXPECT_EQ(model.dofName(model.housingFirstDof()), "housing.pinion_bearing.x");
  EXPECT_EQ(model.dofName(model.dofCount() - 1),
            "housing.mode" + std::to_string(h.mode_frequencies_hz.size()));
  TrainModalOptions options;
  const auto modes = trainModes(model, model.inputSpeed(), options);
  int housing_modes = 0;
  for (const TrainMode& m : modes) {
    double bodies = 0.0;
    for (double e : m.body_kinetic_energy) bodies += e;
    // The bodies' and the housing's kinetic energy fractions add up to one.
    EXPECT_NEAR(bodies + m.housing_fraction, 1.0, 1e-12);
    if (m.whirl == "housing") {
      ++housing_modes;
      EXPECT_GT(m.housing_fraction, 0.5);
    }
  }
  EXPECT_GT(housing_modes, 0) << "the beam's own bending modes lie below the cut-off";
}

TEST(HousingGearbox, BadInputNamesItsKeyOrSet) {
  SKIP_WITHOUT_CCX();
  TempDir dir;
  const fs::path deck = writeHousingDeck(dir.path);
  // Units not declared.
  const std::string no_units =
      errorOf(gearbox("deck = \"" + deck.string() + "\"\npoints = [\"P1\"]\n"), dir.path);
  EXPECT_EQ(no_units.rfind("housing.units | ", 0), 0u) << no_units;
  // A seat set that names no bearing.
  const std::string stray = errorOf(
      gearbox(housingKeys(deck, "seats = [\"PINION_BEARING\", \"GEAR_BEARING\", \"FOO\"]\n")),
      dir.path);
  EXPECT_EQ(stray.rfind("housing.seats | ", 0), 0u) << stray;
  EXPECT_NE(stray.find("FOO"), std::string::npos) << stray;
  // A bearing without a seat: named in the listed seats, or missing from the deck.
  const std::string unlisted =
      errorOf(gearbox(housingKeys(deck, "seats = [\"PINION_BEARING\"]\n")), dir.path);
  EXPECT_EQ(unlisted.rfind("housing.seats | ", 0), 0u) << unlisted;
  EXPECT_NE(unlisted.find("gear_bearing"), std::string::npos) << unlisted;
  TempDir other;
  const fs::path no_seat = writeHousingDeck(other.path, true);
  const std::string missing = errorOf(gearbox(housingKeys(no_seat)), other.path);
  EXPECT_EQ(missing.rfind("housing.seats | ", 0), 0u) << missing;
  EXPECT_NE(missing.find("gear_bearing"), std::string::npos) << missing;
  // A deck ccx rejects: its message is shown.
  TempDir bad;
  const fs::path rejected =
      writeHousingDeck(bad.path, false, "*SOLID SECTION, ELSET=NOSUCHSET, MATERIAL=STEEL\n");
  const std::string ccx = errorOf(gearbox(housingKeys(rejected)), bad.path);
  EXPECT_EQ(ccx.rfind("housing.deck | ", 0), 0u) << ccx;
  EXPECT_NE(ccx.find("*ERROR"), std::string::npos) << ccx;
  // A cut-off below the first fixed-interface mode.
  const std::string low = errorOf(gearbox(housingKeys(deck, "cutoff_hz = 1.0\n")), dir.path);
  EXPECT_EQ(low.rfind("housing.cutoff_hz | ", 0), 0u) << low;
}

TEST(HousingGearbox, CondensedForcedResponseEqualsTheWholeBlock) {
  SKIP_WITHOUT_CCX();
  TempDir dir;
  const GearTrainModel model(
      housedSpec(gearbox(housingKeys(writeHousingDeck(dir.path))), dir.path));
  TrainSteadyOptions exact, fast;
  exact.mesh_harmonics = fast.mesh_harmonics = 4;
  exact.condense_housing = false;
  const TrainSteadySolver reference(model, exact), condensed(model, fast);
  for (double rpm : {700.0, 3000.0, 8000.0}) {
    const double speed = rpm * std::numbers::pi / 30.0;
    const TrainSteadyState a = reference.solve(speed), b = condensed.solve(speed);
    // Two exact solutions of one linear system: round-off of the LU of 12 + n_h DOFs against
    // the condensation's (condition numbers ~1e6 from the stiff bearings): 1e-9 of the largest.
    const double scale = a.harmonic.cwiseAbs().maxCoeff();
    EXPECT_LE((a.harmonic - b.harmonic).cwiseAbs().maxCoeff(), 1e-9 * scale) << rpm << " rpm";
  }
}

TEST(HousingGearbox, FrfsBetweenTwoResponsePointsAreReciprocal) {
  SKIP_WITHOUT_CCX();
  TempDir dir;
  const GearTrainModel model(
      housedSpec(gearbox(housingKeys(writeHousingDeck(dir.path))), dir.path));
  const ReducedHousing& h = model.spec().housing->reduced;
  const int h0 = model.housingFirstDof(), n = model.dofCount();
  // At rest (no gyroscopic term) the dynamic stiffness is symmetric: a force along y at P1
  // gives at P2 along z what the force along z at P2 gives at P1 along y (Maxwell–Betti).
  const Eigen::MatrixXd K = model.meanStiffnessAt(0.0), C = model.dampingAt(0.0);
  auto condensation = detail::HousingCondensation::of(model);
  ASSERT_TRUE(condensation);
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n, 2);
  rhs.col(0).tail(n - h0) = h.recovery.row(0 * 3 + 1).transpose();  // P1, y
  rhs.col(1).tail(n - h0) = h.recovery.row(1 * 3 + 2).transpose();  // P2, z
  for (double f : {50.0, 400.0, 2000.0}) {
    detail::HarmonicBlocks blocks(K, model.mass(), C, Eigen::MatrixXd(), 64, true, condensation);
    ASSERT_TRUE(blocks.condensesHousing());
    blocks.factorize(1, 2.0 * std::numbers::pi * f);
    const Eigen::MatrixXcd x = blocks.solve(1, rhs.cast<Complex>());
    const Complex h21 = h.recovery.row(1 * 3 + 2).cast<Complex>() * x.col(0).tail(n - h0);
    const Complex h12 = h.recovery.row(0 * 3 + 1).cast<Complex>() * x.col(1).tail(n - h0);
    // Reciprocity holds exactly for the symmetric model; the solve's round-off is ~1e-12.
    EXPECT_LE(std::abs(h21 - h12), 1e-8 * std::abs(h12)) << f << " Hz";
    EXPECT_GT(std::abs(h12), 0.0);
  }
}

}  // namespace
}  // namespace geardyn

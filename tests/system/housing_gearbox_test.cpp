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
#include <string>

#include "geardyn/config/gearbox_config.h"
#include "geardyn/config/gearbox_housing.h"
#include "geardyn/error.h"
#include "geardyn/io/calculix_deck.h"
#include "geardyn/solvers/detail/harmonic_blocks.h"
#include "geardyn/solvers/detail/housing_condensation.h"
#include "geardyn/solvers/train_modal.h"
#include "geardyn/solvers/train_response.h"
#include "geardyn/solvers/train_time.h"
#include "geardyn/stiffness/fourier_stiffness.h"
#include "geardyn/system/train_housing.h"
#include "models/housing_beam_deck.h"
#include "support/numeric_assertions.h"
#include "system/mesh_force_sample.h"

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
    // The response points: R q_h of the whole block's rows against R Φ y of the condensation.
    ASSERT_EQ(a.housing_points.rows(), 6);
    ASSERT_EQ(b.housing_points.cols(), b.harmonic.cols());
    const double points = a.housing_points.cwiseAbs().maxCoeff();
    EXPECT_LE((a.housing_points - b.housing_points).cwiseAbs().maxCoeff(), 1e-9 * points);
    // The forced sweep's solve (issue 37): the seats' rows and the points only. What it keeps
    // is the full solve's to round-off of the products' blocking (1e-12); the other housing
    // rows are zero (the example box keeps 36 of 90); the sampled forces, read from the kept
    // rows, are the same.
    const TrainSteadyState c = condensed.solve(speed, /*housing_rows=*/false);
    const int n_t = model.housingFirstDof();
    EXPECT_LE((c.harmonic.topRows(n_t) - b.harmonic.topRows(n_t)).cwiseAbs().maxCoeff(),
              1e-12 * scale);
    int kept = 0;
    for (Eigen::Index i = n_t; i < c.harmonic.rows(); ++i) {
      if (c.harmonic.row(i).isZero(0.0)) continue;
      ++kept;
      EXPECT_LE((c.harmonic.row(i) - b.harmonic.row(i)).cwiseAbs().maxCoeff(), 1e-12 * scale);
    }
    EXPECT_GT(kept, 0);  // all of this small housing's 28 (its seats read every coordinate)
    EXPECT_LE((c.housing_points - b.housing_points).cwiseAbs().maxCoeff(), 1e-12 * points);
    for (std::size_t e = 0; e < b.element_dynamic_force.size(); ++e) {
      EXPECT_NEAR(c.element_dynamic_force[e], b.element_dynamic_force[e],
                  1e-12 * std::max(1.0, b.element_dynamic_force[e]));
    }
    EXPECT_LE((c.mesh_force - b.mesh_force).cwiseAbs().maxCoeff(),
              1e-12 * b.mesh_force.cwiseAbs().maxCoeff());
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

/// Writes `A` as MatrixMarket: one triangle of a `symmetric` file, or both (`general`), with 17
/// digits (a double round-trips exactly), as another FE tool's export would.
void writeMatrixMarket(const Eigen::SparseMatrix<double>& A, const fs::path& path, bool symmetric) {
  std::ofstream out(path);
  out.precision(17);
  out << "%%MatrixMarket matrix coordinate real " << (symmetric ? "symmetric" : "general") << "\n";
  const Eigen::SparseMatrix<double> L =
      symmetric ? Eigen::SparseMatrix<double>(A.triangularView<Eigen::Lower>()) : A;
  out << A.rows() << " " << A.cols() << " " << L.nonZeros() << "\n";
  for (int k = 0; k < L.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(L, k); it; ++it)
      out << it.row() + 1 << " " << it.col() + 1 << " " << it.value() << "\n";
}

TEST(HousingGearbox, MatrixMarketHousingIsTheSameMachineAsCcxs) {
  // The path of a user of Abaqus, Nastran or ANSYS (docs/guide/housing.md): K and M exported in
  // MatrixMarket with the node.direction map, the deck giving only nodes and sets. Written here
  // from ccx's own assembly of the same deck, the gearbox with them is the ccx gearbox.
  SKIP_WITHOUT_CCX();
  TempDir dir;
  const fs::path deck = writeHousingDeck(dir.path);
  const io::FeMatrices fe = io::runCalculix(deck.string(), "housing.deck");
  writeMatrixMarket(fe.K, dir.path / "k.mtx", true);
  writeMatrixMarket(fe.M, dir.path / "m.mtx", false);
  {
    std::ofstream map(dir.path / "housing.dof");
    for (const io::FeDof& d : fe.dofs) map << d.node << "." << d.direction << "\n";
  }
  const std::string files =
      "stiffness_matrix = \"k.mtx\"\nmass_matrix = \"m.mtx\"\ndof_map = \"housing.dof\"\n";
  const GearTrainModel ccx(housedSpec(gearbox(housingKeys(deck)), dir.path));
  const GearTrainModel mtx(housedSpec(gearbox(housingKeys(deck, files)), dir.path));
  const ReducedHousing &a = ccx.spec().housing->reduced, &b = mtx.spec().housing->reduced;
  ASSERT_EQ(a.K.rows(), b.K.rows());
  // The same doubles in the same order: the reductions agree to round-off of the sparse
  // products' summation order, 1e-12 of the largest entry.
  EXPECT_TRUE(testing::isClose(b.K, a.K, 0.0, 1e-12 * a.K.cwiseAbs().maxCoeff()));
  EXPECT_TRUE(testing::isClose(b.M, a.M, 0.0, 1e-12 * a.M.cwiseAbs().maxCoeff()));
  EXPECT_TRUE(
      testing::isClose(b.recovery, a.recovery, 0.0, 1e-12 * a.recovery.cwiseAbs().maxCoeff()));
  TrainModalOptions options;
  const auto fa = trainModes(ccx, ccx.inputSpeed(), options);
  const auto fb = trainModes(mtx, mtx.inputSpeed(), options);
  ASSERT_EQ(fa.size(), fb.size());
  for (std::size_t i = 0; i < fa.size(); ++i) {
    EXPECT_TRUE(testing::isClose(fb[i].frequency, fa[i].frequency, 1e-10)) << "mode " << i;
  }

  // Bad input: the three files come together; a map of another size; a fixed mount (the other
  // tool's matrices hold their boundary conditions).
  const std::string partial =
      errorOf(gearbox(housingKeys(deck, "stiffness_matrix = \"k.mtx\"\n")), dir.path);
  EXPECT_EQ(partial.rfind("housing.mass_matrix | ", 0), 0u) << partial;
  {
    std::ofstream map(dir.path / "short.dof");
    for (std::size_t i = 0; i + 1 < fe.dofs.size(); ++i)
      map << fe.dofs[i].node << "." << fe.dofs[i].direction << "\n";
  }
  const std::string short_map =
      errorOf(gearbox(housingKeys(deck,
                                  "stiffness_matrix = \"k.mtx\"\nmass_matrix = \"m.mtx\"\n"
                                  "dof_map = \"short.dof\"\n")),
              dir.path);
  EXPECT_EQ(short_map.rfind("housing.stiffness_matrix | ", 0), 0u) << short_map;
  const std::string fixed =
      errorOf(gearbox(housingKeys(deck, files + "[housing.mounts.P1]\n")), dir.path);
  EXPECT_EQ(fixed.rfind("housing.mounts.P1 | ", 0), 0u) << fixed;
}

TEST(HousingGearbox, NewmarkWithTheHousingReachesTheForcedSteadyState) {
  // The time analysis's Newmark run of the housed pair against the forced response's steady
  // state at one speed: a smooth mesh stiffness (three harmonics, so that 20 harmonics of the
  // balance are exact to 1e-6) and the transmission error excite train and housing; over one
  // mesh period at the end of the run the response point P2's motion (the housing's modal
  // coordinates through the recovery) and the mesh force agree. Newmark's period error at the
  // tenth mesh harmonic, (ω Δt)²/12 with 512 steps a period, is 1.5e-5; the transient's
  // remainder after the derived duration is the rest: 0.5 % of the peak to peak (the gear-train
  // issue's acceptance of Newmark against the balance).
  SKIP_WITHOUT_CCX();
  TempDir dir;
  GearTrainSpec spec = housedSpec(gearbox(housingKeys(writeHousingDeck(dir.path))), dir.path);
  double mean = 0.0;  // the mesh's own mean stiffness over a cycle (midpoint rule) [N/m]
  for (int i = 0; i < 1000; ++i)
    mean += spec.meshes[0].stiffness->stiffness((i + 0.5) / 1000) / 1000;
  spec.meshes[0].stiffness = std::make_shared<FourierMeshStiffness>(
      mean, std::vector<double>{0.12, 0.05, 0.02}, std::vector<double>{0.0, 0.3, 1.1}, 1.6);
  const GearTrainModel model(spec);
  const double speed = model.inputSpeed();
  TrainSteadyOptions steady;
  steady.mesh_harmonics = 20;
  const TrainSteadyState hbm = solveTrainSteadyState(model, speed, steady);
  TrainTimeOptions time;
  time.steps_per_mesh_period = 512;
  const TrainTimeResponse newmark = solveTrainTimeResponse(model, speed, time);
  ASSERT_EQ(newmark.status, "completed") << newmark.message;
  const double period = 1.0 / hbm.base_frequency;
  const Eigen::VectorXd t = newmark.t.array() - period * std::floor(newmark.t(0) / period);
  const Eigen::MatrixXd q = hbm.displacement(t);
  const ReducedHousing& h = model.spec().housing->reduced;
  const int h0 = model.housingFirstDof(), nh = static_cast<int>(h.K.rows());
  const Eigen::RowVectorXd p2_y = h.recovery.row(1 * 3 + 1);  // P2, y: in the mesh's plane
  Eigen::VectorXd a(t.size()), b(t.size());
  for (Eigen::Index k = 0; k < t.size(); ++k) {
    a[k] = p2_y.dot(q.row(k).segment(h0, nh));
    b[k] = p2_y.dot(newmark.displacement.row(k).segment(h0, nh));
  }
  const double p2p = a.maxCoeff() - a.minCoeff();
  // The beam's static sag under the mesh load (2.5 mm) carries a vibration of ~90 nm.
  ASSERT_GT(p2p, 1e-9) << "no housing vibration to compare";
  const double worst = (a - b).cwiseAbs().maxCoeff();
  std::printf(
      "housed pair at %.0f rpm: P2's y, Newmark against the steady state: worst %.2e of "
      "its peak to peak %.3e m (%lld steps)\n",
      speed * 30.0 / std::numbers::pi, worst / p2p, p2p, newmark.steps);
  EXPECT_LT(worst, 5e-3 * p2p);
  const double f_p2p = hbm.mesh_force_max[0] - hbm.mesh_force_min[0];
  double worst_force = 0.0;
  for (Eigen::Index k = 0; k < t.size(); ++k) {
    const double f = testing::meshForceAt(model.meshes()[0], q.row(k), t(k), speed);
    worst_force = std::max(worst_force, std::abs(f - newmark.mesh_force(k, 0)));
  }

  std::printf("mesh force: worst %.2e of its peak to peak %.3e N\n", worst_force / f_p2p, f_p2p);
  EXPECT_LT(worst_force, 5e-3 * f_p2p);
}

// The seats' r × r LU of the condensation (pivots on |Re| + |Im|, LAPACK's measure) against
// Eigen's PartialPivLU (pivots on |z|): the same solution of A X = B to round-off (A is
// diagonally weighted, cond ≈ 10, so both are within ~1e-15 of the exact X; 1e-12 leaves room),
// with a tiny leading entry that forces a row swap at the first step, and right-hand sides with
// zeros, which the forward sweep skips.
TEST(HousingCondensation, SeatLuSolvesAsEigensPartialPivotingLu) {
  std::srand(7);
  const Eigen::Index n = 12;
  Eigen::MatrixXcd A = Eigen::MatrixXcd::Random(n, n) + 4.0 * Eigen::MatrixXcd::Identity(n, n);
  A(0, 0) = Complex(1e-12, -1e-12);
  const Eigen::MatrixXcd B = Eigen::MatrixXcd::Random(n, 5);
  detail::SmallComplexLU lu;
  lu.compute(A);
  Eigen::MatrixXcd X = B;
  lu.solveInPlace(X);
  const Eigen::PartialPivLU<Eigen::MatrixXcd> reference(A);
  EXPECT_LE((X - reference.solve(B)).norm(), 1e-12 * X.norm());
  EXPECT_LE((A * X - B).norm(), 1e-13 * A.norm() * X.norm());
  Eigen::MatrixXcd E = Eigen::MatrixXcd::Zero(n, 2);
  E(3, 0) = 1.0;
  E(n - 1, 1) = Complex(0.0, 2.0);
  Eigen::MatrixXcd Y = E;
  lu.solveInPlace(Y);
  EXPECT_LE((Y - reference.solve(E)).norm(), 1e-12 * Y.norm());
}

}  // namespace
}  // namespace geardyn

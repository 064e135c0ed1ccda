/// The housing's finite-element path (issue #37, items 1-2): ccx's matrix storage read back, the
/// rigid seat tie, Craig–Bampton against the full model and against beam theory, Guyan's limit,
/// and the errors a user sees. Needs `ccx` (calculix-ccx, installed by scripts/setup.sh).

#include "geardyn/models/housing_superelement.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "geardyn/config/housing_source.h"
#include "geardyn/error.h"
#include "geardyn/io/calculix_deck.h"
#include "geardyn/io/fe_matrices.h"
#include "models/housing_beam_deck.h"
#include "support/numeric_assertions.h"

namespace geardyn {
namespace {

namespace fs = std::filesystem;
using geardyn::testing::BeamDeck;
using geardyn::testing::isClose;

using testing::TempDir;

struct Beam {
  io::CalculixDeck deck;
  io::FeMatrices fe;
};

Beam assemble(const BeamDeck& b, const TempDir& dir) {
  const fs::path inp = dir.path / "beam.inp";
  testing::writeBeamDeck(b, inp);
  Beam beam{io::readCalculixDeck(inp.string(), "housing.deck"),
            io::runCalculix(inp.string(), "housing.deck")};
  return beam;
}

HousingNodeSet set(const Beam& beam, const std::string& name) {
  return {name, beam.deck.nsets.at(name)};
}

/// The rigid seat tie written out anew, independently of reduceHousing's build: columns = 6
/// seat DOFs, then every other DOF in mesh order; u_n = u_c + θ × (x_n − c).
Eigen::SparseMatrix<double> tieMatrix(const Beam& beam, const HousingNodeSet& seat,
                                      Eigen::Vector3d& c) {
  c.setZero();
  for (int n : seat.nodes) c += beam.deck.nodes.at(n);
  c /= static_cast<double>(seat.nodes.size());
  const Eigen::Index n = static_cast<Eigen::Index>(beam.fe.dofs.size());
  std::vector<Eigen::Triplet<double>> t;
  Eigen::Index interior = 0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const io::FeDof d = beam.fe.dofs[static_cast<std::size_t>(i)];
    if (std::find(seat.nodes.begin(), seat.nodes.end(), d.node) == seat.nodes.end()) {
      t.emplace_back(i, 6 + interior++, 1.0);
      continue;
    }
    const Eigen::Vector3d r = beam.deck.nodes.at(d.node) - c;
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d motion = Eigen::Vector3d::Unit(k).cross(r);  // θ_k e_k × r
      t.emplace_back(i, 3 + k, motion[d.direction - 1]);
    }
    t.emplace_back(i, d.direction - 1, 1.0);
  }
  Eigen::SparseMatrix<double> T(n, 6 + interior);
  T.setFromTriplets(t.begin(), t.end());
  return T;
}

/// Tᵀ A T as a dense matrix.
Eigen::MatrixXd projected(const Eigen::SparseMatrix<double>& T,
                          const Eigen::SparseMatrix<double>& A) {
  return Eigen::MatrixXd(Eigen::SparseMatrix<double>(T.transpose() * A * T));
}

Eigen::VectorXd frequenciesHz(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M) {
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(K, M);
  return es.eigenvalues().cwiseMax(0.0).cwiseSqrt() / (2.0 * std::numbers::pi);
}

// A short, coarse beam: a dense reference stays cheap (about 900 DOFs).
BeamDeck smallBeam() {
  BeamDeck b;
  b.length = 0.4;
  b.nx = 8;
  b.ny = b.nz = 1;
  return b;
}

TEST(CcxMatrixStorage, FreeBeamHasTheRigidBodyNullSpaceAndItsMass) {
  TempDir dir;
  BeamDeck b = smallBeam();
  b.clamped = false;
  const Beam beam = assemble(b, dir);
  const Eigen::Index n = beam.fe.K.rows();
  ASSERT_EQ(n, 3 * static_cast<Eigen::Index>(beam.deck.nodes.size()));
  Eigen::VectorXd tx = Eigen::VectorXd::Zero(n), rz = Eigen::VectorXd::Zero(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const io::FeDof d = beam.fe.dofs[static_cast<std::size_t>(i)];
    const Eigen::Vector3d x = beam.deck.nodes.at(d.node);
    if (d.direction == 1) tx[i] = 1.0;
    rz[i] = Eigen::Vector3d::UnitZ().cross(x)[d.direction - 1];
  }
  const double scale = beam.fe.K.diagonal().cwiseAbs().maxCoeff();
  // Rigid motions strain nothing: ccx prints 14 significant digits, so 1e-10 of the largest
  // diagonal entry is round-off.
  EXPECT_LT((beam.fe.K * tx).cwiseAbs().maxCoeff(), 1e-10 * scale);
  EXPECT_LT((beam.fe.K * rz).cwiseAbs().maxCoeff(), 1e-10 * scale * b.length);
  // A translation's kinetic energy: the consistent mass sums to ρ V (printed to 14 digits).
  EXPECT_TRUE(isClose(tx.dot(beam.fe.M * tx), b.rho * b.length * b.width * b.height, 1e-12));
  EXPECT_TRUE(isClose((beam.fe.K - Eigen::SparseMatrix<double>(beam.fe.K.transpose())).norm(), 0.0,
                      0.0, 1e-14 * beam.fe.K.norm()));
}

TEST(CcxMatrixStorage, MatrixMarketRoundTripsTheAssembledModel) {
  TempDir dir;
  const Beam beam = assemble(smallBeam(), dir);
  auto write = [&](const Eigen::SparseMatrix<double>& A, const fs::path& path) {
    std::ofstream out(path);
    out.precision(17);
    out << "%%MatrixMarket matrix coordinate real symmetric\n% lower triangle\n";
    const Eigen::SparseMatrix<double> L = A.triangularView<Eigen::Lower>();
    out << A.rows() << " " << A.cols() << " " << L.nonZeros() << "\n";
    for (int k = 0; k < L.outerSize(); ++k)
      for (Eigen::SparseMatrix<double>::InnerIterator it(L, k); it; ++it)
        out << it.row() + 1 << " " << it.col() + 1 << " " << it.value() << "\n";
  };
  write(beam.fe.K, dir.path / "k.mtx");
  write(beam.fe.M, dir.path / "m.mtx");
  {
    std::ofstream dof(dir.path / "map.dof");
    for (const io::FeDof& d : beam.fe.dofs) dof << d.node << "." << d.direction << "\n";
  }
  const io::FeMatrices back =
      io::readMatrixMarketModel((dir.path / "k.mtx").string(), (dir.path / "m.mtx").string(),
                                (dir.path / "map.dof").string(), "housing.stiffness_file");
  EXPECT_EQ((back.K - beam.fe.K).norm(), 0.0);  // 17 digits round-trip a double exactly
  EXPECT_EQ((back.M - beam.fe.M).norm(), 0.0);
  ASSERT_EQ(back.dofs.size(), beam.fe.dofs.size());

  std::ofstream(dir.path / "bad.mtx") << "%%MatrixMarket matrix array real general\n2 2\n1\n";
  try {
    io::readMatrixMarket((dir.path / "bad.mtx").string(), "housing.stiffness_file");
    FAIL() << "an array-format file was read";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "housing.stiffness_file");
    EXPECT_NE(std::string(e.what()).find("coordinate real symmetric"), std::string::npos);
  }
}

TEST(CcxRunner, ShowsCcxsMessageWhenItRejectsTheDeck) {
  TempDir dir;
  const fs::path inp = dir.path / "bad.inp";
  std::ofstream(inp) << "*NODE\n1, 0, 0, 0\n*SOLID SECTION, ELSET=NOSUCHSET, MATERIAL=STEEL\n";
  try {
    io::runCalculix(inp.string(), "housing.deck");
    FAIL() << "ccx accepted a deck without elements";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "housing.deck");
    EXPECT_NE(std::string(e.what()).find("*ERROR"), std::string::npos) << e.what();
  }
  try {
    io::runCalculix(inp.string(), "housing.deck", "geardyn-no-such-ccx");
    FAIL() << "a missing ccx was not reported";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("could not be started"), std::string::npos);
  }
}

TEST(CcxRunner, RefusesAMeshThatWouldNotFitBeforeRunningCcx) {
  TempDir dir;
  const fs::path inp = dir.path / "beam.inp";
  testing::writeBeamDeck(smallBeam(), inp);
  const io::CalculixDeck deck = io::readCalculixDeck(inp.string(), "housing.deck");
  const double bytes = io::estimateHousingBytes(deck);
  EXPECT_NO_THROW(io::checkHousingFits(deck, inp.string(), "housing.deck", 2.0 * bytes));
  try {
    io::checkHousingFits(deck, inp.string(), "housing.deck", 0.5 * bytes);
    FAIL() << "a mesh twice the limit was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "housing.deck");
    EXPECT_NE(std::string(e.what()).find("fits in memory"), std::string::npos);
  }
  // The deck reader's sets: the end faces of a 1 × 1 section of quadratic hexahedra hold the
  // 8 corner and mid-edge nodes of their face.
  EXPECT_EQ(deck.nsets.at("TIP").size(), 8u);
  EXPECT_EQ(deck.elements, 2 * 8);  // two lines an element (16 entries a line at most)
}

TEST(CraigBampton, WithoutModesIsGuyansStaticCondensation) {
  TempDir dir;
  const Beam beam = assemble(smallBeam(), dir);
  const HousingNodeSet tip = set(beam, "TIP");
  CraigBamptonOptions options;
  options.modes = 0;
  const ReducedHousing red = reduceHousing(beam.fe, beam.deck.nodes, {tip}, {}, options);
  ASSERT_EQ(red.K.rows(), 6);

  Eigen::Vector3d c;
  const Eigen::SparseMatrix<double> T = tieMatrix(beam, tip, c);
  EXPECT_TRUE(isClose(red.centres[0], c, 1e-14, 1e-15));
  const Eigen::MatrixXd K = projected(T, beam.fe.K);
  const Eigen::Index no = K.rows() - 6;
  const Eigen::MatrixXd schur =
      K.topLeftCorner(6, 6) -
      K.topRightCorner(6, no) * K.bottomRightCorner(no, no).ldlt().solve(K.bottomLeftCorner(no, 6));
  // Sparse LDLᵀ against dense LDLᵀ of the same SPD matrix (condition ~1e6 for this beam): 1e-9
  // of the largest entry covers both factorisations' round-off.
  EXPECT_TRUE(isClose(red.K, schur, 0.0, 1e-9 * schur.cwiseAbs().maxCoeff()));
  // Guyan's tip stiffness against beam theory: a clamped-free beam's transverse tip stiffness is
  // 3EI/L³ (Euler–Bernoulli) softened by shear, 1/(L³/3EI + L/(κGA)) (Timoshenko, κ = 5/6);
  // the coarse mesh (8 × 1 × 1 quadratic elements, L/h = 8), the rigid tip face and the
  // clamped face's Poisson stiffening make the solid 2.6 % stiffer (measured); 4 %.
  const BeamDeck b = smallBeam();
  const double I = b.width * std::pow(b.height, 3) / 12.0, A = b.width * b.height;
  const double G = b.E / (2.0 * (1.0 + b.nu));
  const double k_tip =
      1.0 / (std::pow(b.length, 3) / (3.0 * b.E * I) + b.length / (5.0 / 6.0 * G * A));
  const Eigen::Matrix3d flex = red.K.topLeftCorner(6, 6).inverse().topLeftCorner(3, 3);
  EXPECT_TRUE(isClose(1.0 / flex(2, 2), k_tip, 0.04));
}

TEST(CraigBampton, ConvergesToTheFullModelAsModesAreAdded) {
  TempDir dir;
  const Beam beam = assemble(smallBeam(), dir);
  const HousingNodeSet tip = set(beam, "TIP");
  Eigen::Vector3d c;
  const Eigen::SparseMatrix<double> T = tieMatrix(beam, tip, c);
  const Eigen::VectorXd full = frequenciesHz(projected(T, beam.fe.K), projected(T, beam.fe.M));
  constexpr int kCompared = 6;  // the beam's first six modes with the tip face free
  double previous = 1.0;
  for (int modes : {2, 5, 10, 20}) {
    CraigBamptonOptions options;
    options.modes = modes;
    const ReducedHousing red = reduceHousing(beam.fe, beam.deck.nodes, {tip}, {}, options);
    const Eigen::VectorXd f = frequenciesHz(red.K, red.M);
    double worst = 0.0;
    for (int i = 0; i < kCompared; ++i) {
      // Rayleigh–Ritz: a reduced model's frequencies bound the full model's from above.
      EXPECT_GE(f[i], full[i] * (1.0 - 1e-9)) << modes << " modes, mode " << i;
      worst = std::max(worst, f[i] / full[i] - 1.0);
    }
    std::printf(
        "Craig-Bampton, %d fixed-interface modes: worst error of the first %d "
        "frequencies %.3g\n",
        modes, kCompared, worst);
    EXPECT_LT(worst, previous) << modes << " modes";
    previous = worst;
    if (modes == 20) {
      EXPECT_LT(worst, 1e-3) << "20 modes";  // the 0.1 %
    }
  }
  // The cut-off rule (issue #37: twice the highest frequency of interest, here the sixth): the
  // modes kept are exactly those the dense solver finds below it (Sylvester's count), and the
  // first bending pair is within 0.1 %. Measured: bending 1.2e-4, 2nd bending 2.1e-3, torsion
  // 4.5e-3, the axial mode 9.9e-2 (its fixed-interface partner, c/2L = 6.4 kHz, lies just
  // below 2 × 3.25 kHz and is missed): the rule is a start, not a guarantee; 20 modes give 4e-4.
  CraigBamptonOptions options;
  options.cutoff_hz = 2.0 * full[kCompared - 1];
  const ReducedHousing red = reduceHousing(beam.fe, beam.deck.nodes, {tip}, {}, options);
  const Eigen::Index no = T.cols() - 6;
  const Eigen::VectorXd fixed = frequenciesHz((projected(T, beam.fe.K)).bottomRightCorner(no, no),
                                              (projected(T, beam.fe.M)).bottomRightCorner(no, no));
  const Eigen::Index kept = red.mode_frequencies_hz.size();
  ASSERT_GT(kept, 0);
  EXPECT_LT(fixed[kept - 1], options.cutoff_hz);
  EXPECT_GT(fixed[kept], options.cutoff_hz);
  const Eigen::VectorXd f = frequenciesHz(red.K, red.M);
  for (int i = 0; i < kCompared; ++i) {
    std::printf("cut-off %.0f Hz (%ld modes): mode %d %.6g Hz vs full %.6g Hz\n", options.cutoff_hz,
                static_cast<long>(kept), i, f[i], full[i]);
  }
  EXPECT_TRUE(isClose(f[0], full[0], 1e-3));
  EXPECT_TRUE(isClose(f[1], full[1], 1e-3));
}

TEST(CraigBampton, LanczosModesAgreeWithTheDenseSolver) {
  // A beam with more interior DOFs than kDenseModesBelow: the modes come from Spectra.
  TempDir dir;
  BeamDeck b;
  b.nx = 24;
  b.ny = b.nz = 1;
  b.length = 1.2;
  const Beam beam = assemble(b, dir);
  const HousingNodeSet tip = set(beam, "TIP");
  CraigBamptonOptions lanczos;
  lanczos.modes = 8;
  const ReducedHousing red = reduceHousing(beam.fe, beam.deck.nodes, {tip}, {}, lanczos);
  Eigen::Vector3d c;
  const Eigen::SparseMatrix<double> T = tieMatrix(beam, tip, c);
  const Eigen::Index no = T.cols() - 6;
  const Eigen::VectorXd fixed = frequenciesHz((projected(T, beam.fe.K)).bottomRightCorner(no, no),
                                              (projected(T, beam.fe.M)).bottomRightCorner(no, no));
  // Lanczos converged to 1e-10 against a dense QZ-free symmetric solver: 1e-8 relative.
  EXPECT_TRUE(isClose(red.mode_frequencies_hz, fixed.head(8), 1e-8));
}

TEST(CraigBampton, CantileverFrequencyMatchesBeamTheory) {
  // A slender steel cantilever (1 m, 50 × 50 mm, 20 × 2 × 2 quadratic hexahedra) reduced onto
  // its free end: its first bending frequency is Euler–Bernoulli's (1.8751² / 2π L²) √(EI/ρA)
  // less Timoshenko's shear and rotary-inertia correction, ≈ (1 − 0.3 (π r/L)² · 1.8751²/π²...)
  // which for L/r = 69 is 0.1 %; the clamped face's Poisson stiffening another ~0.1 %. 1 %.
  TempDir dir;
  const BeamDeck b;
  const Beam beam = assemble(b, dir);
  const double I = b.width * std::pow(b.height, 3) / 12.0, A = b.width * b.height;
  const double f1 = 1.87510407 * 1.87510407 / (2.0 * std::numbers::pi * b.length * b.length) *
                    std::sqrt(b.E * I / (b.rho * A));
  CraigBamptonOptions options;
  options.modes = 10;
  const ReducedHousing red =
      reduceHousing(beam.fe, beam.deck.nodes, {set(beam, "TIP")}, {set(beam, "MID")}, options);
  const Eigen::VectorXd f = frequenciesHz(red.K, red.M);
  std::printf("cantilever: first bending %.6g Hz, Euler-Bernoulli %.6g Hz\n", f[0], f1);
  EXPECT_TRUE(isClose(f[0], f1, 0.01));
  EXPECT_TRUE(isClose(f[1], f1, 0.01));  // the square section's second bending direction

  // Statics are exact in Craig–Bampton (the constraint modes span them): a tip force's
  // deflection at the response point against the full model's own solution.
  Eigen::VectorXd load = Eigen::VectorXd::Zero(red.K.rows());
  load[2] = 1000.0;  // 1 kN along z at the tip seat
  const Eigen::MatrixXd Kb = red.K.topLeftCorner(6, 6);
  Eigen::VectorXd q = Eigen::VectorXd::Zero(red.K.rows());
  q.head(6) = Kb.ldlt().solve(load.head(6));
  const Eigen::Vector3d mid = red.recovery * q;
  Eigen::Vector3d c;
  const Eigen::SparseMatrix<double> T = tieMatrix(beam, set(beam, "TIP"), c);
  const Eigen::SparseMatrix<double> K = T.transpose() * beam.fe.K * T;
  Eigen::VectorXd F = Eigen::VectorXd::Zero(K.rows());
  F[2] = 1000.0;
  const Eigen::VectorXd u = T * Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>(K).solve(F);
  const int node = beam.deck.nsets.at("MID").front();
  for (std::size_t i = 0; i < beam.fe.dofs.size(); ++i) {
    if (beam.fe.dofs[i].node != node) continue;
    EXPECT_TRUE(isClose(mid[beam.fe.dofs[i].direction - 1], u[static_cast<Eigen::Index>(i)], 1e-8,
                        1e-8 * u.cwiseAbs().maxCoeff()));  // off-axis: round-off
  }
}

TEST(CraigBampton, NamesTheSetOrKeyOfBadInput) {
  TempDir dir;
  const Beam beam = assemble(smallBeam(), dir);
  CraigBamptonOptions options;
  options.cutoff_hz = 1.0;  // far below the first fixed-interface mode (~1.3 kHz)
  try {
    reduceHousing(beam.fe, beam.deck.nodes, {set(beam, "TIP")}, {}, options);
    FAIL() << "a cut-off below every mode was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "housing.cutoff_hz");
  }
  options.modes = 2;
  try {
    reduceHousing(beam.fe, beam.deck.nodes, {set(beam, "ROOT")}, {}, options);
    FAIL() << "a seat on the clamped face was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "housing.seat.ROOT");
    EXPECT_NE(std::string(e.what()).find("*BOUNDARY"), std::string::npos);
  }
  try {
    reduceHousing(beam.fe, beam.deck.nodes, {set(beam, "TIP"), {"TIP2", beam.deck.nsets.at("TIP")}},
                  {}, options);
    FAIL() << "two seats sharing nodes were accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "housing.seat.TIP2");
  }
  EXPECT_THROW(feUnits("mm", "housing.units"), InputError);
  EXPECT_DOUBLE_EQ(feUnits("mm_t_s", "housing.units").length_m, 1e-3);
}

}  // namespace
}  // namespace geardyn

namespace geardyn {
namespace {

config::HousingSource beamSource(const fs::path& deck, const std::string& units) {
  config::HousingSource source;
  source.deck = deck.string();
  source.units = units;
  source.seats = {"tip"};
  source.points = {"MID"};
  source.reduction.modes = 6;
  return source;
}

TEST(HousingSource, CachesTheReductionUnderTheDecksHash) {
  TempDir dir;
  const fs::path inp = dir.path / "beam.inp";
  testing::writeBeamDeck(smallBeam(), inp);
  const config::LoadedHousing first = config::loadHousing(beamSource(inp, "si"));
  EXPECT_FALSE(first.from_cache);
  ASSERT_TRUE(fs::exists(first.cache_file));
  const auto start = std::chrono::steady_clock::now();
  const config::LoadedHousing again = config::loadHousing(beamSource(inp, "si"));
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("cached housing load: %.3g ms\n", 1e3 * seconds);
  EXPECT_TRUE(again.from_cache);
  EXPECT_EQ(again.housing.K, first.housing.K);  // bytes written and read back
  EXPECT_EQ(again.housing.M, first.housing.M);
  EXPECT_EQ(again.housing.recovery, first.housing.recovery);
  EXPECT_EQ(again.housing.seats, first.housing.seats);
  EXPECT_EQ(again.housing.centres[0], first.housing.centres[0]);
  // Another cut-off, or an edited deck: another cache file, reduced again.
  config::HousingSource more = beamSource(inp, "si");
  more.reduction.modes = 8;
  EXPECT_FALSE(config::loadHousing(more).from_cache);
  std::ofstream(inp, std::ios::app) << "** edited\n";
  const config::LoadedHousing edited = config::loadHousing(beamSource(inp, "si"));
  EXPECT_FALSE(edited.from_cache);
  EXPECT_NE(edited.cache_file, first.cache_file);
}

TEST(HousingSource, AnMmTonneDeckGivesTheSiModel) {
  // The same beam written in mm, t, s (E in MPa, ρ in t/mm³) and in SI: one reduced model.
  TempDir dir;
  BeamDeck si = smallBeam(), mm = smallBeam();
  mm.length *= 1e3;
  mm.width *= 1e3;
  mm.height *= 1e3;
  mm.E *= 1e-6;
  mm.rho *= 1e-12;
  testing::writeBeamDeck(si, dir.path / "si.inp");
  testing::writeBeamDeck(mm, dir.path / "mm.inp");
  const ReducedHousing a = config::loadHousing(beamSource(dir.path / "si.inp", "si")).housing;
  const ReducedHousing b = config::loadHousing(beamSource(dir.path / "mm.inp", "mm_t_s")).housing;
  // ccx prints 14 significant digits of each entry in either unit system; the reductions then
  // differ by their round-off, ~1e-10 relative (the beam's condition number ~1e6 × 1e-16 ×
  // the printed digits' 1e-14 / 1e-16).
  EXPECT_TRUE(isClose(frequenciesHz(b.K, b.M), frequenciesHz(a.K, a.M), 1e-8));
  EXPECT_TRUE(isClose(b.centres[0], a.centres[0], 1e-12, 1e-15));
}

TEST(HousingSource, NamesAnUnknownSetWithASuggestion) {
  TempDir dir;
  const fs::path inp = dir.path / "beam.inp";
  testing::writeBeamDeck(smallBeam(), inp);
  config::HousingSource source = beamSource(inp, "si");
  source.seats = {"TIPP"};
  try {
    config::loadHousing(source);
    FAIL() << "an unknown seat set was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "housing.seats");
    EXPECT_NE(std::string(e.what()).find("did you mean \"TIP\""), std::string::npos) << e.what();
  }
  source = beamSource(inp, "inch");
  EXPECT_THROW(config::loadHousing(source), InputError);
}

}  // namespace
}  // namespace geardyn

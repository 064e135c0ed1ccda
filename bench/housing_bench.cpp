/// Housing assembly and reduction (issue #37, "Performance"): the box housing of the two-stage
/// reducer meshed by examples/housing_box_gmsh.py (GEARDYN_HOUSING_SIZE [m], default 0.03:
/// about 35 k DOFs; 0.02: about 72 k; or the deck GEARDYN_HOUSING_DECK), assembled by ccx, its six
/// seats tied, reduced by Craig–Bampton below GEARDYN_HOUSING_CUTOFF_HZ (default 2000 Hz). One
/// iteration each: the budget is 30 s for 50 k DOFs on 2 cores (0.025: about 50 k DOFs).
/// The reduction runs with CHOLMOD (libgeardyn_cholmod.so) and with Eigen's SimplicialLDLT
/// (GEARDYN_SPARSE_CHOLESKY=simplicial) in the same process, wall and CPU time of each part; a
/// cached reload of the reduced housing (config::loadHousing) is timed too.

#include <benchmark/benchmark.h>

#include <Eigen/Eigenvalues>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "geardyn/config/gearbox_config.h"
#include "geardyn/config/gearbox_housing.h"
#include "geardyn/config/housing_source.h"
#include "geardyn/io/calculix_deck.h"
#include "geardyn/models/housing_superelement.h"
#include "geardyn/solvers/train_response.h"
#include "geardyn/system/housing_coupling.h"

namespace {

namespace fs = std::filesystem;

double envOr(const char* name, double fallback) {
  const char* v = std::getenv(name);
  return v != nullptr ? std::atof(v) : fallback;
}

const std::string& deckPath() {
  static const std::string path = [] {
    if (const char* given = std::getenv("GEARDYN_HOUSING_DECK")) return std::string(given);
    const fs::path out = fs::temp_directory_path() / "geardyn-housing-bench.inp";
    const std::string command =
        "/usr/bin/python3 " GEARDYN_SOURCE_DIR "/examples/housing_box_gmsh.py " + out.string() +
        " --size " + std::to_string(envOr("GEARDYN_HOUSING_SIZE", 0.03));
    if (std::system(command.c_str()) != 0) throw std::runtime_error("gmsh script failed");
    return out.string();
  }();
  return path;
}

const char* kSeats[] = {"INPUT_A",        "INPUT_B",  "INTERMEDIATE_A",
                        "INTERMEDIATE_B", "OUTPUT_A", "OUTPUT_B"};

void BM_HousingCcxAssembly(benchmark::State& state) {
  const std::string& path = deckPath();
  for (auto _ : state) {
    const geardyn::io::FeMatrices fe = geardyn::io::runCalculix(path, "housing.deck");
    state.counters["dofs"] = static_cast<double>(fe.dofs.size());
    state.counters["k_entries"] = static_cast<double>(fe.K.nonZeros());
  }
}
BENCHMARK(BM_HousingCcxAssembly)->Iterations(1)->Unit(benchmark::kSecond);

/// state.range(0): 1 = CHOLMOD supernodal (METIS), 0 = Eigen's SimplicialLDLT (AMD).
void BM_HousingCraigBampton(benchmark::State& state) {
  const std::string& path = deckPath();
  geardyn::io::CalculixDeck deck = geardyn::io::readCalculixDeck(path, "housing.deck");
  geardyn::io::FeMatrices fe = geardyn::io::runCalculix(path, "housing.deck");
  std::vector<geardyn::HousingNodeSet> seats, points;
  for (const char* s : kSeats) seats.push_back({s, deck.nsets.at(s)});
  points.push_back({"TOP", deck.nsets.at("TOP")});
  geardyn::CraigBamptonOptions options;
  options.cutoff_hz = envOr("GEARDYN_HOUSING_CUTOFF_HZ", 2000.0);
  if (state.range(0) == 0) {
    setenv("GEARDYN_SPARSE_CHOLESKY", "simplicial", 1);
  } else {
    unsetenv("GEARDYN_SPARSE_CHOLESKY");
  }
  for (auto _ : state) {
    const std::clock_t cpu = std::clock();
    const geardyn::ReducedHousing red =
        geardyn::reduceHousing(fe, deck.nodes, seats, points, options);
    state.counters["cpu_s"] = static_cast<double>(std::clock() - cpu) / CLOCKS_PER_SEC;
    state.counters["dofs"] = static_cast<double>(fe.dofs.size());
    state.counters["modes"] = static_cast<double>(red.mode_frequencies_hz.size());
    state.counters["factor_s"] = red.factorisation_s;
    state.counters["lanczos_s"] = red.modes_s;
    state.counters["other_s"] = red.other_s;
  }
  unsetenv("GEARDYN_SPARSE_CHOLESKY");
}
BENCHMARK(BM_HousingCraigBampton)->Arg(1)->Arg(0)->Iterations(1)->Unit(benchmark::kSecond);

/// A rerun with the reduction cached next to the deck: the whole config::loadHousing (hashing
/// the deck, reading the cache file).
void BM_HousingCachedLoad(benchmark::State& state) {
  geardyn::config::HousingSource source;
  source.deck = deckPath();
  for (const char* s : kSeats) source.seats.push_back(s);
  source.points = {"TOP", "SIDE"};
  source.reduction.cutoff_hz = envOr("GEARDYN_HOUSING_CUTOFF_HZ", 2000.0);
  geardyn::config::loadHousing(source);  // reduce and cache, untimed
  for (auto _ : state) {
    const geardyn::config::LoadedHousing h = geardyn::config::loadHousing(source);
    if (!h.from_cache) state.SkipWithError("the reduction was not cached");
    benchmark::DoNotOptimize(h.housing.K.data());
  }
}
BENCHMARK(BM_HousingCachedLoad)->Unit(benchmark::kMillisecond);

/// The two-stage reducer (examples/gearboxes/two_stage_reducer.toml) on the box: its modes on the
/// rigid and on the flexible housing (printed), and the time of one forced-response solve per
/// frequency, (K − ω²M + iωC) x = f, with and without the housing (the budget: ≤ 2 ×).
void BM_TwoStageReducerOnTheBox(benchmark::State& state) {
  std::vector<std::string> warnings;
  const geardyn::GearTrainModel model(geardyn::config::gearTrainFromConfig(
      geardyn::config::loadConfigFile(GEARDYN_SOURCE_DIR
                                      "/examples/gearboxes/two_stage_reducer.toml",
                                      geardyn::config::gearboxSchema()),
      warnings));
  geardyn::config::HousingSource source;
  source.deck = deckPath();
  for (const char* s : kSeats) {
    std::string name = s;
    for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    source.seats.push_back(name);
  }
  source.points = {"TOP", "SIDE"};
  source.reduction.cutoff_hz = envOr("GEARDYN_HOUSING_CUTOFF_HZ", 2000.0);
  const geardyn::config::LoadedHousing housing = geardyn::config::loadHousing(source);
  std::vector<geardyn::HousingLink> links;
  for (const std::string& s : source.seats) links.push_back({s, s});
  const double speed = model.inputSpeed();
  const geardyn::HousedTrain t = geardyn::coupleHousing(model, housing.housing, links, speed);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> rigid(model.meanStiffnessAt(speed),
                                                                  model.mass());
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> housed(t.K, t.M);
  std::printf("two-stage reducer: %d train DOFs + %ld housing DOFs (%ld modes)\n", model.dofCount(),
              static_cast<long>(housing.housing.K.rows()),
              static_cast<long>(housing.housing.mode_frequencies_hz.size()));
  for (int i = 0; i < model.dofCount(); ++i) {
    std::printf("  mode %2d: rigid housing %9.2f Hz, box housing %9.2f Hz\n", i,
                std::sqrt(std::max(rigid.eigenvalues()[i], 0.0)) / (2 * M_PI),
                std::sqrt(std::max(housed.eigenvalues()[i], 0.0)) / (2 * M_PI));
  }
  const double w = 2 * M_PI * 800.0;
  auto solveTime = [&](const Eigen::MatrixXd& K, const Eigen::MatrixXd& M,
                       const Eigen::MatrixXd& C) {
    const Eigen::MatrixXcd D = (K - w * w * M).cast<std::complex<double>>() +
                               std::complex<double>(0, w) * C.cast<std::complex<double>>();
    const Eigen::VectorXcd f = Eigen::VectorXcd::Ones(K.rows());
    const auto start = std::chrono::steady_clock::now();
    Eigen::VectorXcd x;
    for (int r = 0; r < 200; ++r) x = D.partialPivLu().solve(f);
    benchmark::DoNotOptimize(x);
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / 200;
  };
  for (auto _ : state) {
    const double alone =
        solveTime(model.meanStiffnessAt(speed), model.mass(), model.dampingAt(speed));
    const double with = solveTime(t.K, t.M, t.C);
    state.counters["solve_us_rigid"] = 1e6 * alone;
    state.counters["solve_us_housed"] = 1e6 * with;
    state.counters["ratio"] = with / alone;
  }
}
BENCHMARK(BM_TwoStageReducerOnTheBox)->Iterations(1)->Unit(benchmark::kSecond);

/// The train's forced-response solver (the example's 2 mesh harmonics) on the rigid housing
/// (`housed` 0), in the box with its residual vectors (1) or without them (2).
struct ForcedCase {
  geardyn::GearTrainModel model;
  geardyn::TrainSteadySolver solver;
  static geardyn::GearTrainSpec spec(int housed) {
    const std::string file =
        housed >= 1 ? "two_stage_reducer_housed.toml" : "two_stage_reducer.toml";
    std::vector<std::string> overrides;
    if (housed == 2) overrides.push_back("housing.residual_vectors=false");
    const geardyn::config::Config c =
        geardyn::config::loadConfigFile(GEARDYN_SOURCE_DIR "/examples/gearboxes/" + file,
                                        geardyn::config::gearboxSchema(), overrides);
    std::vector<std::string> warnings;
    geardyn::GearTrainSpec out = geardyn::config::gearTrainFromConfig(c, warnings);
    if (housed >= 1) geardyn::config::attachHousing(c, out, 2760.0, 0.0);
    return out;
  }
  static geardyn::TrainSteadyOptions options() {
    geardyn::TrainSteadyOptions o;
    o.mesh_harmonics = 2;
    return o;
  }
  explicit ForcedCase(int housed) : model(spec(housed)), solver(model, options()) {}
};

double threadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

/// The ratio measured in pairs: at each of the 120 speeds the rigid and the housed
/// solve (state.range(0): 1 with, 2 without residual vectors) alternate, each timed in the
/// thread's CPU time, so that the shared machine's load changes hit both alike; the ratio of
/// the sums. Each solve is the `train` forced sweep's per speed (solve(w, false): of the
/// housing, the seats' rows and the response points; the rigid train has none).
void BM_ForcedPerSpeedPaired(benchmark::State& state) {
  const ForcedCase rigid(0), housed(static_cast<int>(state.range(0)));
  constexpr int kSpeeds = 120;
  double t_rigid = 0.0, t_housed = 0.0;
  for (auto _ : state) {
    for (int i = 1; i <= kSpeeds; ++i) {
      const double w = 1800.0 * i / kSpeeds * M_PI / 30.0;
      double t0 = threadCpuSeconds();
      benchmark::DoNotOptimize(rigid.solver.solve(w, false).harmonic.data());
      const double t1 = threadCpuSeconds();
      benchmark::DoNotOptimize(housed.solver.solve(w, false).housing_points.data());
      t_rigid += t1 - t0;
      t_housed += threadCpuSeconds() - t1;
    }
  }
  const double solves = static_cast<double>(state.iterations()) * kSpeeds;
  state.counters["rigid_us_per_speed"] = 1e6 * t_rigid / solves;
  state.counters["housed_us_per_speed"] = 1e6 * t_housed / solves;
  state.counters["ratio"] = t_housed / t_rigid;
}
BENCHMARK(BM_ForcedPerSpeedPaired)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

/// The forced response per speed as the `train` forced analysis computes it
/// (TrainSteadySolver::solve without all housing rows, the example's 2 mesh harmonics): the
/// two-stage reducer on the rigid housing (state.range(0) = 0) and in the example's box (1,
/// examples/gearboxes/two_stage_reducer_housed.toml, cut-off 2760 Hz as in
/// examples/train_two_stage_reducer_housing.toml), 120 speeds from 15 to 1800 rpm a pass.
void BM_ForcedPerSpeed(benchmark::State& state) {
  // 0: the rigid housing; 1: the box with its residual vectors (the default); 2: without them.
  const bool housed = state.range(0) >= 1;
  const std::string file = housed ? "two_stage_reducer_housed.toml" : "two_stage_reducer.toml";
  std::vector<std::string> overrides;
  if (state.range(0) == 2) overrides.push_back("housing.residual_vectors=false");
  const geardyn::config::Config c =
      geardyn::config::loadConfigFile(GEARDYN_SOURCE_DIR "/examples/gearboxes/" + file,
                                      geardyn::config::gearboxSchema(), overrides);
  std::vector<std::string> warnings;
  geardyn::GearTrainSpec spec = geardyn::config::gearTrainFromConfig(c, warnings);
  if (housed) geardyn::config::attachHousing(c, spec, 2760.0, 0.0);
  const geardyn::GearTrainModel model(spec);
  geardyn::TrainSteadyOptions options;
  options.mesh_harmonics = 2;
  const geardyn::TrainSteadySolver solver(model, options);
  constexpr int kSpeeds = 120;
  const std::clock_t cpu = std::clock();
  const auto wall = std::chrono::steady_clock::now();
  for (auto _ : state) {
    for (int i = 1; i <= kSpeeds; ++i) {
      const double rpm = 1800.0 * i / kSpeeds;
      const geardyn::TrainSteadyState s = solver.solve(rpm * M_PI / 30.0, false);
      benchmark::DoNotOptimize(s.harmonic.data());
    }
  }
  const double solves = static_cast<double>(state.iterations()) * kSpeeds;
  state.counters["cpu_us_per_speed"] =
      1e6 * static_cast<double>(std::clock() - cpu) / CLOCKS_PER_SEC / solves;
  state.counters["wall_us_per_speed"] =
      1e6 * std::chrono::duration<double>(std::chrono::steady_clock::now() - wall).count() / solves;
  state.counters["dofs"] = model.dofCount();
  const geardyn::TrainSteadyState one = solver.solve(900.0 * M_PI / 30.0);
  state.counters["harmonics"] = one.harmonics;
  state.counters["samples"] = static_cast<double>(one.t.size());
}
BENCHMARK(BM_ForcedPerSpeed)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

}  // namespace

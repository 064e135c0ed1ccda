/// Housing assembly and reduction (issue #37, "Performance"): the box housing of the two-stage
/// reducer meshed by examples/housing_box_gmsh.py (GEARDYN_HOUSING_SIZE [m], default 0.03:
/// about 35 k DOFs; 0.02: about 72 k), assembled by ccx, its six seats tied, reduced by
/// Craig–Bampton below GEARDYN_HOUSING_CUTOFF_HZ (default 2000 Hz). One iteration each: the
/// issue's budget is 30 s for 50 k DOFs on 2 cores.

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "geardyn/io/calculix_deck.h"
#include "geardyn/models/housing_superelement.h"

namespace {

namespace fs = std::filesystem;

double envOr(const char* name, double fallback) {
  const char* v = std::getenv(name);
  return v != nullptr ? std::atof(v) : fallback;
}

const std::string& deckPath() {
  static const std::string path = [] {
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

void BM_HousingCraigBampton(benchmark::State& state) {
  const std::string& path = deckPath();
  geardyn::io::CalculixDeck deck = geardyn::io::readCalculixDeck(path, "housing.deck");
  geardyn::io::FeMatrices fe = geardyn::io::runCalculix(path, "housing.deck");
  std::vector<geardyn::HousingNodeSet> seats, points;
  for (const char* s : kSeats) seats.push_back({s, deck.nsets.at(s)});
  points.push_back({"TOP", deck.nsets.at("TOP")});
  geardyn::CraigBamptonOptions options;
  options.cutoff_hz = envOr("GEARDYN_HOUSING_CUTOFF_HZ", 2000.0);
  for (auto _ : state) {
    const geardyn::ReducedHousing red =
        geardyn::reduceHousing(fe, deck.nodes, seats, points, options);
    state.counters["modes"] = static_cast<double>(red.mode_frequencies_hz.size());
    state.counters["first_mode_hz"] =
        red.mode_frequencies_hz.size() ? red.mode_frequencies_hz[0] : 0;
  }
}
BENCHMARK(BM_HousingCraigBampton)->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace

#pragma once
/// The mesh-force spectrum of the torus balance against a long Newmark run (issue 32): the DFT
/// of the Newmark mesh force over whole common periods gives the lines h f₀; each torus line
/// n·g is the line h = n·g / f₀ (the tones of the box map to distinct h on the trains tested).
/// Shared by the unit test (one speed) and the long test (three speeds).

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <string>
#include <vector>

#include "geardyn/config/gearbox_config.h"
#include "geardyn/config/train_analysis.h"
#include "geardyn/solvers/train_response.h"
#include "geardyn/solvers/train_time.h"
#include "geardyn/torus/train_torus.h"

namespace geardyn::testing {

/// A gearbox of examples/gearboxes/ (GEARDYN_SOURCE_DIR).
inline GearTrainSpec exampleGearbox(const std::string& name) {
  const config::Config config = config::loadConfigFile(
      std::string(GEARDYN_SOURCE_DIR "/examples/gearboxes/") + name, config::gearboxSchema());
  std::vector<std::string> warnings;
  return config::gearTrainFromConfig(config, warnings);
}

/// The speeds `geardyn train` [forced] runs at by default on `model`
/// (config::forcedSpeedsFromConfig of an analysis file with no [forced] keys: 200 speeds, 0.1–1.5 ×
/// the operating speed), with `overrides` as --set would give them (e.g. "forced.points=20").
inline std::vector<double> defaultForcedSpeeds(const GearTrainModel& model,
                                               const std::vector<std::string>& overrides = {}) {
  const config::Config analysis =
      config::parseConfig("", "defaults", config::trainSchema(false), overrides);
  return config::forcedSpeedsFromConfig(analysis, model.inputSpeed());
}

struct SpectrumComparison {
  double worst = 0.0;    ///< max |A_newmark − A_torus| over the lines above the floor / largest
  double largest = 0.0;  ///< largest line [N]
  int lines = 0;         ///< lines compared (above the floor in either spectrum)
};

/// Worst difference per mesh between the lines of a torus state and of a Newmark record of
/// `periods` common periods, over the lines above `floor` × the largest.
inline std::vector<SpectrumComparison> compareSpectra(const GearTrainModel& model,
                                                      const TrainTorusState& torus,
                                                      const TrainTimeResponse& newmark, int periods,
                                                      double floor) {
  const double f0 = trainBaseFrequency(model, 1, 1000000000).ratio * std::abs(torus.input_speed);
  const Eigen::Index N = newmark.t.size();
  int highest = 0;
  for (const auto& lines : torus.mesh_force_lines) {
    for (const TorusLine& line : lines) {
      highest = std::max(highest, static_cast<int>(std::lround(line.frequency / f0)));
    }
  }
  std::vector<SpectrumComparison> out;
  for (Eigen::Index m = 0; m < newmark.mesh_force.cols(); ++m) {
    // Newmark lines h = 1..highest (bins h × periods of the record).
    std::vector<double> a(highest + 1, 0.0), b(highest + 1, 0.0);
    const Eigen::VectorXd f = newmark.mesh_force.col(m);
    for (int h = 1; h <= highest; ++h) {
      const double step = 2.0 * std::numbers::pi * h * periods / static_cast<double>(N);
      std::complex<double> sum = 0.0;
      for (Eigen::Index k = 0; k < N; ++k) sum += f(k) * std::polar(1.0, -step * k);
      a[h] = 2.0 * std::abs(sum) / static_cast<double>(N);
    }
    for (const TorusLine& line : torus.mesh_force_lines[m]) {
      const long h = std::lround(line.frequency / f0);
      if (h >= 1 && h <= highest) b[h] += line.amplitude;
    }
    SpectrumComparison c;
    for (int h = 1; h <= highest; ++h) c.largest = std::max({c.largest, a[h], b[h]});
    for (int h = 1; h <= highest; ++h) {
      if (std::max(a[h], b[h]) < floor * c.largest) continue;
      ++c.lines;
      c.worst = std::max(c.worst, std::abs(a[h] - b[h]) / c.largest);
    }
    out.push_back(c);
  }
  return out;
}

/// The torus balance with L mesh harmonics against Newmark with `steps` per fastest mesh
/// period (one common period recorded), lines above 1e-3 of the largest.
inline std::vector<SpectrumComparison> compareTorusWithNewmark(const GearTrainModel& model,
                                                               double speed, int L, int steps) {
  TrainTorusOptions torus_options;
  torus_options.mesh_harmonics = L;
  torus_options.group_harmonics = std::max(100, L);
  const TrainTorusState torus = TrainTorusSolver(model, torus_options).solve(speed);
  TrainTimeOptions options;
  options.steps_per_mesh_period = steps;
  const TrainTimeResponse newmark = solveTrainTimeResponse(model, speed, options);
  if (newmark.status != "completed") return {};
  return compareSpectra(model, torus, newmark, 1, 1e-3);
}

}  // namespace geardyn::testing

/// `train` analysis `nonlinear` on the torus of the mesh phases (train_nonlinear_analysis.h;
/// torus/train_torus_balance.h): chosen when the meshes' common period is long
/// (nonlinear.method). Continuation in speed with every frequency moving together, per-point
/// mesh deflections, forces and contact loss, the mesh-force lines per tone and per mesh order,
/// and Newmark checks and Lyapunov estimates of stability at chosen speeds.

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>

#include "geardyn/config/train_analysis.h"
#include "geardyn/error.h"
#include "geardyn/solvers/continuation.h"
#include "geardyn/solvers/train_response.h"
#include "geardyn/torus/train_torus_balance.h"
#include "geardyn/torus/train_torus_lyapunov.h"
#include "geardyn/units.h"
#include "torus_tones.h"
#include "train_nonlinear_analysis.h"
#include "wall_clock.h"

namespace geardyn::analysis::detail {
namespace {

using geardyn::units::kRpm;
using Json = nlohmann::ordered_json;
/// Lines below this fraction of a mesh force's largest are not tabulated (as forced_tones.csv).
constexpr double kToneFloor = 1e-3;
/// The Newmark check runs this many periods of the slowest generator: the quasi-periodic
/// response then covers the torus densely enough, and it is longer than the decay time of the
/// mesh modes (ζ ≈ 0.05) by far; a perturbation of an unstable solution grows over it.
constexpr double kCheckPeriods = 100.0;

}  // namespace

bool nonlinearOnTorus(const GearTrainModel& model, const config::Config& analysis) {
  const std::string method = analysis.string("nonlinear.method");
  if (method != "auto") return method == "torus";
  int largest = 1;
  for (int p : trainBaseFrequency(model, 1, std::numeric_limits<int>::max()).mesh_multiple) {
    largest = std::max(largest, p);
  }
  return largest * analysis.integer("nonlinear.torus_mesh_harmonics") >
         analysis.integer("forced.torus_above");
}

std::string runTrainNonlinearTorus(const GearTrainModel& model, const config::Config& analysis,
                                   AnalysisResult& result, std::string& text,
                                   const AnalysisContext& context) {
  const auto start = Clock::now();
  TrainTorusBalanceOptions options;
  options.mesh_harmonics = static_cast<int>(analysis.integer("nonlinear.torus_mesh_harmonics"));
  options.group_harmonics =
      std::max(static_cast<int>(analysis.integer("forced.torus_above")), options.mesh_harmonics);
  options.tolerance = analysis.real("nonlinear.tolerance");
  options.max_iterations = static_cast<int>(analysis.integer("nonlinear.max_iterations"));
  TrainTorusBalance hb(model, options);
  const auto [lo, hi] = config::nonlinearSpeedRange(analysis, model.inputSpeed());
  const double scale = hb.baseFrequency(kRpm);  // ω per rpm [rad/s]
  ContinuationOptions sweep;
  sweep.start = hb.baseFrequency(lo);
  sweep.stop = hb.baseFrequency(hi);
  if (analysis.string("nonlinear.direction") == "down") std::swap(sweep.start, sweep.stop);
  // Steps: 1/100 of the range at most (the torus has no single resonance width to derive
  // them from: every tone n·ω has its own); given keys bound them.
  const double range = std::abs(sweep.stop - sweep.start);
  const auto given = [&](const std::string& key, double fallback) {
    return analysis.has(key) ? analysis.real(key) * scale : fallback;
  };
  sweep.max_step = given("nonlinear.max_step_rpm", range / 100.0);
  sweep.initial_step = given("nonlinear.initial_step_rpm", sweep.max_step / 5.0);
  sweep.min_step = given("nonlinear.min_step_rpm", 1e-6 * range);
  sweep.fold_tolerance = given("nonlinear.fold_tolerance_rpm", 1e-3 * range);
  sweep.max_points = static_cast<int>(analysis.integer("nonlinear.max_points"));
  sweep.stability = false;  // quasi-periodic: the Newmark checks below
  sweep.display_scale = scale;
  sweep.display_unit = "rpm";
  sweep.progress = context.progressFor("train: nonlinear (torus)", "rpm");
  const auto sweep_start = Clock::now();
  const ContinuationResult run = continueInFrequency(hb, sweep);
  const double sweep_seconds = secondsSince(sweep_start);

  const auto& meshes = model.meshes();
  const int r = static_cast<int>(meshes.size());
  const TrainTorusGenerators& g = hb.generators();
  const int k = static_cast<int>(g.ratio.size());
  std::vector<std::string> header{"speed_rpm", "branch"};
  for (const TrainMesh& m : meshes) {
    header.push_back("p2p_deflection_" + m.name + "_m");
    header.push_back("max_force_" + m.name + "_n");
    header.push_back("contact_loss_" + m.name);
  }
  io::CsvTable table(header);
  std::vector<std::string> tone_header{"speed_rpm", "mesh"};
  for (int j = 0; j < k; ++j) tone_header.push_back(fmt::format("harmonic_g{}", j + 1));
  for (const char* c : {"tone", "frequency_hz", "amplitude_n", "relative_amplitude"}) {
    tone_header.push_back(c);
  }
  io::CsvTable tones(tone_header);
  io::CsvTable orders({"speed_rpm", "mesh", "order", "frequency_hz", "amplitude_n"});
  std::vector<double> worst_loss(r, 0.0), worst_force(r, 0.0);
  for (const SweepPoint& sp : run.points) {
    const HarmonicBalancePoint& p = sp.solution;
    const double speed = std::abs(hb.inputSpeed(p.omega));
    const Eigen::MatrixXd forces = hb.gridMeshForces(p.q);
    std::vector<io::CsvCell> row{speed / kRpm, sp.branch};
    const Eigen::MatrixXd deflections = hb.gridCoordinates(p.q);
    for (int m = 0; m < r; ++m) {
      // Over the grid: every phase relation of the generators (the trajectory is a line on it).
      const double loss = (forces.col(m).array() == 0.0).cast<double>().mean();
      const double peak = forces.col(m).cwiseAbs().maxCoeff();
      worst_loss[m] = std::max(worst_loss[m], loss);
      worst_force[m] = std::max(worst_force[m], peak);
      row.push_back(deflections.col(m).maxCoeff() - deflections.col(m).minCoeff());
      row.push_back(peak);
      row.push_back(loss);
    }
    table.addRow(row);
    const auto lines = hb.meshForceLines(p.q, p.omega);
    for (int m = 0; m < r; ++m) {
      const int j = g.mesh_generator[m], P = g.mesh_multiple[m];
      for (const TorusLine& line : lines[m]) {
        bool pure = line.tone[j] % P == 0;
        for (int a = 0; a < k; ++a) pure = pure && (a == j || line.tone[a] == 0);
        if (pure && line.tone[j] > 0 && line.tone[j] / P <= options.mesh_harmonics) {
          orders.addRow(
              {speed / kRpm, meshes[m].name, line.tone[j] / P, line.frequency, line.amplitude});
        }
      }
      addToneRows(tones, speed / kRpm, meshes[m].name, lines[m], kToneFloor);
    }
  }
  result.addTable("nonlinear_torus.csv", table);
  result.addTable("nonlinear_tones.csv", tones);
  result.addTable("nonlinear_mesh_orders.csv", orders);

  // Stability of the quasi-periodic solutions: Newmark from each solution at the chosen speeds.
  Json checks = Json::array();
  for (double rpm : analysis.realList("nonlinear.newmark_speeds_rpm")) {
    const double omega = hb.baseFrequency(rpm * kRpm);
    for (const HarmonicBalancePoint& p : solutionsAtFrequency(hb, {&run}, omega)) {
      double slowest = std::numeric_limits<double>::infinity();
      for (double ratio : g.ratio) slowest = std::min(slowest, ratio * rpm * kRpm);
      const TorusNewmarkCheck check =
          torusNewmarkCheck(model, hb, p, kCheckPeriods / slowest, 256, 0.05);
      // The Lyapunov estimate over the same window: the verdict of the linearised equation,
      // independent of the truncation's agreement with Newmark (train_torus_lyapunov.h).
      const TorusLyapunovEstimate lyapunov =
          torusLyapunovEstimate(model, hb, p, kCheckPeriods / slowest);
      Json per = Json::object();
      for (int m = 0; m < r; ++m) {
        per[meshes[m].name] = {{"p2p_newmark_m", check.p2p_newmark[m]},
                               {"p2p_torus_m", check.p2p_torus[m]},
                               {"deviation", check.deviation[m]}};
      }
      checks.push_back(
          {{"speed_rpm", rpm},
           {"status", check.status},
           {"stable", check.stable},
           {"window_s", kCheckPeriods / slowest},
           {"lyapunov",
            {{"status", lyapunov.status},
             {"stable", lyapunov.stable},
             {"max_exponent_per_s",
              lyapunov.status == "completed" ? Json(lyapunov.max_exponent) : Json(nullptr)}}},
           {"meshes", per}});
    }
  }
  Json generators = Json::array();
  for (int j = 0; j < k; ++j) {
    Json members = Json::array();
    for (int m = 0; m < r; ++m) {
      if (g.mesh_generator[m] == j) {
        members.push_back({{"mesh", meshes[m].name}, {"multiple", g.mesh_multiple[m]}});
      }
    }
    generators.push_back({{"order", g.ratio[j] * 2.0 * std::numbers::pi},
                          {"harmonics", g.harmonics[j]},
                          {"meshes", members}});
  }
  Json per_mesh = Json::object();
  for (int m = 0; m < r; ++m) {
    per_mesh[meshes[m].name] = {{"max_contact_loss", worst_loss[m]},
                                {"max_force_n", worst_force[m]}};
  }
  result.summary.results["nonlinear"] = {
      {"method", "torus"},
      {"mesh_harmonics", options.mesh_harmonics},
      {"torus", {{"generators", generators}, {"tones", hb.tones().cols()}}},
      {"points", run.points.size()},
      {"folds", run.folds.size()},
      {"completed", run.completed},
      {"meshes", per_mesh},
      {"stability", "newmark checks and lyapunov estimates (quasi-periodic: no monodromy)"},
      {"newmark_checks", checks},
      {"sweep_wall_time_s", sweep_seconds},
      {"total_wall_time_s", secondsSince(start)}};
  text += fmt::format("nonlinear (torus, {} generators, {} tones): {} points in {:.2f} s{}\n", k,
                      hb.tones().cols(), run.points.size(), sweep_seconds,
                      run.completed ? "" : " (" + run.message + ")");
  return run.completed ? "ok" : "incomplete";
}

}  // namespace geardyn::analysis::detail

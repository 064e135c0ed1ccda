/// `train` analysis `stats`: Gelman's (2005) mean excitation ratio per mesh of any train and the
/// statistics of every mesh's dynamic force and transmission error (train_stats_analysis.h).

#include "train_stats_analysis.h"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <optional>

#include "geardyn/analysis/stats_results.h"
#include "geardyn/config/train_analysis.h"
#include "geardyn/error.h"
#include "geardyn/solvers/train_response.h"
#include "geardyn/solvers/train_time.h"
#include "geardyn/stats/train_mesh_statistics.h"
#include "geardyn/units.h"

namespace geardyn::analysis::detail {
namespace {

using geardyn::units::kRpm;
using Json = nlohmann::ordered_json;

Json recordJson(const RecordStatistics& s) {
  return {{"mean", s.mean}, {"rms", s.rms}, {"std", s.std},
          {"min", s.min},   {"max", s.max}, {"peak_to_peak", s.peakToPeak()}};
}

/// mesh_statistics.csv: one row per mesh (blank R columns for a mesh without load).
io::CsvTable statisticsTable(const std::vector<TrainMeshStatistics>& stats) {
  io::CsvTable table({"mesh",
                      "static_force_n",
                      "baseload_n",
                      "mean_excitation_ratio",
                      "mean_excitation_ratio_eq15",
                      "mean_excitation_ratio_eq11",
                      "simulated_mean_excitation_ratio",
                      "variable_term_v",
                      "a",
                      "d_k",
                      "d_e",
                      "r_ke",
                      "delta_m1_ef",
                      "dynamic_factor",
                      "mesh_force_mean_n",
                      "mesh_force_rms_n",
                      "mesh_force_min_n",
                      "mesh_force_max_n",
                      "mesh_force_p2p_n",
                      "dte_mean_m",
                      "dte_rms_m",
                      "dte_min_m",
                      "dte_max_m",
                      "dte_p2p_m"});
  for (const TrainMeshStatistics& s : stats) {
    std::vector<io::CsvCell> row{s.mesh, s.static_force, s.baseload};
    if (s.excitation) {
      const MeanExcitation& e = *s.excitation;
      for (double v : {e.ratio, e.ratio_eq15, e.ratio_eq11, s.simulated_ratio, e.variable_term, e.a,
                       e.d_k, e.d_e, e.r_ke, e.delta_m1_ef, s.dynamic_factor}) {
        row.push_back(v);
      }
    } else {
      for (int i = 0; i < 11; ++i) row.push_back(std::string());
    }
    for (const RecordStatistics* r : {&s.force, &s.dte}) {
      for (double v : {r->mean, r->rms, r->min, r->max, r->peakToPeak()}) row.push_back(v);
    }
    table.addRow(row);
  }
  return table;
}

}  // namespace

int runTrainStats(const GearTrainModel& model, const config::Config& analysis,
                  AnalysisResult& result, std::string& text, const TrainTimeResponse* record) {
  const auto start = std::chrono::steady_clock::now();
  io::RunSummary& summary = result.summary;
  const double speed = config::analysisSpeed(analysis, "time", model.inputSpeed());
  const double torque = model.spec().operating.input_torque;
  const double design =
      analysis.has("stats.design_torque") ? analysis.real("stats.design_torque") : torque;
  if (!(design * torque > 0.0)) {
    throw InputError("stats.design_torque", fmt::format("{:g} N m", design),
                     fmt::format("a torque != 0 in the sense of the operating torque ({:g} N m): "
                                 "the load the profile modifications were designed for",
                                 torque));
  }
  if (model.hasNonlinearElements()) {
    summary.warnings.push_back(
        "stats: the mean excitation statistics assume linear meshes (Gelman eq. 1): the Newmark "
        "run uses each mesh's linear law k(φ)(δ − e(φ)), without contact loss, backlash, the "
        "tooth-pair gaps of flank modifications or bearing clearance");
  }
  const TrainStaticResult statics = solveTrainStatic(model, speed);
  TrainTimeOptions options = config::trainTimeOptionsFromConfig(analysis);
  options.record_rates = false;
  std::optional<TrainTimeResponse> own;
  const TrainTimeResponse& r =
      record ? *record : own.emplace(solveTrainTimeResponse(model, speed, options));
  if (r.status != "completed") {
    summary.warnings.push_back("stats: " + r.message);
    summary.results["stats"] = {{"status", r.status}, {"steps", r.steps}};
    return 1;
  }
  const std::vector<TrainMeshStatistics> stats =
      trainMeshStatistics(model, speed, r, statics.mesh_force, design / torque);
  result.addTable("mesh_statistics.csv", statisticsTable(stats));
  Json meshes = Json::object();
  text += fmt::format("stats at {:.1f} rpm ({} Newmark steps of {:.3g} s, record {:.4g} s):\n",
                      speed / kRpm, r.steps, r.time_step,
                      r.time_step * static_cast<double>(r.t.size()));
  for (const TrainMeshStatistics& s : stats) {
    Json mesh = {{"static_force_n", s.static_force},
                 {"baseload_n", s.baseload},
                 {"mean_excitation_ratio", nullptr},
                 {"simulated_mean_excitation_ratio", nullptr},
                 {"dynamic_factor", nullptr},
                 {"mesh_force_n", recordJson(s.force)},
                 {"dynamic_transmission_error_m", recordJson(s.dte)}};
    if (s.excitation) {
      mesh["mean_excitation_ratio"] = s.excitation->ratio;
      mesh["simulated_mean_excitation_ratio"] = s.simulated_ratio;
      mesh["dynamic_factor"] = s.dynamic_factor;
      mesh["mean_excitation"] = analysis::toJson(*s.excitation);
      mesh["simulated_dynamic_mean_excitation"] = s.simulated_dynamic_mean_excitation;
      text += fmt::format(
          "  {:<16} R {:.6f} [-] (simulated {:.6f} [-]), dynamic factor {:.4f} [-], force rms "
          "{:.6g} N, p2p {:.4g} N, DTE p2p {:.4g} µm\n",
          s.mesh, s.excitation->ratio, s.simulated_ratio, s.dynamic_factor, s.force.rms,
          s.force.peakToPeak(), 1e6 * s.dte.peakToPeak());
    } else {
      summary.warnings.push_back(fmt::format(
          "stats: mesh {} carries {:g} N along its line of action at the operating point (not > "
          "0): its mean excitation ratio, a ratio to the transmitted load, is undefined",
          s.mesh, s.static_force));
      text += fmt::format("  {:<16} static force {:.6g} N (R undefined): force rms {:.6g} N\n",
                          s.mesh, s.static_force, s.force.rms);
    }
    meshes[s.mesh] = mesh;
  }
  summary.results["stats"] = {
      {"status", r.status},
      {"speed_rpm", speed / kRpm},
      {"design_torque_n_m", design},
      {"time_step_s", r.time_step},
      {"steps", r.steps},
      {"record_s", r.time_step * static_cast<double>(r.t.size())},
      {"record_from_time_analysis", record != nullptr},
      {"meshes", meshes},
      {"wall_time_s",
       std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()}};
  return 0;
}

}  // namespace geardyn::analysis::detail

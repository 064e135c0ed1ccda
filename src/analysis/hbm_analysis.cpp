/// `hbm`: harmonic-balance forced response swept in frequency.

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <numbers>

#include "geardyn/analysis/analyses.h"
#include "geardyn/analysis/hbm_results.h"
#include "geardyn/analysis/simulate_results.h"
#include "geardyn/config/hbm_config.h"
#include "geardyn/config/simulate_config.h"
#include "geardyn/error.h"

namespace geardyn::analysis {
namespace {

/// p2p of the stable branches of one sweep at frequency f (linear interpolation between
/// consecutive stable points that bracket it).
std::vector<double> stableP2pAt(const std::vector<analysis::SweepRow>& rows, double f) {
  std::vector<double> values;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const auto& a = rows[i - 1];
    const auto& b = rows[i];
    if (a.sweep != b.sweep || !a.stable || !b.stable) continue;
    if ((a.frequency - f) * (b.frequency - f) > 0.0 || a.frequency == b.frequency) continue;
    const double w = (f - a.frequency) / (b.frequency - a.frequency);
    values.push_back(a.p2p + w * (b.p2p - a.p2p));
  }
  return values;
}

using SweepRuns = std::vector<std::pair<std::string, ContinuationResult>>;

/// The continuation's options: the steps the user gave (in the unit of the keys), the others
/// derived from the problem (deriveContinuationSteps); `steps` records them for summary.json.
ContinuationOptions continuationOptions(const config::Config& config,
                                        const config::GearPairModelBuild& build,
                                        const HarmonicBalanceOptions& hbm_options, double scale,
                                        nlohmann::ordered_json& steps) {
  ContinuationOptions sweep;
  const auto given = [&](const char* key) {
    return config.has(key) ? config.real(key) * scale : 0.0;
  };
  sweep.initial_step = given("sweep.initial_step");
  sweep.min_step = given("sweep.min_step");
  sweep.max_step = given("sweep.max_step");
  sweep.fold_tolerance = given("sweep.fold_tolerance");
  sweep.display_scale = scale;
  sweep.display_unit = build.nondimensional ? "(nondimensional)" : "Hz";
  sweep.stability = config.boolean("sweep.stability");
  sweep.stability_method = config.string("sweep.stability_method") == "hill"
                               ? StabilityMethod::kHill
                               : StabilityMethod::kMonodromy;
  const double start = config.real("sweep.start"), stop = config.real("sweep.stop");
  if (!(stop > start)) {
    const std::string unit = build.nondimensional ? "" : " Hz";
    throw InputError("sweep.stop", fmt::format("{:g}{}", stop, unit),
                     fmt::format("must exceed sweep.start = {:g}{}", start, unit));
  }
  sweep.start = start * scale;
  sweep.stop = stop * scale;
  deriveContinuationSteps(sweep, build.natural_frequency, build.damping_ratio,
                          hbm_options.harmonics);
  if (sweep.fold_tolerance == 0.0) sweep.fold_tolerance = 1e-3 * (stop - start) * scale;
  steps = {{"initial_step", sweep.initial_step / scale},
           {"min_step", sweep.min_step / scale},
           {"max_step", sweep.max_step / scale},
           {"fold_tolerance", sweep.fold_tolerance / scale},
           {"derived", !config.has("sweep.max_step")}};
  return sweep;
}

/// The sweeps' points as rows, their folds, bifurcations and per-sweep record in summary.json.
struct SweepRecord {
  std::vector<analysis::SweepRow> rows;
  nlohmann::ordered_json folds = nlohmann::ordered_json::array();
  nlohmann::ordered_json bifurcations = nlohmann::ordered_json::array();
  nlohmann::ordered_json sweeps = nlohmann::ordered_json::object();
  int failures = 0, points = 0;
  bool completed = true;
};

SweepRecord recordSweeps(const SweepRuns& runs, HarmonicBalance& hbm, const GearPairModel& model,
                         double scale, AnalysisResult& result) {
  SweepRecord record;
  auto& rows = record.rows;
  for (const auto& [which, run] : runs) {
    const std::size_t first = rows.size();
    for (const auto& p : run.points)
      rows.push_back(analysis::sweepRow(hbm, model, p, which, scale));
    for (std::size_t index : run.folds) {
      record.folds.push_back({{"sweep", which},
                              {"frequency", rows[first + index].frequency},
                              {"p2p", rows[first + index].p2p}});
    }
    for (const Bifurcation& b : run.bifurcations) {
      record.bifurcations.push_back({{"sweep", which},
                                     {"type", toString(b.type)},
                                     {"frequency", rows[first + b.index].frequency},
                                     {"p2p", rows[first + b.index].p2p}});
    }
    record.failures += run.failures;
    record.points += static_cast<int>(run.points.size());
    record.completed = record.completed && run.completed;
    record.sweeps[which] = {{"points", run.points.size()},
                            {"completed", run.completed},
                            {"folds", run.folds.size()},
                            {"step_cuts", run.failures},
                            {"message", run.message}};
    if (!run.completed) result.errors.push_back("sweep " + which + ": " + run.message);
  }
  return record;
}

/// newmark.csv: Newmark runs at `sweep.newmark_frequencies` against the stable branches there.
void addNewmarkChecks(const config::Config& config, const GearPairModel& model,
                      const std::vector<analysis::SweepRow>& rows, double scale,
                      bool nondimensional, AnalysisResult& result) {
  const auto newmark_frequencies = config.realList("sweep.newmark_frequencies");
  if (newmark_frequencies.empty()) return;
  const std::string u = nondimensional ? "nondim" : "m";
  io::CsvTable table({nondimensional ? "frequency_nondim" : "frequency_hz",
                      "p2p_newmark_transverse_" + u, "p2p_hbm_transverse_" + u,
                      "relative_difference", "status"});
  nlohmann::ordered_json checks = nlohmann::ordered_json::array();
  for (double f : newmark_frequencies) {
    GearPairModelSpec spec = model.spec();
    spec.mesh_frequency = f * scale / (2.0 * std::numbers::pi);
    const GearPairModel at(spec);
    const TimeResponse r = solveTimeResponse(at, config::timeResponseOptionsFromConfig(config));
    const analysis::TimeResponseChannels c = analysis::channelsOf(at, r);
    const double p2p =
        *std::max_element(c.y.begin(), c.y.end()) - *std::min_element(c.y.begin(), c.y.end());
    const auto candidates = stableP2pAt(rows, f);
    double best = NAN;
    for (double v : candidates) {
      if (std::isnan(best) || std::abs(v - p2p) < std::abs(best - p2p)) best = v;
    }
    const double difference = std::isnan(best) ? NAN : best / p2p - 1.0;
    table.addRow({f, p2p, best, difference, toString(r.status)});
    checks.push_back(
        {{"frequency", f},
         {"p2p_newmark", p2p},
         {"p2p_hbm",
          std::isnan(best) ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(best)},
         {"relative_difference", std::isnan(difference) ? nlohmann::ordered_json(nullptr)
                                                        : nlohmann::ordered_json(difference)},
         {"status", toString(r.status)}});
  }
  result.addTable("newmark.csv", table);
  result.summary.results["newmark_checks"] = checks;
}

/// period_<i>_<sweep>.csv: one period of every distinct solution the sweeps cross at each of
/// `hbm.detail_frequencies` (solved there from the neighbours' interpolated coefficients).
void addDetailPeriods(const config::Config& config, HarmonicBalance& hbm,
                      const GearPairModel& model, const SweepRuns& runs,
                      const std::vector<analysis::SweepRow>& rows, double scale,
                      bool nondimensional, StabilityMethod stability_method,
                      AnalysisResult& result) {
  int detail = 0;
  for (double f : config.realList("hbm.detail_frequencies")) {
    std::vector<double> found;  // p2p of the solutions written at f (the sweeps meet the same ones)
    for (std::size_t i = 1; i < rows.size(); ++i) {
      if (rows[i].sweep != rows[i - 1].sweep ||
          (rows[i - 1].frequency - f) * (rows[i].frequency - f) > 0.0)
        continue;
      // Guess: interpolate the neighbours' coefficients, then solve at f.
      const auto& run = runs[rows[i].sweep == runs.front().first ? 0 : 1].second;
      const std::size_t first =
          rows[i].sweep == runs.front().first ? 0 : runs.front().second.points.size();
      const auto& a = run.points[i - 1 - first].solution;
      const auto& b = run.points[i - first].solution;
      const double w = (f * scale - a.omega) / (b.omega - a.omega);
      HarmonicBalancePoint point;
      point.omega = f * scale;
      point.q = a.q + w * (b.q - a.q);
      hbm.solve(point);
      if (!point.converged) continue;
      if (config.boolean("sweep.stability")) hbm.classify(point, stability_method, false);
      const auto x = hbm.timeSignal(point.q);
      const double p2p =
          *std::max_element(x.begin(), x.end()) - *std::min_element(x.begin(), x.end());
      if (std::any_of(found.begin(), found.end(),
                      [&](double v) { return std::abs(v - p2p) <= 1e-6 * p2p; }))
        continue;
      found.push_back(p2p);
      const auto force = hbm.meshForceSignal(point.q, point.omega);
      const bool nd = nondimensional;
      io::CsvTable table(
          {"tau_rad", nd ? "t_nondim" : "t_s", nd ? "x_transverse_nondim" : "x_transverse_m",
           nd ? "y_transverse_nondim" : "y_transverse_m",
           nd ? "mesh_force_transverse_nondim" : "mesh_force_transverse_n",
           nd ? "mesh_stiffness_transverse_nondim" : "mesh_stiffness_transverse_n_per_m"});
      for (std::size_t k = 0; k < x.size(); ++k) {
        const double phase = static_cast<double>(k) / x.size();
        const double y = x[k] - model.transmissionError().value(model.spec().initial_phase + phase);
        table.addRow({2.0 * std::numbers::pi * phase, 2.0 * std::numbers::pi * phase / point.omega,
                      x[k], y, force[k], y != 0.0 ? force[k] / y : 0.0});
      }
      const std::string name = fmt::format("period_{}_{}.csv", detail++, rows[i].sweep);
      result.addTable(name, table);
      result.summary.results["details"].push_back(
          {{"file", name}, {"frequency", f}, {"stable", point.stable}, {"p2p", p2p}});
    }
  }
}

/// The printed lines: points, folds, step cuts, the peak and the bifurcations, in the unit of
/// the configuration (nondimensional models: [-], the frequency as Ω/ω_n and the deflection in
/// x₀).
std::string hbmReport(const HarmonicBalanceOptions& hbm_options, const SweepRecord& record,
                      const nlohmann::ordered_json& peak, bool nondimensional) {
  const std::string length_unit = nondimensional ? " [-]" : " m";
  const std::string frequency_unit = nondimensional ? " [-]" : " Hz";
  std::string text =
      fmt::format("harmonic balance, H = {}, N = {}: {} points, {} folds, {} step cuts\n",
                  hbm_options.harmonics, hbm_options.samples_per_period, record.points,
                  record.folds.size(), record.failures);
  if (!peak.is_null()) {
    text += fmt::format("  peak p2p {:.6g}{} at {:.6g}{}\n", peak["p2p"].get<double>(), length_unit,
                        peak["frequency"].get<double>(), frequency_unit);
  }
  for (const auto& b : record.bifurcations) {
    text += fmt::format("  {} ({} sweep) at {:.6g}{}, p2p {:.6g}{}\n", b["type"].get<std::string>(),
                        b["sweep"].get<std::string>(), b["frequency"].get<double>(), frequency_unit,
                        b["p2p"].get<double>(), length_unit);
  }
  return text;
}

}  // namespace

AnalysisResult hbmAnalysis(const config::Config& config, const AnalysisContext& context) {
  context.checkBudget("hbm");
  const config::GearPairModelBuild build = config::buildGearPairModel(config, false);
  std::vector<std::string> warnings = build.warnings;
  const GearPairModel model(build.spec);
  const HarmonicBalanceOptions hbm_options = config::harmonicBalanceOptionsFromConfig(config);
  HarmonicBalance hbm(model, hbm_options);
  const double scale = build.nondimensional ? 1.0 : 2.0 * std::numbers::pi;  // ω = scale · f

  nlohmann::ordered_json steps;
  ContinuationOptions sweep = continuationOptions(config, build, hbm_options, scale, steps);
  const double start = config.real("sweep.start"), stop = config.real("sweep.stop");
  const std::string direction = config.string("sweep.direction");
  SweepRuns runs;
  const auto clock_start = std::chrono::steady_clock::now();
  for (const std::string which : {"up", "down"}) {
    if (direction != "both" && direction != which) continue;
    sweep.start = (which == "up" ? start : stop) * scale;
    sweep.stop = (which == "up" ? stop : start) * scale;
    sweep.progress = context.progressFor("hbm: sweep " + which, "");
    runs.emplace_back(which, continueInFrequency(hbm, sweep));
  }
  const double sweep_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count();

  AnalysisResult result("hbm", config, context);
  const SweepRecord record = recordSweeps(runs, hbm, model, scale, result);
  io::RunSummary& summary = result.summary;
  summary.status = record.completed ? "ok" : "incomplete_sweep";
  nlohmann::ordered_json peak;
  for (const auto& r : record.rows) {
    if (peak.is_null() || r.p2p > peak["p2p"].get<double>())
      peak = {{"frequency", r.frequency}, {"p2p", r.p2p}, {"stable", r.stable}};
  }
  summary.results = {{"points", record.points},
                     {"wall_time_s", sweep_seconds},
                     {"time_per_point_s", record.points > 0 ? sweep_seconds / record.points : 0.0},
                     {"folds", record.folds},
                     {"peak", peak},
                     {"failures", record.failures},
                     {"bifurcations", record.bifurcations},
                     {"continuation_steps", steps},
                     {"sweeps", record.sweeps},
                     {"harmonics", hbm_options.harmonics},
                     {"samples_per_period", hbm_options.samples_per_period},
                     {"natural_frequency", build.natural_frequency / scale}};
  result.addTable("sweep.csv",
                  analysis::sweepTable(record.rows, hbm_options.harmonics, build.nondimensional));
  addNewmarkChecks(config, model, record.rows, scale, build.nondimensional, result);
  addDetailPeriods(config, hbm, model, runs, record.rows, scale, build.nondimensional,
                   sweep.stability_method, result);

  summary.warnings = warnings;
  context.warnings(warnings);
  result.report = hbmReport(hbm_options, record, peak, build.nondimensional);
  result.summary.numerical_failure = !record.completed;
  return result;
}

}  // namespace geardyn::analysis

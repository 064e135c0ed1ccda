/// The Newmark checks of the `nonlinear` analysis of `geardyn train`
/// (train_nonlinear_analysis.h): nonlinear Newmark from the balance's stable solutions.

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

#include "geardyn/config/train_analysis.h"
#include "geardyn/error.h"
#include "geardyn/solvers/continuation.h"
#include "geardyn/solvers/train_harmonic_balance.h"
#include "geardyn/solvers/train_nonlinear_time.h"
#include "geardyn/units.h"
#include "train_nonlinear_analysis.h"
#include "wall_clock.h"

namespace geardyn::analysis::detail {
namespace {

using geardyn::units::kRpm;
constexpr double kTwoPi = 2.0 * std::numbers::pi;
using Json = nlohmann::ordered_json;

}  // namespace

/// nonlinear.stability_method: "monodromy" (the default) or "hill".
StabilityMethod stabilityMethod(const config::Config& analysis) {
  return analysis.string("nonlinear.stability_method") == "hill" ? StabilityMethod::kHill
                                                                 : StabilityMethod::kMonodromy;
}

/// Nonlinear Newmark started on every stable solution at the check speeds (unstable ones are
/// listed, not integrated: a time integration leaves them). A correct periodic solution is kept:
/// p2p of every mesh deflection (and clearance bearing radial displacement) within the Newmark
/// discretisation error.
Json newmarkChecks(const GearTrainModel& model, const config::Config& analysis,
                   TrainHarmonicBalance& hbm,
                   const std::vector<std::pair<std::string, ContinuationResult>>& runs,
                   double scale, bool stability, AnalysisResult& result,
                   const AnalysisContext& context) {
  const auto speeds = analysis.realList("nonlinear.newmark_speeds_rpm");
  Json checks = Json::array();
  if (speeds.empty()) return checks;
  TrainNonlinearTimeOptions options;
  options.steps_per_mesh_period =
      static_cast<int>(analysis.integer("nonlinear.newmark_steps_per_mesh_period"));
  options.event_refinement =
      static_cast<int>(analysis.integer("nonlinear.newmark_event_refinement"));
  options.contact_refinement =
      static_cast<int>(analysis.integer("nonlinear.newmark_contact_refinement"));
  options.max_periods = static_cast<int>(analysis.integer("nonlinear.newmark_max_periods"));
  options.validate();               // steps × 2^refinement, before any sweep runs
  options.steady_tolerance = 1e-7;  // p2p to 1e-7: far below the 1 % the check resolves
  std::vector<std::string> header{"speed_rpm", "solution", "stable", "newmark_status",
                                  "newmark_periods"};
  for (const TrainMesh& m : model.meshes()) {
    header.push_back("p2p_deflection_hbm_" + m.name + "_m");
    header.push_back("p2p_deflection_newmark_" + m.name + "_m");
  }
  for (const TrainClearanceBearing& b : model.clearanceBearings()) {
    header.push_back("p2p_radial_hbm_" + b.name + "_m");
    header.push_back("p2p_radial_newmark_" + b.name + "_m");
  }
  header.emplace_back("max_relative_difference");
  io::CsvTable table(header);
  const ProgressCallback progress =
      context.progressFor("train: nonlinear Newmark checks", "speeds");
  for (std::size_t k = 0; k < speeds.size(); ++k) {
    if (progress) progress(static_cast<double>(k), static_cast<double>(speeds.size()));
    const double omega = speeds[k] * scale;
    std::vector<const ContinuationResult*> sweeps;
    for (const auto& run : runs) sweeps.push_back(&run.second);
    const auto solutions = solutionsAtFrequency(hbm, sweeps, omega);
    if (solutions.empty()) {
      result.summary.warnings.push_back(
          fmt::format("nonlinear Newmark check at {:g} rpm: no harmonic-balance solution there "
                      "(the sweep did not reach it)",
                      speeds[k]));
    }
    for (std::size_t s = 0; s < solutions.size(); ++s) {
      HarmonicBalancePoint p = solutions[s];
      if (stability) hbm.classify(p, stabilityMethod(analysis), false);
      const Eigen::MatrixXd d = hbm.meshDeflections(p.q);
      const Eigen::MatrixXd u = hbm.bearingDisplacements(p.q);
      const auto radialP2p = [&](int b) {
        const Eigen::VectorXd radius = u.middleCols(2 * b, 2).rowwise().norm();
        return radius.maxCoeff() - radius.minCoeff();
      };
      std::vector<io::CsvCell> cells{
          speeds[k], static_cast<long long>(s),
          stability ? io::CsvCell(static_cast<long long>(p.stable)) : io::CsvCell(std::string())};
      Json check = {{"speed_rpm", speeds[k]}, {"solution", s}, {"stable", p.stable}};
      if (!p.stable) {
        cells.insert(cells.end(), {std::string("not_integrated_unstable"), 0LL});
        for (int m = 0; m < hbm.meshCount(); ++m) {
          cells.insert(cells.end(), {d.col(m).maxCoeff() - d.col(m).minCoeff(), std::string()});
        }
        for (int b = 0; b < hbm.bearingCount(); ++b) {
          cells.insert(cells.end(), {radialP2p(b), std::string()});
        }
        cells.emplace_back(std::string());
        table.addRow(cells);
        check["newmark_status"] = "not_integrated_unstable";
        checks.push_back(check);
        continue;
      }
      const auto [q0, v0] = hbm.initialState(p);
      const TrainNonlinearTimeResponse r =
          solveTrainNonlinearTime(model, hbm.inputSpeed(omega), options, q0, v0);
      cells.insert(cells.end(), {r.status, static_cast<long long>(r.periods)});
      double worst = 0.0;
      Json hbm_p2p = Json::object(), newmark_p2p = Json::object();
      Json hbm_radial = Json::object(), newmark_radial = Json::object();
      for (int m = 0; m < hbm.meshCount(); ++m) {
        const double a = d.col(m).maxCoeff() - d.col(m).minCoeff(), b = r.meshPeakToPeak(m);
        cells.insert(cells.end(), {a, b});
        worst = std::max(worst, std::abs(b / a - 1.0));
        hbm_p2p[model.meshes()[m].name] = a;
        newmark_p2p[model.meshes()[m].name] = b;
      }
      for (int b = 0; b < hbm.bearingCount(); ++b) {
        const double a = radialP2p(b), c = r.bearingRadialPeakToPeak(b);
        cells.insert(cells.end(), {a, c});
        worst = std::max(worst, std::abs(c / a - 1.0));
        hbm_radial[model.clearanceBearings()[b].name] = a;
        newmark_radial[model.clearanceBearings()[b].name] = c;
      }
      cells.emplace_back(worst);
      table.addRow(cells);
      check.update({{"newmark_status", r.status},
                    {"newmark_periods", r.periods},
                    {"newmark_refined_steps", r.refined_steps},
                    {"p2p_deflection_hbm_m", hbm_p2p},
                    {"p2p_deflection_newmark_m", newmark_p2p},
                    {"p2p_radial_hbm_m", hbm_radial},
                    {"p2p_radial_newmark_m", newmark_radial},
                    {"max_relative_difference", worst}});
      checks.push_back(check);
      if (r.status != "steady_state") {
        result.summary.warnings.push_back(
            fmt::format("nonlinear Newmark check at {:g} rpm (solution {}): {} after {} common "
                        "periods ({}); raise nonlinear.newmark_max_periods",
                        speeds[k], s, r.status, r.periods, r.message));
      }
    }
  }
  result.addTable("newmark_checks.csv", table);
  return checks;
}

}  // namespace geardyn::analysis::detail

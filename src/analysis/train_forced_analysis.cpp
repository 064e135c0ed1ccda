/// `train` [forced]: the linear steady state over a speed range (train_forced_analysis.h).
/// Balanced over the meshes' common period (train_response.h) when it is short, else on the
/// torus of the mesh phases (train_torus.h); forced.method forces either.

#include "train_forced_analysis.h"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <complex>
#include <functional>
#include <limits>
#include <mutex>
#include <numbers>
#include <optional>
#include <thread>

#include "geardyn/config/train_analysis.h"
#include "geardyn/error.h"
#include "geardyn/solvers/train_element_orders.h"
#include "geardyn/solvers/train_response.h"
#include "geardyn/torus/train_torus.h"
#include "geardyn/torus/train_torus_truncation.h"
#include "geardyn/units.h"
#include "torus_tones.h"
#include "train_housing_analysis.h"

namespace geardyn::analysis::detail {
namespace {

using geardyn::units::kRpm;
using Json = nlohmann::ordered_json;
using Clock = std::chrono::steady_clock;
/// forced_tones.csv lists a mesh's lines down to this fraction of its largest line: the
/// sidebands an analyst reads off a spectrum (60 dB below the strongest line).
constexpr double kToneTableFloor = 1e-3;

/// What one speed's steady state gives the tables, from either solver.
struct ForcedPoint {
  std::vector<double> dynamic_factor, p2p, element_force;
  std::vector<std::vector<double>> orders;  // per mesh, orders 1..L [N]
  std::vector<std::vector<TorusLine>> lines;
  int iterations = 0;
  bool direct = false;
};

ForcedPoint pointOf(const TrainSteadyState& s) {
  ForcedPoint p;
  p.dynamic_factor = s.dynamic_factor;
  for (std::size_t m = 0; m < s.mesh_force_max.size(); ++m) {
    p.p2p.push_back(s.mesh_force_max[m] - s.mesh_force_min[m]);
  }
  p.orders = s.mesh_force_harmonics;
  p.element_force = s.element_dynamic_force;
  return p;
}

ForcedPoint pointOf(TrainTorusState&& s) {
  ForcedPoint p;
  p.dynamic_factor = s.dynamic_factor;
  for (std::size_t m = 0; m < s.mesh_force_max.size(); ++m) {
    p.p2p.push_back(s.mesh_force_max[m] - s.mesh_force_min[m]);
  }
  p.orders = std::move(s.mesh_force_harmonics);
  p.element_force = s.element_dynamic_force;
  p.lines = std::move(s.mesh_force_lines);
  p.iterations = s.iterations;
  p.direct = s.linear_solver == "direct";
  return p;
}

/// Every speed's torus steady state (speed 0 skipped) on the worker threads (context.threads,
/// 0: all hardware threads; each takes the next speed in ascending order with its own
/// workspace, so that its GMRES starts from its previous speeds), progress reported as speeds
/// finish.
std::vector<ForcedPoint> solveTorusSpeeds(const TrainTorusSolver& solver,
                                          const std::vector<double>& speeds,
                                          const AnalysisContext& context,
                                          const ProgressCallback& progress) {
  std::vector<ForcedPoint> points(speeds.size());
  const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
  const std::size_t threads = std::min<std::size_t>(
      speeds.size(), context.threads > 0 ? static_cast<unsigned>(context.threads) : hardware);
  std::atomic<std::size_t> next{0};
  std::size_t finished = 0;
  std::mutex lock;
  std::exception_ptr failure;
  const auto work = [&] {
    TrainTorusWorkspace workspace;
    for (std::size_t i = next++; i < speeds.size(); i = next++) {
      try {
        if (speeds[i] != 0.0) points[i] = pointOf(solver.solve(speeds[i], workspace));
      } catch (...) {
        const std::lock_guard<std::mutex> guard(lock);
        if (!failure) failure = std::current_exception();
        next = speeds.size();
      }
      if (progress) {
        const std::lock_guard<std::mutex> guard(lock);
        progress(static_cast<double>(++finished), static_cast<double>(speeds.size()));
      }
    }
  };
  std::vector<std::thread> pool;
  for (std::size_t t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
  return points;
}

/// Mesh orders forced_bearing_orders.csv is written for (1..this, at most L).
constexpr int kBearingOrders = 3;

/// forced_bearing_orders.csv rows of one common-period steady state: the dynamic force of every
/// bearing element with force rows (radial: the (y, z) amplitudes combined; axial: `<b>.axial`;
/// tilt and torsion springs carry moments only and are left out) at each mesh's orders
/// 1..min(L, kBearingOrders) (train_element_orders.h: the spring force's harmonic) [N]: the path
/// of the whine orders into the housing.
void addBearingOrderRows(const GearTrainModel& model, const TrainSteadyState& state, double speed,
                         int mesh_harmonics, io::CsvTable& table) {
  const auto& meshes = model.meshes();
  const int orders = std::min(mesh_harmonics, kBearingOrders);
  for (const TrainElement& e : model.elements()) {
    if (e.kind != "bearing" ||
        std::all_of(e.moment_rows.begin(), e.moment_rows.end(), [](bool m) { return m; }))
      continue;
    for (std::size_t m = 0; m < meshes.size(); ++m) {
      const double f_m = meshes[m].frequency_ratio * std::abs(speed);
      for (int l = 1; l <= orders; ++l) {
        const int h = l * state.mesh_multiple[m];
        if (h > state.harmonics) break;
        table.addRow(
            {speed / kRpm, e.name, meshes[m].name, l, l * f_m, elementForceHarmonic(e, state, h)});
      }
    }
  }
}

/// Mesh orders the operating deflection shapes are written for (1..this, at most L).
constexpr int kOdsOrders = 3;

/// Per mesh, the complex amplitudes Q of every DOF at its orders 1..(at most kOdsOrders) at one
/// speed, q_l(t) = Re[Q e^{i l ω_m t}] [m, rad].
using OdsShapes = std::vector<std::vector<Eigen::VectorXcd>>;

/// The common-period steady state's shapes: Q = 2 X_h, h = l × the mesh's multiple of the base
/// frequency (train_response.h: q(t) = Re[X_0 + 2 Σ X_h e^{i h ω₀ t}]).
OdsShapes odsShapes(const TrainSteadyState& s, std::size_t meshes) {
  OdsShapes out(meshes);
  for (std::size_t m = 0; m < meshes; ++m) {
    for (int l = 1; l <= kOdsOrders && l * s.mesh_multiple[m] <= s.harmonics; ++l) {
      out[m].push_back(2.0 * s.harmonic.col(l * s.mesh_multiple[m]));
    }
  }
  return out;
}

/// The torus steady state's shapes: Q = 2 X_n at the tone n = l P_m e_{j(m)} of the mesh's own
/// generator (train_torus.h: q(t) = Σ_n X_n e^{i n·θ}, X_{−n} = conj X_n), while it is in T.
OdsShapes odsShapes(const TrainTorusState& s, std::size_t meshes) {
  OdsShapes out(meshes);
  for (std::size_t m = 0; m < meshes; ++m) {
    for (int l = 1; l <= kOdsOrders; ++l) {
      Eigen::VectorXi n = Eigen::VectorXi::Zero(s.tones.rows());
      n(s.mesh_generator[m]) = l * s.mesh_multiple[m];
      Eigen::Index t = 0;
      while (t < s.tones.cols() && s.tones.col(t) != n) ++t;
      if (t == s.tones.cols()) break;
      out[m].push_back(2.0 * s.harmonic.col(t));
    }
  }
  return out;
}

/// forced_ods.csv: the operating deflection shapes of the steady state (either balance), the
/// complex amplitude of every DOF at each mesh's orders 1..kOdsOrders (the unit column: m or
/// rad), at the operating speed and at each mesh's largest dynamic factor (`speeds`, rad/s;
/// duplicates skipped); `shapes(speed)` solves one speed.
void writeOds(const GearTrainModel& model, const std::function<OdsShapes(double)>& shapes,
              std::vector<double> speeds, AnalysisResult& result) {
  io::CsvTable ods({"speed_rpm", "mesh", "order", "frequency_hz", "dof", "unit", "real", "imag"});
  std::sort(speeds.begin(), speeds.end());
  speeds.erase(std::unique(speeds.begin(), speeds.end()), speeds.end());
  for (double speed : speeds) {
    if (speed == 0.0) continue;
    const OdsShapes shape = shapes(speed);
    for (std::size_t m = 0; m < model.meshes().size(); ++m) {
      const double f_m = model.meshes()[m].frequency_ratio * std::abs(speed);
      for (std::size_t l = 1; l <= shape[m].size(); ++l) {
        for (int i = 0; i < model.dofCount(); ++i) {
          const std::complex<double> q = shape[m][l - 1](i);
          const std::string name = model.dofName(i);
          const bool angle = name.find("theta") != std::string::npos;
          ods.addRow({speed / kRpm, model.meshes()[m].name, static_cast<int>(l),
                      static_cast<double>(l) * f_m, name, angle ? "rad" : "m", q.real(), q.imag()});
        }
      }
    }
  }
  result.addTable("forced_ods.csv", ods);
}

/// The derived truncation (train_truncation.h) into both solvers' options, and on the torus the
/// product index set weighted by its estimate unless forced.torus_truncation says "box" or
/// "diamond" (train_torus_truncation.h); returns L_m per mesh.
std::vector<int> deriveTruncation(const GearTrainModel& model, const std::vector<double>& speeds,
                                  const config::Config& analysis, TrainSteadyOptions& steady,
                                  TrainTorusOptions& torus_options) {
  const MeshHarmonicsEstimate estimate = estimateMeshHarmonics(model, speeds);
  steady.mesh_harmonics = estimate.harmonics;
  const std::string truncation = analysis.string("forced.torus_truncation");
  torus_options = torusOptionsFromEstimate(estimate, torus_options,
                                           truncation == "box"       ? TorusTruncation::kBox
                                           : truncation == "diamond" ? TorusTruncation::kDiamond
                                                                     : TorusTruncation::kProduct);
  return estimate.per_mesh;
}

/// summary.json's forced.torus: the generators (their orders and harmonics, the meshes on
/// each), the truncation, the tone count and the linear solves' effort.
Json torusJson(const GearTrainModel& model, const TrainTorusSolver& solver,
               const TrainTorusOptions& torus_options, int max_iterations, int direct) {
  const auto& meshes = model.meshes();
  const TrainTorusGenerators& g = solver.generators();
  Json generators = Json::array();
  for (std::size_t j = 0; j < g.ratio.size(); ++j) {
    Json members = Json::array();
    for (std::size_t m = 0; m < meshes.size(); ++m) {
      if (g.mesh_generator[m] == static_cast<int>(j)) {
        members.push_back({{"mesh", meshes[m].name}, {"multiple", g.mesh_multiple[m]}});
      }
    }
    // g_j per input revolution: the generator's events per turn of the input shaft.
    generators.push_back({{"order", g.ratio[j] * 2.0 * std::numbers::pi},
                          {"harmonics", g.harmonics[j]},
                          {"meshes", members}});
  }
  return {{"generators", generators},
          {"truncation", torus_options.truncation == TorusTruncation::kProduct   ? "product"
                         : torus_options.truncation == TorusTruncation::kDiamond ? "diamond"
                                                                                 : "box"},
          {"tones", solver.toneCount()},
          {"max_gmres_iterations", max_iterations},
          {"direct_solves", direct}};
}

}  // namespace

void runTrainForced(const GearTrainModel& model, const config::Config& analysis,
                    AnalysisResult& result, io::RunSummary& summary, std::string& text,
                    const AnalysisContext& context) {
  runTrainForcedAt(model, analysis, config::forcedSpeedsFromConfig(analysis, model.inputSpeed()),
                   result, summary, text, context);
}

void runTrainForcedAt(const GearTrainModel& model, const config::Config& analysis,
                      const std::vector<double>& speeds, AnalysisResult& result,
                      io::RunSummary& summary, std::string& text, const AnalysisContext& context) {
  const auto start = Clock::now();
  TrainSteadyOptions steady = config::trainSteadyOptionsFromConfig(analysis);
  TrainTorusOptions torus_options = config::trainTorusOptionsFromConfig(analysis);
  // Without forced.mesh_harmonics: L_m per mesh from the problem (train_truncation.h).
  const bool derived = !analysis.has("forced.mesh_harmonics");
  const std::vector<int> per_mesh =
      derived ? deriveTruncation(model, speeds, analysis, steady, torus_options)
              : std::vector<int>(model.meshes().size(), steady.mesh_harmonics);
  // Base harmonics the common period needs: L_m × the multiple of its base, the largest.
  int common_harmonics = 0;
  const std::vector<int> multiples =
      trainBaseFrequency(model, 1, std::numeric_limits<int>::max()).mesh_multiple;
  for (std::size_t m = 0; m < multiples.size(); ++m) {
    common_harmonics = std::max(common_harmonics, multiples[m] * per_mesh[m]);
  }
  const std::string requested = analysis.string("forced.method");
  const bool torus = requested == "torus" ||
                     (requested == "auto" && common_harmonics > torus_options.group_harmonics);
  std::optional<TrainSteadySolver> common;
  std::optional<TrainTorusSolver> torus_solver;
  if (torus) {
    torus_solver.emplace(model, torus_options);
  } else {
    common.emplace(model, steady);
  }
  const auto& meshes = model.meshes();
  std::vector<std::string> header{"speed_rpm"};
  for (const TrainMesh& m : meshes) {
    header.push_back("dynamic_factor_" + m.name);
    header.push_back("p2p_" + m.name + "_normal_n");  // mesh force along the contact normal
    header.push_back("h1_" + m.name + "_normal_n");
  }
  for (const TrainElement& e : model.elements()) {
    header.push_back(
        fmt::format("dynamic_{}_{}", e.name, e.local_stiffness.rows() == 1 ? "n_m" : "n"));
  }
  io::CsvTable table(header);
  io::CsvTable orders_table({"speed_rpm", "mesh", "order", "frequency_hz", "amplitude_n"});
  io::CsvTable bearing_orders(
      {"speed_rpm", "bearing", "mesh", "order", "frequency_hz", "amplitude_n"});
  std::vector<std::string> tone_header{"speed_rpm", "mesh"};
  const int k = torus ? static_cast<int>(torus_solver->generators().ratio.size()) : 0;
  for (int j = 0; j < k; ++j) tone_header.push_back(fmt::format("harmonic_g{}", j + 1));
  for (const char* column : {"tone", "frequency_hz", "amplitude_n", "relative_amplitude"}) {
    tone_header.push_back(column);
  }
  io::CsvTable tones_table(tone_header);
  // Per mesh: the largest dynamic factor and the largest peak-to-peak mesh force over the
  // speeds, each with its speed (the headline numbers a sweep over `train` names).
  std::vector<double> worst(meshes.size(), 0.0), worst_speed(meshes.size(), 0.0);
  std::vector<double> p2p(meshes.size(), 0.0), p2p_speed(meshes.size(), 0.0);
  int max_iterations = 0, direct = 0;
  const ProgressCallback progress = context.progressFor("train: forced response", "speeds");
  // The housing's response points (common period only: the torus keeps no DOF harmonics).
  HousingResponseTable housing(model);
  // The torus speeds on the worker threads (the solver is thread-safe), in order afterwards.
  std::vector<ForcedPoint> torus_points;
  if (torus) torus_points = solveTorusSpeeds(*torus_solver, speeds, context, progress);
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    if (progress && !torus) progress(static_cast<double>(i), static_cast<double>(speeds.size()));
    if (speeds[i] == 0.0) continue;
    const double speed = speeds[i];
    ForcedPoint s;
    if (torus) {
      s = std::move(torus_points[i]);
    } else {
      // The housing's response points and seat rows only (issue 37); the ODS below solve again
      // with every row.
      const TrainSteadyState state = common->solve(speed, /*housing_rows=*/false);
      addBearingOrderRows(model, state, speed, steady.mesh_harmonics, bearing_orders);
      housing.add(state);
      s = pointOf(state);
    }
    max_iterations = std::max(max_iterations, s.iterations);
    direct += s.direct ? 1 : 0;
    std::vector<io::CsvCell> row{speed / kRpm};
    for (std::size_t m = 0; m < meshes.size(); ++m) {
      row.push_back(s.dynamic_factor[m]);
      row.push_back(s.p2p[m]);
      row.push_back(s.orders[m][0]);
      if (s.dynamic_factor[m] > worst[m]) worst[m] = s.dynamic_factor[m], worst_speed[m] = speed;
      if (s.p2p[m] > p2p[m]) p2p[m] = s.p2p[m], p2p_speed[m] = speed;
      const double f_m = meshes[m].frequency_ratio * std::abs(speed);
      for (std::size_t l = 0; l < s.orders[m].size(); ++l) {
        orders_table.addRow({speed / kRpm, meshes[m].name, static_cast<int>(l + 1), (l + 1.0) * f_m,
                             s.orders[m][l]});
      }
      if (torus)
        addToneRows(tones_table, speed / kRpm, meshes[m].name, s.lines[m], kToneTableFloor);
    }
    for (double f : s.element_force) row.push_back(f);
    table.addRow(row);
  }
  result.addTable("forced_response.csv", table);
  std::vector<double> ods_speeds = worst_speed;
  ods_speeds.push_back(model.inputSpeed());
  const std::size_t r = meshes.size();
  writeOds(
      model,
      [&](double speed) {
        return torus ? odsShapes(torus_solver->solve(speed), r)
                     : odsShapes(common->solve(speed), r);
      },
      ods_speeds, result);
  result.addTable("forced_mesh_orders.csv", orders_table);
  if (!torus) result.addTable("forced_bearing_orders.csv", bearing_orders);
  if (torus) result.addTable("forced_tones.csv", tones_table);
  Json peaks = Json::object();
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    peaks[meshes[m].name] = {{"max_dynamic_factor", worst[m]},
                             {"at_speed_rpm", worst_speed[m] / kRpm},
                             {"max_p2p_force_n", p2p[m]},
                             {"max_p2p_force_at_speed_rpm", p2p_speed[m] / kRpm}};
    text += fmt::format("  {}: max dynamic factor {:.3f} [-] at {:.0f} rpm\n", meshes[m].name,
                        worst[m], worst_speed[m] / kRpm);
  }
  Json forced = {{"speeds", speeds.size()},
                 {"mesh_harmonics", steady.mesh_harmonics},
                 {"mesh_harmonics_derived", derived},
                 {"mesh_harmonics_per_mesh", Json::object()},
                 {"method", torus ? "torus" : "common_period"},
                 {"common_period_harmonics", common_harmonics}};
  if (torus)
    forced["torus"] = torusJson(model, *torus_solver, torus_options, max_iterations, direct);
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    forced["mesh_harmonics_per_mesh"][meshes[m].name] = per_mesh[m];
  }
  forced["meshes"] = peaks;
  summary.results["forced"] = forced;
  housing.write(result, summary, text);
  forced = summary.results["forced"];
  if (torus && housing.active()) {
    summary.warnings.push_back(
        "forced: the housing's response points are reported with the common-period method only "
        "(forced.method = \"common_period\")");
  }
  forced["wall_time_s"] = std::chrono::duration<double>(Clock::now() - start).count();
  summary.results["forced"] = forced;
  text += fmt::format("forced response ({}): {} speeds in {:.2f} s\n",
                      torus ? fmt::format("torus, {} generators", k) : "common period",
                      speeds.size(), forced["wall_time_s"].get<double>());
}

}  // namespace geardyn::analysis::detail

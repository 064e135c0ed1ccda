/// The `time` analysis of `geardyn train` (see train_time_analysis.h).

#include "train_time_analysis.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <nlohmann/json.hpp>
#include <numbers>

#include "geardyn/analysis/run_budget.h"
#include "geardyn/analysis/run_estimates.h"
#include "geardyn/config/train_analysis.h"
#include "geardyn/error.h"
#include "geardyn/io/csv_table.h"
#include "geardyn/solvers/detail/train_time_full_law.h"
#include "geardyn/solvers/train_harmonic_balance.h"
#include "geardyn/solvers/train_response.h"
#include "geardyn/system/bearing_law.h"
#include "geardyn/torus/train_torus.h"
#include "geardyn/units.h"
#include "train_probes_analysis.h"
#include "train_undamped_modes.h"
#include "wall_clock.h"

namespace geardyn::analysis::detail {
namespace {

using geardyn::units::kRpm;
using Json = nlohmann::ordered_json;

/// How the derived duration came about (null when time.duration was given).
Json transientJson(const TrainTimeResponse& r) {
  if (!r.transient) return nullptr;
  return {{"decay_time_s", r.transient->decay_time},
          {"slowest_mode_frequency_hz", r.transient->slowest_frequency},
          {"slowest_mode_damping_ratio", r.transient->slowest_damping_ratio},
          {"undamped_modes_hz", [&] {
             Json list = Json::array();
             for (const TrainUndampedMode& m : r.transient->undamped) list.push_back(m.frequency);
             return list;
           }()}};
}

/// The plan of the time run, refused before it allocates when a mode the forcing drives has no
/// damping (naming the keys that would damp it) or when it would not fit in memory.
TrainTimePlan planTime(const GearTrainModel& model, double speed, const TrainTimeOptions& options,
                       const AnalysisContext& context) {
  const TrainTimePlan plan = planTrainTimeResponse(model, speed, options);
  if (plan.transient) {
    for (const TrainUndampedMode& mode : plan.transient->undamped) {
      if (!mode.excited) continue;
      std::vector<std::string> keys = dampingKeysOf(model, mode);
      keys.push_back("gearbox.mass_proportional_damping");
      throw InputError("time.duration", "0 (derived)",
                       fmt::format("a duration > 0 s: the mode at {:.4g} Hz has no damping and {} "
                                   "excite it, so its transient never decays; damp it with "
                                   "{} or give time.duration",
                                   mode.frequency, forcingOf(model), fmt::join(keys, ", ")));
    }
  }
  if (plan.steps <= kMaxTrainTimeSteps) {
    RunEstimate estimate = estimateTrainTime(
        static_cast<double>(plan.steps), model.dofCount(),
        static_cast<double>(options.record_periods * plan.steps_per_period), options.record_rates,
        static_cast<int>(model.meshes().size()), "time.duration",
        options.duration > 0.0 ? fmt::format("{:g} s", options.duration)
                               : fmt::format("0 (derived: {:.4g} s)", plan.duration));
    if (estimate.bytes > memoryLimitBytes()) {  // the kept window, not the duration, is large
      estimate.key = "time.record_periods";
      estimate.value = std::to_string(options.record_periods);
    }
    context.note(checkRunEstimate(estimate, "train time"));
  }
  return plan;
}

/// The radial bearing elements (rows u_y, u_z of the relative displacement: a stiffness
/// bearing's two, a rolling bearing's first two of five; system/train_elements.cpp): the
/// columns bearing_force_<name>_y_n and _z_n of time_history.csv.
std::vector<const TrainElement*> radialBearings(const GearTrainModel& model) {
  std::vector<const TrainElement*> out;
  for (const TrainElement& e : model.elements()) {
    if (e.kind == "bearing" && e.jacobian.rows() >= 2 && !e.moment_rows[0] && !e.moment_rows[1] &&
        e.name.find('.') == std::string::npos)
      out.push_back(&e);
  }
  return out;
}

/// The radial bearings' spring forces (k J q[dofs])_{y,z} over a record [N] (the static load
/// included; a bearing on its full law: the law's F(u)_{y,z}, bearing_law.h), Newmark's and the
/// steady state's, and the largest distance between the two force
/// vectors against the steady state's peak-to-peak (the larger of its y and z ranges): the
/// comparison of a train without meshes (a rotor with an unbalance, whose bearing force turns at
/// a constant magnitude).
class BearingForces {
 public:
  BearingForces(const GearTrainModel& model, const std::vector<const TrainElement*>& bearings)
      : worst_(bearings.size(), 0.0),
        low_(bearings.size(), {HUGE_VAL, HUGE_VAL}),
        high_(bearings.size(), {-HUGE_VAL, -HUGE_VAL}),
        law_(bearings.size(), -1),
        laws_(trainBearingLaws(model)) {
    for (std::size_t b = 0; b < bearings.size(); ++b) {
      for (std::size_t l = 0; l < laws_.size(); ++l) {
        if (laws_[l].bearing().rolling && laws_[l].bearing().name == bearings[b]->name)
          law_[b] = static_cast<int>(l);
      }
    }
  }
  /// Appends sample k's columns to `row`: Newmark's (y, z) forces per bearing, then the steady
  /// state's (q: its displacements on the record's times; null: no comparison).
  void add(const std::vector<const TrainElement*>& bearings,
           const Eigen::Ref<const Eigen::RowVectorXd>& newmark, const Eigen::MatrixXd* q,
           Eigen::Index k, std::vector<io::CsvCell>& row) {
    std::vector<Eigen::Vector2d> newmark_force(bearings.size());
    for (std::size_t b = 0; b < bearings.size(); ++b) {
      newmark_force[b] = force(*bearings[b], law_[b], newmark);
      row.push_back(newmark_force[b](0));
      row.push_back(newmark_force[b](1));
    }
    if (!q) return;
    for (std::size_t b = 0; b < bearings.size(); ++b) {
      const Eigen::Vector2d f = force(*bearings[b], law_[b], q->row(k));
      row.push_back(f(0));
      row.push_back(f(1));
      worst_[b] = std::max(worst_[b], (f - newmark_force[b]).norm());
      low_[b] = low_[b].cwiseMin(f), high_[b] = high_[b].cwiseMax(f);
    }
  }
  /// Per bearing: the largest |F_Newmark − F_steady| over the record relative to the steady
  /// state's peak-to-peak (0 where it has none).
  nlohmann::ordered_json differences(const std::vector<const TrainElement*>& bearings) const {
    nlohmann::ordered_json out = nlohmann::ordered_json::object();
    for (std::size_t b = 0; b < bearings.size(); ++b) {
      const double p2p = (high_[b] - low_[b]).maxCoeff();
      out[bearings[b]->name] = p2p > 0 ? worst_[b] / p2p : 0.0;
    }
    return out;
  }

 private:
  Eigen::Vector2d force(const TrainElement& e, int law,
                        const Eigen::Ref<const Eigen::RowVectorXd>& q) const {
    Eigen::VectorXd local(static_cast<Eigen::Index>(e.dofs.size()));
    for (std::size_t i = 0; i < e.dofs.size(); ++i)
      local(static_cast<Eigen::Index>(i)) = q(e.dofs[i]);
    const Eigen::VectorXd u = e.jacobian * local;
    if (law < 0) return (e.local_stiffness * u).head<2>();
    const TrainBearingLaw& l = laws_[law];
    return l.contactForce(TrainBearingLaw::Vector(u.head(l.width())), nullptr).head<2>();
  }
  std::vector<double> worst_;
  std::vector<Eigen::Vector2d> low_, high_;
  std::vector<int> law_;  // per bearing: its full law in laws_, or −1
  std::vector<TrainBearingLaw> laws_;
};

/// The frequency-domain steady state a time run is compared with, on the run's times `t`: the
/// common-period balance, or on the torus of the mesh phases (train_torus.h) when the common
/// period needs more than forced.torus_above harmonics (its peaks, orders and q(t) stand in for
/// the balance's, which would need thousands of harmonics). `compare` is false, with a warning,
/// when neither can be solved.
struct SteadyReference {
  bool compare = true, torus = false;
  bool full_law = false;  ///< the nonlinear balance (a rolling bearing's full law)
  TrainSteadyOptions options;
  TrainSteadyState state;
  Eigen::MatrixXd q;  ///< rows: the times t, cols: DOFs [m, rad]
  int base_harmonics = 0;
  Clock::time_point start;
};

/// With a rolling bearing's full law the reference is the nonlinear common-period balance
/// (train_harmonic_balance.h, [nonlinear] harmonics and samples) at the run's speed, from its
/// starting guess: q(t) = X₀ + Σ_h (X_{c,h} cos hω₀t + X_{s,h} sin hω₀t), the mesh forces'
/// extremes and their harmonics at the mesh orders from its samples.
void fullLawReference(const GearTrainModel& model, const config::Config& analysis, double speed,
                      const Eigen::VectorXd& t, SteadyReference& ref) {
  TrainHarmonicBalance hbm(model, config::trainHarmonicBalanceOptionsFromConfig(analysis));
  HarmonicBalancePoint p;
  p.omega = hbm.baseFrequency(speed);
  p.q = hbm.startingGuess(p.omega);
  hbm.solve(p);
  if (!p.converged) {
    throw InputError("nonlinear.harmonics", std::to_string(hbm.harmonics()),
                     fmt::format("a nonlinear balance that converges at {:g} rpm (residual {:.3g}) "
                                 "for the comparison of the time run with the full bearing law",
                                 speed / kRpm, p.residual));
  }
  const Eigen::MatrixXd X = hbm.displacementCoefficients(p);
  const int H = hbm.harmonics();
  ref.q.resize(t.size(), X.rows());
  for (Eigen::Index k = 0; k < t.size(); ++k) {
    Eigen::VectorXd q = X.col(0);
    for (int h = 1; h <= H; ++h) {
      q += X.col(2 * h - 1) * std::cos(h * p.omega * t(k)) +
           X.col(2 * h) * std::sin(h * p.omega * t(k));
    }
    ref.q.row(k) = q.transpose();
  }
  const Eigen::MatrixXd f = hbm.meshContactForces(p.q);  // samples over a common period
  const auto N = static_cast<double>(f.rows());
  ref.state.mesh_multiple = hbm.meshMultiples();
  for (Eigen::Index m = 0; m < f.cols(); ++m) {
    ref.state.mesh_force_max.push_back(f.col(m).maxCoeff());
    ref.state.mesh_force_min.push_back(f.col(m).minCoeff());
    const int p_m = ref.state.mesh_multiple[m];
    std::vector<double> amplitudes;
    for (int l = 1; l * p_m <= H; ++l) {
      std::complex<double> sum = 0.0;
      for (Eigen::Index i = 0; i < f.rows(); ++i)
        sum += f(i, m) * std::polar(1.0, -2.0 * std::numbers::pi * l * p_m * i / N);
      amplitudes.push_back(2.0 * std::abs(sum) / N);
    }
    ref.state.mesh_force_harmonics.push_back(amplitudes);
  }
  ref.base_harmonics = H;
}

SteadyReference steadyReference(const GearTrainModel& model, const config::Config& analysis,
                                double speed, const Eigen::VectorXd& t, io::RunSummary& summary) {
  SteadyReference ref;
  ref.start = Clock::now();
  if (geardyn::detail::hasFullBearingLaw(model)) {
    ref.full_law = true;
    try {
      fullLawReference(model, analysis, speed, t, ref);
    } catch (const InputError& e) {
      ref.compare = false;
      summary.warnings.push_back(std::string("no frequency-domain comparison: ") + e.what());
    }
    return ref;
  }
  ref.options.mesh_harmonics = static_cast<int>(analysis.integer("time.mesh_harmonics"));
  ref.options.max_base_harmonics = static_cast<int>(analysis.integer("forced.max_base_harmonics"));
  const TrainBaseFrequency base = trainBaseFrequency(model, 1, 1 << 30);
  const int common_harmonics =
      ref.options.mesh_harmonics *
      (base.mesh_multiple.empty()
           ? 1
           : *std::max_element(base.mesh_multiple.begin(), base.mesh_multiple.end()));
  ref.torus = common_harmonics > analysis.integer("forced.torus_above");
  ref.base_harmonics = common_harmonics;
  try {
    if (ref.torus) {
      TrainTorusOptions options = config::trainTorusOptionsFromConfig(analysis);
      options.mesh_harmonics = ref.options.mesh_harmonics;
      options.group_harmonics = std::max(options.group_harmonics, options.mesh_harmonics);
      TrainTorusState torus = TrainTorusSolver(model, options).solve(speed);
      ref.q = torus.displacement(t);
      ref.state.mesh_force_max = torus.mesh_force_max;
      ref.state.mesh_force_min = torus.mesh_force_min;
      ref.state.mesh_force_harmonics = torus.mesh_force_harmonics;
      ref.state.mesh_multiple = base.mesh_multiple;
    } else {
      ref.state = solveTrainSteadyState(model, speed, ref.options);
      ref.q = ref.state.displacement(t);
      ref.base_harmonics = ref.state.harmonics;
    }
  } catch (const InputError& e) {
    ref.compare = false;
    summary.warnings.push_back(std::string("no frequency-domain comparison: ") + e.what());
  }
  return ref;
}

/// How far the steady state itself is from converged (a stiffness with jumps, such as the
/// potential-energy model's, needs many harmonics): the largest change of its mesh forces over
/// the window `t` when its mesh harmonics are doubled, per mesh, relative to the p2p (empty when
/// twice the harmonics exceed forced.max_base_harmonics).
Json steadyTruncation(const GearTrainModel& model, double speed, const TrainSteadyOptions& steady,
                      const Eigen::VectorXd& t, const TrainSteadyState& s,
                      const Eigen::MatrixXd& steady_force) {
  Json truncation = Json::object();
  TrainSteadyOptions doubled = steady;
  doubled.mesh_harmonics *= 2;
  try {
    const Eigen::MatrixXd q2 = solveTrainSteadyState(model, speed, doubled).displacement(t);
    for (std::size_t m = 0; m < model.meshes().size(); ++m) {
      const TrainMesh& mesh = model.meshes()[m];
      const auto column = static_cast<Eigen::Index>(m);
      double change = 0.0;
      for (Eigen::Index k = 0; k < t.size(); ++k) {
        change = std::max(change, std::abs(steady_force(k, column) -
                                           mesh.force(t(k), speed, q2.row(k).transpose())));
      }
      const double p2p = s.mesh_force_max[m] - s.mesh_force_min[m];
      truncation[model.meshes()[m].name] = p2p > 0 ? change / p2p : 0.0;
    }
  } catch (const InputError&) {
    // Twice the harmonics exceed forced.max_base_harmonics: not estimated (null).
  }
  return truncation;
}

/// Mesh-force harmonics of the Newmark window (whole common periods) against the balance's:
/// pointwise values near a stiffness jump converge slowly in both methods (Gibbs, step size),
/// the harmonics at the mesh orders quickly. Orders 1..3 per mesh.
Json meshForceHarmonics(const GearTrainModel& model, const config::Config& analysis,
                        const TrainSteadyState& s, const TrainTimeResponse& r) {
  Json harmonics = Json::object();
  const int periods = static_cast<int>(analysis.integer("time.record_periods"));
  for (std::size_t m = 0; m < model.meshes().size(); ++m) {
    const Eigen::VectorXd f = r.mesh_force.col(static_cast<Eigen::Index>(m));
    const double scale = s.mesh_force_harmonics[m][0];
    Json orders = Json::array();
    for (int l = 1; l <= 3 && l <= static_cast<int>(s.mesh_force_harmonics[m].size()); ++l) {
      const double step =
          2.0 * std::numbers::pi * l * s.mesh_multiple[m] * periods / static_cast<double>(f.size());
      std::complex<double> sum = 0.0;
      for (Eigen::Index k = 0; k < f.size(); ++k) sum += f(k) * std::polar(1.0, -step * k);
      const double newmark = 2.0 * std::abs(sum) / static_cast<double>(f.size());
      const double hbm = s.mesh_force_harmonics[m][l - 1];
      orders.push_back(
          {{"order", l},
           {"newmark_n", newmark},
           {"steady_state_n", hbm},
           {"difference_relative_to_order_1", scale > 0 ? std::abs(newmark - hbm) / scale : 0.0}});
    }
    harmonics[model.meshes()[m].name] = orders;
  }
  return harmonics;
}

}  // namespace

int runTrainTime(const GearTrainModel& model, const config::Config& analysis,
                 AnalysisResult& result, std::string& text,
                 std::optional<TrainTimeResponse>& record, const AnalysisContext& context) {
  io::RunSummary& summary = result.summary;
  const auto start = Clock::now();
  const double speed = config::analysisSpeed(analysis, "time", model.inputSpeed());
  checkTrainProbes(model, analysis, speed);
  const TrainTimeOptions options = config::trainTimeOptionsFromConfig(analysis);
  const TrainTimePlan plan = planTime(model, speed, options, context);
  const bool dormand_prince = options.method == TrainTimeMethod::kDormandPrince;
  const TrainTimeResponse r = solveTrainTimeResponse(
      model, speed, options, plan,
      context.progressFor("train: time", dormand_prince ? "s simulated" : "Newmark steps"));
  const double seconds = secondsSince(start);
  if (r.status != "completed") {
    summary.warnings.push_back(r.message);
    summary.results["time"] = {{"status", r.status}, {"steps", r.steps}};
    return 1;
  }
  // The frequency-domain steady state on the same window, for the comparison a user would make.
  const SteadyReference ref = steadyReference(model, analysis, speed, r.t, summary);
  const bool compare = ref.compare, torus = ref.torus || ref.full_law;
  const TrainSteadyState& s = ref.state;
  const Eigen::MatrixXd& q = ref.q;
  const TrainSteadyOptions& steady = ref.options;
  std::vector<std::string> header{"t_s"};
  for (const TrainMesh& m : model.meshes()) header.push_back("mesh_force_" + m.name + "_normal_n");
  const auto steady_start = ref.start;
  if (compare) {
    for (const TrainMesh& m : model.meshes())
      header.push_back("steady_mesh_force_" + m.name + "_normal_n");
  }
  const std::vector<const TrainElement*> bearings = radialBearings(model);
  for (const char* prefix : {"", "steady_"}) {
    if (*prefix && !compare) break;
    for (const TrainElement* b : bearings) {
      header.push_back(fmt::format("{}bearing_force_{}_y_n", prefix, b->name));
      header.push_back(fmt::format("{}bearing_force_{}_z_n", prefix, b->name));
    }
  }
  io::CsvTable table(header);
  BearingForces bearing_forces(model, bearings);
  // The steady state's mesh forces on the record's times (also the truncation check's base).
  Eigen::MatrixXd steady_force(compare ? r.t.size() : 0, r.mesh_force.cols());
  Json differences = Json::object();
  std::vector<double> worst(model.meshes().size(), 0.0);
  // Rows of every `stride`-th step: a long record's table (a 1 s probe record at 512 steps a
  // mesh period is 3e5 rows) need not hold the integrator's resolution.
  const Eigen::Index stride = analysis.integer("time.history_stride");
  for (Eigen::Index k = 0; k < r.t.size(); ++k) {
    std::vector<io::CsvCell> row{r.t(k)};
    for (Eigen::Index m = 0; m < r.mesh_force.cols(); ++m) row.push_back(r.mesh_force(k, m));
    if (compare) {
      for (std::size_t m = 0; m < model.meshes().size(); ++m) {
        const double f = model.meshes()[m].force(r.t(k), speed, q.row(k).transpose());
        steady_force(k, static_cast<Eigen::Index>(m)) = f;
        worst[m] = std::max(worst[m], std::abs(f - r.mesh_force(k, static_cast<Eigen::Index>(m))));
        row.push_back(f);
      }
    }
    bearing_forces.add(bearings, r.displacement.row(k), compare ? &q : nullptr, k, row);
    if (k % stride == 0) table.addRow(row);
  }
  result.addTable("time_history.csv", table);
  const Json truncation = compare && !torus
                              ? steadyTruncation(model, speed, steady, r.t, s, steady_force)
                              : Json::object();
  const Json harmonics = compare ? meshForceHarmonics(model, analysis, s, r) : Json::object();
  if (compare) {
    for (std::size_t m = 0; m < model.meshes().size(); ++m) {
      const double p2p = s.mesh_force_max[m] - s.mesh_force_min[m];
      differences[model.meshes()[m].name] = p2p > 0 ? worst[m] / p2p : 0.0;
    }
  }
  // Newmark from the static state and the balance are two solutions of one periodic problem:
  // beyond 5 % of p2p one of them has not converged (a transient that has not decayed, a step
  // too coarse for the stiffness jumps, too few harmonics).
  constexpr double kAgreement = 0.05;
  std::string status = r.status;
  std::vector<std::string> disagreeing;
  // A train without meshes (a rotor with an unbalance) is compared by its bearing forces.
  const Json bearing_differences = compare ? bearing_forces.differences(bearings) : Json();
  if (model.meshes().empty() && compare) {
    for (const auto& [bearing, difference] : bearing_differences.items()) {
      if (difference.get<double>() > kAgreement)
        disagreeing.push_back(
            fmt::format("bearing {} {:.3g} %", bearing, 100.0 * difference.get<double>()));
    }
  }
  for (const auto& [mesh, difference] : differences.items()) {
    if (difference.get<double>() > kAgreement) {
      const std::string own =
          truncation.contains(mesh)
              ? fmt::format(
                    ", the steady state itself {:.3g} % from its value at twice the "
                    "harmonics",
                    100.0 * truncation[mesh].get<double>())
              : std::string();
      disagreeing.push_back(
          fmt::format("{} {:.3g} %{}", mesh, 100.0 * difference.get<double>(), own));
    }
  }
  if (!disagreeing.empty()) {
    status = "differs_from_steady_state";
    summary.warnings.push_back(fmt::format(
        "time: Newmark and the frequency-domain steady state differ by more than {:g} % of the "
        "{} force's p2p ({}): one has not converged; raise time.steps_per_mesh_period and "
        "time.mesh_harmonics, or give a longer time.duration",
        100.0 * kAgreement, model.meshes().empty() ? "bearing" : "mesh",
        fmt::join(disagreeing, ", ")));
  }
  const double steady_seconds = compare ? secondsSince(steady_start) : 0.0;
  summary.results["time"] = {
      {"status", status},
      {"method", dormand_prince ? "dormand_prince" : "newmark"},
      {"speed_rpm", speed / kRpm},
      {"time_step_s", r.time_step},
      {"steps", r.steps},
      {"wall_time_s", seconds},
      {"steady_state_wall_time_s", steady_seconds},
      {"duration_s", static_cast<double>(r.steps) * r.time_step},
      {"transient", transientJson(r)},
      {"step_time_us", 1e6 * seconds / static_cast<double>(r.steps)},
      {"steady_state_method",
       ref.full_law ? "nonlinear_balance" : (torus ? "torus" : "common_period")},
      {"full_bearing_law", geardyn::detail::hasFullBearingLaw(model)},
      {"max_difference_to_steady_state_relative_to_p2p", differences},
      {"bearing_force_difference_to_steady_state_relative_to_p2p", bearing_differences},
      {"steady_state_truncation_relative_to_p2p", truncation.empty() ? Json() : truncation},
      {"mesh_force_harmonics", harmonics}};
  if (dormand_prince) {
    summary.results["time"]["integrator_steps"] = r.integrator_steps;
    summary.results["time"]["relative_tolerance"] = options.relative_tolerance;
  }
  if (r.transient) {
    const std::string undamped = undampedModesWarning(model, r.transient->undamped, speed / kRpm);
    if (!undamped.empty()) summary.warnings.push_back(undamped);
  }
  text += fmt::format(
      "time: {} Newmark steps of {:.3g} s in {:.2f} s{}\n", r.steps, r.time_step, seconds,
      compare ? fmt::format("; steady state for the comparison ({}) in {:.2f} s",
                            ref.full_law ? fmt::format("nonlinear balance, {} harmonics: the "
                                                       "full bearing law",
                                                       ref.base_harmonics)
                            : torus      ? std::string("torus")
                                         : fmt::format("{} base harmonics", ref.base_harmonics),
                            steady_seconds)
              : std::string());
  writeTrainProbes(model, analysis, speed, r, compare && !torus ? &s : nullptr, result, text);
  record = r;
  return 0;
}

}  // namespace geardyn::analysis::detail

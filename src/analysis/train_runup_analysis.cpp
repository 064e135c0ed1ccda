/// `train` analysis `runup`: any gear train along a linear input-speed ramp (train_runup.h), its
/// order tracks against the input angle and a waterfall (train_runup_analysis.h).

#include "train_runup_analysis.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

#include "geardyn/analysis/run_budget.h"
#include "geardyn/analysis/run_estimates.h"
#include "geardyn/config/train_analysis.h"
#include "geardyn/error.h"
#include "geardyn/signal/order_analysis.h"
#include "geardyn/solvers/train_response.h"
#include "geardyn/solvers/train_runup.h"
#include "geardyn/units.h"

namespace geardyn::analysis::detail {
namespace {

using geardyn::units::kRpm;
using Json = nlohmann::ordered_json;
constexpr double kTwoPi = 2.0 * std::numbers::pi;
// The waterfall shows up to this factor above the highest tracked mesh harmonic at top speed.
constexpr double kWaterfallHeadroom = 1.2;
// The ramp's (unapplied) inertial torque above this fraction of the input torque is reported.
constexpr double kInertiaTorqueWarning = 0.05;

/// What is tracked: a mesh's dynamic force [N] or a DOF's displacement [m, rad].
struct Channel {
  std::string name;
  const char* unit;  // a literal: "N", "m" or "rad"
  int mesh = -1, dof = -1;
};

std::vector<Channel> channelsFromConfig(const GearTrainModel& model,
                                        const config::Config& analysis) {
  std::vector<Channel> channels;
  std::vector<std::string> names = analysis.stringList("runup.channels");
  if (names.empty()) {
    for (const TrainMesh& m : model.meshes()) names.push_back(m.name);
  }
  for (const std::string& name : names) {
    Channel c{name, "", -1, -1};
    for (std::size_t m = 0; m < model.meshes().size(); ++m) {
      if (model.meshes()[m].name == name) c.mesh = static_cast<int>(m), c.unit = "N";
    }
    for (int i = 0; i < model.dofCount() && c.mesh < 0; ++i) {
      if (model.dofName(i) == name) {
        c.dof = i;
        const std::string kind = name.substr(name.rfind('.') + 1);
        c.unit = kind == "y" || kind == "z" || kind == "x" ? "m" : "rad";
      }
    }
    if (c.mesh < 0 && c.dof < 0) {
      std::string meshes;
      for (const TrainMesh& m : model.meshes()) meshes += (meshes.empty() ? "" : ", ") + m.name;
      throw InputError("runup.channels", name,
                       fmt::format("a mesh name ({}) or a DOF name such as {} (mode_shapes.csv)",
                                   meshes, model.dofName(0)));
    }
    channels.push_back(c);
  }
  return channels;
}

/// The tracked orders of the input speed: the input's 1× and harmonics 1..L of every mesh;
/// `order` per column name, `unique` the distinct orders the fit uses, `column_order` the index
/// of each column's order in `unique`.
struct Orders {
  std::vector<std::string> column;
  std::vector<double> order, unique;
  std::vector<int> column_order;
  std::vector<int> mesh;  ///< the mesh of a column (−1: the input's 1×)
};

Orders trackedOrders(const GearTrainModel& model, int harmonics) {
  Orders o;
  const std::string input = model.spec().operating.input_shaft;
  o.column.push_back("amplitude_1x_" + input);
  o.order.push_back(1.0);
  o.mesh.push_back(-1);
  for (int l = 1; l <= harmonics; ++l) {
    for (std::size_t m = 0; m < model.meshes().size(); ++m) {
      o.column.push_back(fmt::format("amplitude_{}x_mesh_{}", l, model.meshes()[m].name));
      o.order.push_back(l * model.meshes()[m].frequency_ratio * kTwoPi);  // per input turn
      o.mesh.push_back(static_cast<int>(m));
    }
  }
  for (double order : o.order) {
    int index = -1;
    for (std::size_t u = 0; u < o.unique.size(); ++u) {
      if (std::abs(o.unique[u] - order) <= 1e-9 * order) index = static_cast<int>(u);
    }
    if (index < 0) {
      index = static_cast<int>(o.unique.size());
      o.unique.push_back(order);
    }
    o.column_order.push_back(index);
  }
  return o;
}

/// runup.csv (one row per channel and window) and the largest window of every mesh order per
/// channel: {channel: {order: {speed_rpm, amplitude, unit}}}.
Json addOrderTracks(const std::vector<Channel>& channels, const Orders& orders,
                    const std::vector<OrderTrack>& tracks, AnalysisResult& result) {
  std::vector<std::string> header{"channel", "unit", "t_s", "speed_rpm"};
  header.insert(header.end(), orders.column.begin(), orders.column.end());
  io::CsvTable table(header);
  Json peaks = Json::object();
  for (std::size_t c = 0; c < channels.size(); ++c) {
    const OrderTrack& track = tracks[c];
    std::vector<double> best(orders.column.size(), -1.0), best_speed(orders.column.size(), 0.0);
    for (std::size_t w = 0; w < track.time.size(); ++w) {
      std::vector<io::CsvCell> row{channels[c].name, std::string(channels[c].unit), track.time[w],
                                   track.speed[w] / kRpm};
      for (std::size_t j = 0; j < orders.column.size(); ++j) {
        const double a = track.amplitude[orders.column_order[j]][w];
        row.push_back(a);
        if (a > best[j]) best[j] = a, best_speed[j] = track.speed[w];
      }
      table.addRow(row);
    }
    Json per_order = Json::object();
    for (std::size_t j = 0; j < orders.column.size(); ++j) {
      if (orders.mesh[j] < 0) continue;  // the 1×: no excitation in the model to peak
      per_order[orders.column[j].substr(std::string("amplitude_").size())] = {
          {"speed_rpm", best_speed[j] / kRpm}, {"amplitude", best[j]}, {"unit", channels[c].unit}};
    }
    peaks[channels[c].name] = per_order;
  }
  result.addTable("runup.csv", table);
  return peaks;
}

void addWaterfall(const Channel& channel, const TrainRunUpResponse& r,
                  const Eigen::VectorXd& signal, int window, double fmax, AnalysisResult& result) {
  const double fs = 1.0 / r.time_step;
  io::CsvTable table({"channel", "unit", "t_s", "speed_rpm", "frequency_hz", "amplitude"});
  Eigen::VectorXd hann(window);
  for (int k = 0; k < window; ++k) hann(k) = 0.5 - 0.5 * std::cos(kTwoPi * k / window);
  const double gain = hann.mean();  // coherent gain: a sinusoid's amplitude is kept
  for (Eigen::Index start = 0; start + window <= signal.size(); start += window) {
    // Hann-windowed (the strong mesh orders leak far less), amplitudes divided by its mean.
    const Eigen::VectorXd x = signal.segment(start, window).cwiseProduct(hann);
    AmplitudeSpectrum s = amplitudeSpectrum(x, fs);
    for (double& a : s.amplitude) a /= gain;
    const double speed = r.speed.segment(start, window).cwiseAbs().mean();
    const double t = r.t(start) + 0.5 * window * r.time_step;
    // From the third bin: the mean (a mesh force's static load) is not vibration, and the
    // Hann window spreads it over bins 0 and 1.
    for (std::size_t k = 2; k < s.frequency.size() && s.frequency[k] <= fmax; ++k)
      table.addRow({channel.name, channel.unit, t, speed / kRpm, s.frequency[k], s.amplitude[k]});
  }
  result.addTable("waterfall.csv", table);
}

}  // namespace

int runTrainRunUp(const GearTrainModel& model, const config::Config& analysis,
                  AnalysisResult& result, std::string& text, const AnalysisContext& context) {
  const auto start = std::chrono::steady_clock::now();
  io::RunSummary& summary = result.summary;
  TrainRunUpOptions options = config::trainRunUpOptionsFromConfig(analysis);
  options.ramp = config::runUpRampFromConfig(analysis, model.inputSpeed());
  const std::vector<Channel> channels = channelsFromConfig(model, analysis);
  for (const Channel& c : channels) {
    if (c.dof >= 0) options.dofs.push_back(c.dof);
  }
  const int harmonics = static_cast<int>(analysis.integer("runup.mesh_harmonics"));
  const Orders orders = trackedOrders(model, harmonics);
  if (!(options.ramp.maxSpeed() > 0.0)) {
    throw InputError("runup.speed_max_rpm", "0 rpm", "a speed > 0 (no mesh frequency at rest)");
  }
  const TrainRunUpDefaults defaults = trainRunUpDefaults(
      model, options.ramp.start, options.ramp.end, harmonics,
      static_cast<int>(analysis.integer("campbell.modes")), analysis.real("runup.window"));
  const bool derived_duration = !(options.ramp.duration > 0.0);
  if (derived_duration && !std::isfinite(defaults.duration)) {
    for (const TrainRunUpResonance& x : defaults.resonances) {
      if (std::isfinite(x.sweep_duration)) continue;
      throw InputError(
          "runup.duration", "0 (derived)",
          fmt::format("a duration > 0 s: mode {} ({:.1f} Hz), crossed by the {} line at {:.1f} "
                      "rpm, is undamped, so no sweep passes it quasi-statically (add mesh or "
                      "bearing damping, or give the duration)",
                      x.mode + 1, x.frequency, x.line, x.speed / kRpm));
    }
  }
  if (derived_duration) options.ramp.duration = defaults.duration;
  const double dt = options.time_step > 0.0
                        ? options.time_step
                        : trainRunUpTimeStep(model, options.ramp, options.steps_per_mesh_period);
  const int window = static_cast<int>(std::llround(defaults.window / dt));
  if (window < 2 * static_cast<int>(orders.unique.size()) + 1 || window < 8) {
    throw InputError("runup.window", fmt::format("{:g} s", defaults.window),
                     fmt::format("at least {} time steps of {:.3g} s",
                                 std::max<int>(8, 2 * orders.unique.size() + 1), dt));
  }
  const double steps = std::ceil(options.ramp.duration / dt - 1e-9);
  const RunEstimate estimate = estimateTrainRunUp(
      steps, model.dofCount(), static_cast<int>(channels.size()),
      static_cast<int>(model.meshes().size()), "runup.duration",
      fmt::format("{:g} s{}", options.ramp.duration, derived_duration ? " (derived)" : ""));
  context.note(checkRunEstimate(estimate, "train runup"));
  if (!derived_duration && options.ramp.duration < defaults.duration) {
    summary.warnings.push_back(fmt::format(
        "runup: duration {:.3g} s is shorter than the quasi-stationary {:.3g} s the resonances "
        "in the range ask for (train_runup.h; inf: an undamped one): their peaks are lowered "
        "and moved in the sweep direction",
        options.ramp.duration, defaults.duration));
  }
  const double inertia_torque = trainRampInertiaTorque(model, options.ramp);
  const double input_torque = std::abs(model.spec().operating.input_torque);
  const double inertia_fraction = input_torque > 0.0 ? inertia_torque / input_torque : 0.0;
  if (inertia_fraction > kInertiaTorqueWarning) {
    summary.warnings.push_back(fmt::format(
        "runup: the ramp's rigid acceleration needs {:.3g} N m at the input ({:.1f} % of the "
        "operating torque), which is not applied (the rotation is kinematic, train_runup.h): "
        "lengthen runup.duration for a quasi-steady load",
        inertia_torque, 100.0 * inertia_fraction));
  }
  options.progress = context.progressFor("train: run-up", "steps");
  const TrainRunUpResponse r = solveTrainRunUp(model, options);
  if (r.status != "completed") {
    summary.warnings.push_back(r.message);
    summary.results["runup"] = {{"status", r.status}, {"steps", r.steps}};
    return 1;
  }
  // Signals: mesh forces and displacements, one column per channel.
  Eigen::MatrixXd signals(r.t.size(), static_cast<Eigen::Index>(channels.size()));
  for (std::size_t c = 0, d = 0; c < channels.size(); ++c) {
    signals.col(static_cast<Eigen::Index>(c)) =
        channels[c].mesh >= 0 ? r.mesh_force.col(channels[c].mesh)
                              : r.displacement.col(static_cast<Eigen::Index>(d++));
  }
  const std::vector<double> speed(r.speed.cwiseAbs().begin(), r.speed.cwiseAbs().end());
  // Windows cut to whole common periods of the meshes (in input angle: 1 / (f₀/|Ω|) rad), so
  // that no harmonic of the train leaks into the tracked orders.
  const double common_period = 1.0 / trainBaseFrequency(model, 1, 1000000000).ratio;
  const std::vector<OrderTrack> tracks = trackOrdersByAngle(
      signals, 1.0 / r.time_step, r.angle, speed, orders.unique, window, common_period);
  const Json peaks = addOrderTracks(channels, orders, tracks, result);
  double fmax = 0.0;
  for (const TrainMesh& m : model.meshes())
    fmax = std::max(fmax, harmonics * m.frequency_ratio * options.ramp.maxSpeed());
  fmax = std::min(kWaterfallHeadroom * fmax, 0.5 / r.time_step);
  addWaterfall(channels.front(), r, signals.col(0), window, fmax, result);
  io::CsvTable lines({"line", "order", "hz_per_rpm"});
  for (std::size_t j = 0; j < orders.column.size(); ++j) {
    lines.addRow({orders.column[j].substr(std::string("amplitude_").size()), orders.order[j],
                  orders.order[j] / kTwoPi * kRpm});
  }
  result.addTable("runup_orders.csv", lines);
  Json resonances = Json::array();
  for (const TrainRunUpResonance& x : defaults.resonances) {
    resonances.push_back({{"mode", x.mode + 1},
                          {"line", x.line},
                          {"speed_rpm", x.speed / kRpm},
                          {"frequency_hz", x.frequency},
                          {"damping_ratio", x.damping_ratio},
                          {"quasi_static_duration_s",
                           std::isfinite(x.sweep_duration) ? Json(x.sweep_duration) : Json()}});
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  summary.results["runup"] = {{"status", r.status},
                              {"speed_start_rpm", options.ramp.start / kRpm},
                              {"speed_end_rpm", options.ramp.end / kRpm},
                              {"start", r.start},
                              {"duration_s", options.ramp.duration},
                              {"duration_derived", derived_duration},
                              {"quasi_static_duration_s",
                               std::isfinite(defaults.duration) ? Json(defaults.duration) : Json()},
                              {"sweep_rate_rpm_per_s", (options.ramp.end - options.ramp.start) /
                                                           options.ramp.duration / kRpm},
                              {"window_s", window * r.time_step},
                              {"windows", tracks.front().time.size()},
                              {"time_step_s", r.time_step},
                              {"steps", r.steps},
                              {"factorisations", r.factorisations},
                              {"speed_tolerance", options.speed_tolerance},
                              {"ramp_inertia_torque_n_m", inertia_torque},
                              {"ramp_inertia_torque_fraction", inertia_fraction},
                              {"mesh_order_peaks", peaks},
                              {"campbell_resonances", resonances},
                              {"wall_time_s", seconds}};
  const Channel& first = channels.front();
  double top = -1.0, top_speed = 0.0;
  std::string top_order;
  for (const auto& [order, peak] : peaks[first.name].items()) {
    if (peak["amplitude"].get<double>() > top) {
      top = peak["amplitude"].get<double>();
      top_speed = peak["speed_rpm"].get<double>();
      top_order = order;
    }
  }
  text += fmt::format(
      "run-up {:.0f} -> {:.0f} rpm in {:.3g} s ({} steps, {} factorisation(s)): largest "
      "mesh-order response of {} is {} {:.4g} {} at {:.0f} rpm; {} resonance(s) in range\n",
      options.ramp.start / kRpm, options.ramp.end / kRpm, options.ramp.duration, r.steps,
      r.factorisations, first.name, top_order, top, first.unit, top_speed,
      defaults.resonances.size());
  return 0;
}

}  // namespace geardyn::analysis::detail

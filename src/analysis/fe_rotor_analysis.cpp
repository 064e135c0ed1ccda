/// `rotor` with [model] type = "fe_geared_rotor": the finite-element two-shaft
/// geared rotor of Visnadi & de Castro (2021) — time response (constant speed or run-up), modal
/// analysis, Campbell diagram and the comparison of mesh-stiffness models (Figs. 3–7).

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <complex>
#include <exception>
#include <memory>
#include <numbers>
#include <thread>

#include "geardyn/analysis/analyses.h"
#include "geardyn/analysis/fe_rotor_modes.h"
#include "geardyn/config/fe_rotor_config.h"
#include "geardyn/config/geometry_config.h"
#include "geardyn/error.h"
#include "geardyn/signal/order_analysis.h"
#include "geardyn/stiffness/mesh_stiffness_summary.h"
#include "geardyn/units.h"

namespace geardyn::analysis {
namespace {

constexpr int kOk = 0, kFailed = 1;  // what each analysis type returns
constexpr double kTwoPi = 2.0 * std::numbers::pi;
using geardyn::units::kRpm;

/// The steady-state window of a constant-speed response: harmonics at the mesh orders and the
/// amplitude spectra of every channel (displacement and acceleration).
struct SteadyAnalysis {
  std::vector<double> orders, frequencies;
  std::vector<std::vector<double>> displacement, acceleration;  // [channel][order]
  std::vector<AmplitudeSpectrum> displacement_spectrum, acceleration_spectrum;
  double window = 0.0;       // [s]
  double last_change = 0.0;  // max |q(t) − q(t − T_m)| / max |q| over the last mesh period
};

SteadyAnalysis analyseSteady(const config::Config& config, const FeRotorModel& model,
                             const FeTimeResponse& r) {
  SteadyAnalysis a;
  const double dt = config.real("time.time_step"), fs = 1.0 / dt;
  const double f_mesh = model.speed().start * model.pinionTeeth() / kTwoPi;
  const int harmonics = static_cast<int>(config.integer("time.harmonics"));
  for (int h = 1; h <= harmonics && h * f_mesh < fs / 2; ++h) {
    a.orders.push_back(h);
    a.frequencies.push_back(h * f_mesh);
  }
  const long long period = std::llround(1.0 / (f_mesh * dt));
  long long n = std::llround(config.integer("time.window_mesh_periods") / (f_mesh * dt));
  n = std::min<long long>(n, static_cast<long long>(r.t.size()) - 1);
  a.window = n * dt;
  const long long first = static_cast<long long>(r.t.size()) - n;
  double change = 0.0, scale = 0.0;
  // One least-squares design for every channel, displacement and acceleration together.
  const Eigen::Index channels = r.displacement.cols();
  Eigen::MatrixXd window(n, 2 * channels);
  window << r.displacement.middleRows(first, n), r.acceleration.middleRows(first, n);
  const auto amplitudes = harmonicAmplitudesPerColumn(window, fs, a.frequencies);
  a.displacement.assign(amplitudes.begin(), amplitudes.begin() + channels);
  a.acceleration.assign(amplitudes.begin() + channels, amplitudes.end());
  for (Eigen::Index c = 0; c < channels; ++c) {
    const Eigen::VectorXd q = window.col(c);
    const Eigen::VectorXd acc = window.col(channels + c);
    a.displacement_spectrum.push_back(amplitudeSpectrum(q, fs));
    a.acceleration_spectrum.push_back(amplitudeSpectrum(acc, fs));
    if (n > period) {
      for (long long k = n - period; k < n; ++k) {
        change = std::max(change, std::abs(q(k) - q(k - period)));
        scale = std::max(scale, std::abs(q(k)));
      }
    }
  }
  a.last_change = scale > 0.0 ? change / scale : 0.0;
  return a;
}

double spectrumLimit(const config::Config& config, const SteadyAnalysis& a) {
  return config.has("time.spectrum_max_frequency") ? config.real("time.spectrum_max_frequency")
         : a.frequencies.empty()                   ? 1e3
                                                   : 1.25 * a.frequencies.back();
}

/// The unit of a DOF's displacement: "rad" for the rotations (…rx, …ry, …rz), else "m".
std::string dofUnit(const std::string& name) {
  const auto dot = name.rfind('.');
  return name.compare(dot == std::string::npos ? 0 : dot + 1, 1, "r") == 0 ? "rad" : "m";
}

std::vector<std::string> channelNames(const FeRotorModel& model, const FeTimeResponse& r) {
  std::vector<std::string> names;
  for (int c : r.channels) names.push_back(model.dofName(c));
  return names;
}

nlohmann::ordered_json modelJson(const FeRotorModel& model, const std::string& stiffness) {
  const GearTrainSpec& s = model.train().spec();
  double mass = 0.0;
  for (const TrainShaftSpec& shaft : s.shafts)
    for (std::size_t e = 0; e < shaft.section_lengths.size(); ++e)
      mass += shaft.density * std::numbers::pi / 4.0 * shaft.section_lengths[e] *
              (std::pow(shaft.outer_diameters[e], 2) - std::pow(shaft.inner_diameters[e], 2));
  for (const TrainDiskSpec& d : s.disks) mass += d.mass;
  const TrainMesh& mesh = model.train().meshes().front();
  return {
      {"type", "fe_geared_rotor"},
      {"dofs", model.dofCount()},
      {"nodes", {model.nodeCount(0), model.nodeCount(1)}},
      {"mass_kg", mass},
      {"mesh_stiffness_model", stiffness},
      {"mean_mesh_stiffness_n_per_m", model.meanMeshStiffness()},
      {"line_of_action_angle_deg", model.layout().line_of_action_angle * 180.0 / std::numbers::pi},
      // β_b < 0 for a right-hand pinion (feRotorFromConfig)
      {"base_helix_angle_deg",
       -std::copysign(std::abs(mesh.base_helix_angle), s.gears.front().gear.helix_angle) * 180.0 /
           std::numbers::pi},
      {"pinion_base_radius_m", mesh.base_radius_a},
      {"gear_base_radius_m", mesh.base_radius_b},
      {"nominal_mesh_force_n", model.nominalMeshForce()},
      {"gear_speed_ratio", model.spinRatio(1)},
      {"mesh_frequency_hz", model.speed().start * model.pinionTeeth() / kTwoPi}};
}

io::CsvTable timeHistoryTable(const FeRotorModel& model, const FeTimeResponse& r, int every) {
  // The mesh acts along the contact normal (docs/theory/mesh_stiffness.md, "Which plane").
  std::vector<std::string> columns{"t_s", "speed_rpm", "mesh_stiffness_normal_n_per_m",
                                   "mesh_force_normal_n"};
  for (const auto& name : channelNames(model, r)) {
    const std::string u = dofUnit(name);
    columns.push_back(name + "_" + u);
    columns.push_back(name + "_vel_" + u + "_per_s");
    columns.push_back(name + "_acc_" + u + "_per_s2");
  }
  io::CsvTable table(columns);
  for (std::size_t k = 0; k < r.t.size(); k += every) {
    std::vector<io::CsvCell> row{r.t[k], r.speed[k] / kRpm, r.mesh_stiffness[k], r.mesh_force[k]};
    for (int c = 0; c < r.displacement.cols(); ++c) {
      row.push_back(r.displacement(k, c));
      row.push_back(r.velocity(k, c));
      row.push_back(r.acceleration(k, c));
    }
    table.addRow(row);
  }
  return table;
}

void addHarmonicRows(io::CsvTable& table, const std::string& model_name,
                     const std::vector<std::string>& names, const SteadyAnalysis& a) {
  for (std::size_t c = 0; c < names.size(); ++c) {
    for (std::size_t h = 0; h < a.orders.size(); ++h) {
      std::vector<io::CsvCell> row;
      if (!model_name.empty()) row.push_back(model_name);
      row.insert(row.end(), {names[c], dofUnit(names[c]), a.orders[h], a.frequencies[h],
                             a.displacement[c][h], a.acceleration[c][h]});
      table.addRow(row);
    }
  }
}

void addSpectrumRows(io::CsvTable& table, const std::string& model_name,
                     const std::vector<std::string>& names, const SteadyAnalysis& a, double fmax) {
  for (std::size_t c = 0; c < names.size(); ++c) {
    const auto& d = a.displacement_spectrum[c];
    for (std::size_t k = 0; k < d.frequency.size() && d.frequency[k] <= fmax; ++k) {
      std::vector<io::CsvCell> row;
      if (!model_name.empty()) row.push_back(model_name);
      row.insert(row.end(), {names[c], dofUnit(names[c]), d.frequency[k], d.amplitude[k],
                             a.acceleration_spectrum[c].amplitude[k]});
      table.addRow(row);
    }
  }
}

nlohmann::ordered_json harmonicsJson(const std::vector<std::string>& names,
                                     const SteadyAnalysis& a) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (std::size_t c = 0; c < names.size(); ++c) {
    j[names[c]] = {{"displacement", a.displacement[c]}, {"acceleration", a.acceleration[c]}};
  }
  return j;
}

void reportDivergence(const FeTimeResponse& r, std::vector<std::string>& warnings) {
  if (!r.converged()) {
    warnings.push_back("Newmark: " + r.message);
  }
}

/// The run-up: order tracking of the mesh order and 1× in windows, a waterfall of the first
/// channel's acceleration, the speed of the largest mesh-order response per channel, and the
/// Campbell crossings of the mesh line within the speed range.
void runUpOutputs(const config::Config& config, const FeRotorModel& model, const FeTimeResponse& r,
                  AnalysisResult& result, nlohmann::ordered_json& results, std::string& text) {
  const double dt = config.real("time.time_step"), fs = 1.0 / dt;
  const int window = static_cast<int>(std::llround(config.real("time.runup_window") / dt));
  const std::vector<double> orders{static_cast<double>(model.pinionTeeth()), 1.0};
  const auto names = channelNames(model, r);
  io::CsvTable track_table({"channel", "unit", "t_s", "speed_rpm", "mesh_order_displacement",
                            "mesh_order_acceleration", "x1_displacement"});
  nlohmann::ordered_json peaks = nlohmann::ordered_json::object();
  const Eigen::Index channels = r.displacement.cols();
  Eigen::MatrixXd signals(r.displacement.rows(), 2 * channels);
  signals << r.displacement, r.acceleration;
  const std::vector<OrderTrack> tracks = trackOrdersPerColumn(signals, fs, r.speed, orders, window);
  for (std::size_t c = 0; c < names.size(); ++c) {
    const OrderTrack& disp = tracks[c];
    const OrderTrack& acc = tracks[channels + c];
    double best = -1.0, best_speed = 0.0;
    for (std::size_t w = 0; w < disp.time.size(); ++w) {
      track_table.addRow({names[c], dofUnit(names[c]), disp.time[w], disp.speed[w] / kRpm,
                          disp.amplitude[0][w], acc.amplitude[0][w], disp.amplitude[1][w]});
      if (acc.amplitude[0][w] > best) best = acc.amplitude[0][w], best_speed = acc.speed[w];
    }
    peaks[names[c]] = {{"speed_rpm", best_speed / kRpm}, {"mesh_order_acceleration", best}};
  }
  result.addTable("runup.csv", track_table);
  // Waterfall of the first channel's acceleration.
  // The first channel's acceleration [m/s² or rad/s², the unit column].
  io::CsvTable waterfall({"unit", "t_s", "speed_rpm", "frequency_hz", "amplitude"});
  const std::string waterfall_unit = dofUnit(names.front()) + "/s^2";
  const double fmax = config.has("time.spectrum_max_frequency")
                          ? config.real("time.spectrum_max_frequency")
                          : 1.25 * model.speed().maxSpeed() * orders[0] / kTwoPi;
  for (Eigen::Index start = 0; start + window <= r.acceleration.rows(); start += window) {
    const AmplitudeSpectrum s = amplitudeSpectrum(r.acceleration.col(0).segment(start, window), fs);
    double speed = 0.0;
    for (int k = 0; k < window; ++k) speed += r.speed[start + k] / window;
    for (std::size_t k = 0; k < s.frequency.size() && s.frequency[k] <= fmax; ++k)
      waterfall.addRow({waterfall_unit, r.t[start] + 0.5 * window * dt, speed / kRpm,
                        s.frequency[k], s.amplitude[k]});
  }
  result.addTable("waterfall.csv", waterfall);
  // Where the Campbell diagram puts the mesh-line crossings inside the ramp.
  const auto& p = model.speed();
  const double lo = std::min(p.start, p.end), hi = std::max(p.start, p.end);
  std::vector<double> speeds;
  for (int i = 0; i <= 40; ++i) speeds.push_back(lo + (hi - lo) * i / 40.0);
  nlohmann::ordered_json predicted = nlohmann::ordered_json::array();
  if (hi > lo) {
    std::vector<std::string> notes;  // the time run has reported the file's warnings
    const FeRotorTrain train = feRotorTrain(config, model, notes);
    const TrainCampbell d =
        feRotorCampbell(train, model, speeds, static_cast<int>(config.integer("campbell.modes")),
                        config.real("modal.max_damping_ratio"));
    for (const auto& cs : d.critical_speeds) {
      if (cs.line != "mesh") continue;
      predicted.push_back({{"mode", cs.mode},
                           {"speed_rpm", cs.speed / kRpm},
                           {"frequency_hz", cs.frequency},
                           {"whirl", cs.whirl}});
    }
  }
  results["runup"] = {{"window_s", window * dt},
                      {"mesh_order_peaks", peaks},
                      {"campbell_mesh_crossings", predicted}};
  text += fmt::format(
      "  run-up {:.0f} -> {:.0f} rpm: largest mesh-order response of {} at {:.0f} "
      "rpm; {} Campbell crossing(s) of the mesh line in range\n",
      p.start / kRpm, p.end / kRpm, names[0], peaks[names[0]]["speed_rpm"].get<double>(),
      predicted.size());
}

/// ζ for people: round-off of an undamped mode (|ζ| < 1e-10, the eigensolver's accuracy on
/// ζ = −Re λ / |λ|) is 0, not "-0.0000"; a small real ζ keeps its sign and digits.
std::string dampingRatioText(double zeta) {
  if (std::abs(zeta) < 1e-10) return "0.0000";
  return std::abs(zeta) < 5e-5 ? fmt::format("{:.1e}", zeta) : fmt::format("{:.4f}", zeta);
}

int runTime(const config::Config& config, const AnalysisContext& context, io::RunSummary& summary,
            AnalysisResult& result, std::string& text) {
  config::FeRotorBuild build = config::feRotorFromConfig(config);
  summary.warnings.insert(summary.warnings.end(), build.warnings.begin(), build.warnings.end());
  const FeRotorModel model(std::move(build.train), std::move(build.layout));
  context.checkBudget("rotor_fe_time", model.dofCount());
  FeTimeOptions o = config::feTimeOptionsFromConfig(config, model);
  o.progress = context.progressFor("rotor: Newmark", "steps");
  const FeTimeResponse r = solveFeRotorTimeResponse(model, o);
  reportDivergence(r, summary.warnings);
  summary.results["model"] = modelJson(model, build.stiffness_model);
  summary.results["time"] = {{"status", toString(r.status)},
                             {"steps", r.steps},
                             {"factorisations", r.factorisations},
                             {"message", r.message}};
  result.addTable(
      "time_history.csv",
      timeHistoryTable(model, r, static_cast<int>(config.integer("time.output_every"))));
  text += fmt::format("  {}\n", r.message);
  if (!r.converged()) return kFailed;
  const auto names = channelNames(model, r);
  if (model.speed().constant() && model.speed().start == 0.0) {
    summary.results["steady"] = nullptr;  // at rest: no mesh period, no harmonics
    text += "  at rest (speed.speed_rpm = 0): no mesh harmonics\n";
  } else if (model.speed().constant()) {
    const SteadyAnalysis a = analyseSteady(config, model, r);
    // unit: of the channel's displacement (m or rad); its acceleration is in unit/s².
    io::CsvTable harmonics(
        {"channel", "unit", "order", "frequency_hz", "displacement", "acceleration"});
    addHarmonicRows(harmonics, "", names, a);
    result.addTable("harmonics.csv", harmonics);
    io::CsvTable spectrum({"channel", "unit", "frequency_hz", "displacement", "acceleration"});
    addSpectrumRows(spectrum, "", names, a, spectrumLimit(config, a));
    result.addTable("spectrum.csv", spectrum);
    summary.results["steady"] = {{"window_s", a.window},
                                 {"last_period_change", a.last_change},
                                 {"mesh_orders", a.orders},
                                 {"harmonics", harmonicsJson(names, a)}};
    // With unbalance the response repeats with the shaft revolutions, not the mesh period.
    if (a.last_change > 1e-3 && !model.hasUnbalance()) {
      summary.warnings.push_back(fmt::format(
          "the response still changes by {:.2g} of its size between the last two mesh periods: "
          "lengthen time.duration for a steady window",
          a.last_change));
    }
    text += fmt::format(
        "  steady window {:.3g} s (relative change over the last mesh period {:.2g} [-]); {} "
        "channels: "
        "mesh-order 1..{} amplitudes in harmonics.csv\n",
        a.window, a.last_change, names.size(), a.orders.size());
  } else {
    runUpOutputs(config, model, r, result, summary.results, text);
  }
  return kOk;
}

nlohmann::ordered_json modeJson(const TrainMode& m) {
  return {{"frequency_hz", m.frequency},
          {"damping_ratio", m.damping_ratio},
          {"whirl", m.whirl},
          {"forward_fraction", m.forward_fraction},
          {"lateral_fraction", m.lateral_fraction},
          {"torsional_fraction", m.torsional_fraction},
          {"axial_fraction", m.axial_fraction}};
}

/// The model and its train (the file's gearbox).
struct FeRotorModels {
  config::FeRotorBuild build;
  std::unique_ptr<FeRotorModel> model;
  FeRotorTrain train;
};

FeRotorModels buildModels(const config::Config& config, io::RunSummary& summary) {
  FeRotorModels m;
  m.build = config::feRotorFromConfig(config);
  summary.warnings.insert(summary.warnings.end(), m.build.warnings.begin(), m.build.warnings.end());
  m.model = std::make_unique<FeRotorModel>(m.build.train, m.build.layout);
  // The gearbox reader's warnings are about the same gears and mesh-stiffness model, which the
  // file's own build has just reported in the file's keys.
  std::vector<std::string> same_warnings;
  m.train = feRotorTrain(config, *m.model, same_warnings);
  return m;
}

/// The modes at one speed, from the train's modal solver on the file's gearbox.
int runFeRotorModal(const config::Config& config, io::RunSummary& summary, AnalysisResult& result,
                    std::string& text) {
  const FeRotorModels models = buildModels(config, summary);
  const FeRotorModel& model = *models.model;
  const double speed = (config.has("modal.speed_rpm") ? config.real("modal.speed_rpm")
                                                      : config.real("speed.speed_rpm")) *
                       kRpm;
  const auto modes =
      feRotorModes(models.train, speed, static_cast<int>(config.integer("modal.modes")),
                   config.real("modal.max_damping_ratio"));
  io::CsvTable table({"mode", "frequency_hz", "damping_ratio", "whirl", "forward_fraction",
                      "lateral_fraction", "torsional_fraction", "axial_fraction"});
  io::CsvTable shapes({"mode", "dof", "re", "im", "amplitude"});
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (std::size_t j = 0; j < modes.size(); ++j) {
    const TrainMode& m = modes[j];
    table.addRow({static_cast<long long>(j + 1), m.frequency, m.damping_ratio, m.whirl,
                  m.forward_fraction, m.lateral_fraction, m.torsional_fraction, m.axial_fraction});
    for (int i = 0; i < model.dofCount(); ++i) {
      const std::complex<double> x = m.shape(models.train.train_dof[i]);
      shapes.addRow(
          {static_cast<long long>(j + 1), model.dofName(i), x.real(), x.imag(), std::abs(x)});
    }
    list.push_back(modeJson(m));
    text += fmt::format("  mode {:2d}: {:9.2f} Hz  zeta {} [-]  {}\n", j + 1, m.frequency,
                        dampingRatioText(m.damping_ratio), m.whirl);
  }
  result.addTable("modes.csv", table);
  result.addTable("mode_shapes.csv", shapes);
  summary.results["model"] = modelJson(model, models.build.stiffness_model);
  summary.results["modal"] = {
      {"speed_rpm", speed / kRpm}, {"solver", "train_modal (the file's gearbox)"}, {"modes", list}};
  return kOk;
}

int runFeRotorCampbell(const config::Config& config, io::RunSummary& summary,
                       AnalysisResult& result, std::string& text) {
  const FeRotorModels models = buildModels(config, summary);
  const FeRotorModel& model = *models.model;
  const auto speeds = config::campbellSpeedsFromConfig(config);
  const TrainCampbell d = feRotorCampbell(models.train, model, speeds,
                                          static_cast<int>(config.integer("campbell.modes")),
                                          config.real("modal.max_damping_ratio"));
  io::CsvTable table(
      {"speed_rpm", "mode", "frequency_hz", "damping_ratio", "whirl", "forward_fraction"});
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    for (std::size_t j = 0; j < d.modes[i].size(); ++j) {
      const TrainMode& m = d.modes[i][j];
      table.addRow({speeds[i] / kRpm, static_cast<long long>(j + 1), m.frequency, m.damping_ratio,
                    m.whirl, m.forward_fraction});
    }
  }
  result.addTable("campbell.csv", table);
  // The order of a line: its slope [Hz per rad/s] × 2π, multiples of the pinion speed.
  io::CsvTable lines({"line", "order"});
  for (const auto& l : d.lines) lines.addRow({l.name, l.slope * kTwoPi});
  result.addTable("campbell_lines.csv", lines);
  io::CsvTable critical({"mode", "line", "speed_rpm", "frequency_hz", "whirl"});
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const auto& c : d.critical_speeds) {
    critical.addRow(
        {static_cast<long long>(c.mode + 1), c.line, c.speed / kRpm, c.frequency, c.whirl});
    list.push_back({{"mode", c.mode + 1},
                    {"line", c.line},
                    {"speed_rpm", c.speed / kRpm},
                    {"frequency_hz", c.frequency},
                    {"whirl", c.whirl}});
  }
  result.addTable("critical_speeds.csv", critical);
  summary.results["model"] = modelJson(model, models.build.stiffness_model);
  summary.results["campbell"] = {{"speeds_rpm", {speeds.front() / kRpm, speeds.back() / kRpm}},
                                 {"points", speeds.size()},
                                 {"solver", "train_modal (the file's gearbox)"},
                                 {"critical_speeds", list}};
  text += fmt::format("  {} modes tracked over {:.0f}-{:.0f} rpm; {} critical speed(s)\n",
                      d.modes.front().size(), speeds.front() / kRpm, speeds.back() / kRpm,
                      d.critical_speeds.size());
  for (const auto& c : d.critical_speeds)
    text += fmt::format("    mode {} x {}: {:.1f} rpm ({:.1f} Hz, {})\n", c.mode + 1, c.line,
                        c.speed / kRpm, c.frequency, c.whirl);
  return kOk;
}

/// Visnadi §4: the same rotor with each mesh-stiffness model; amplitudes at the mesh orders.
int runCompare(const config::Config& config, const AnalysisContext& context,
               io::RunSummary& summary, AnalysisResult& result, std::string& text) {
  const auto models = config.stringList("compare.models");
  if (models.empty()) throw InputError("compare.models", "[]", "at least one model");
  struct Case {
    std::string name;
    std::unique_ptr<FeRotorModel> model;
    FeTimeResponse response;
    double mean = 0.0;
    std::vector<std::string> warnings;
  };
  std::vector<Case> cases;
  for (const auto& name : models) {
    config::FeRotorBuild build = config::feRotorFromConfig(config, name);
    Case c{name,
           std::make_unique<FeRotorModel>(std::move(build.train), std::move(build.layout)),
           {},
           0.0,
           build.warnings};
    c.mean = c.model->meanMeshStiffness();
    cases.push_back(std::move(c));
  }
  if (!cases.front().model->speed().constant()) {
    throw InputError("speed.end_speed_rpm", "",
                     "compare_stiffness runs at constant speed (no end_speed_rpm)");
  }
  if (!(cases.front().model->speed().start > 0.0)) {
    throw InputError("speed.speed_rpm", "0 rpm",
                     "a speed > 0 rpm: the comparison is of mesh harmonics");
  }
  // The cases are independent: run them on the worker threads (options are read first, so that
  // configuration errors surface here, on the main thread).
  std::vector<FeTimeOptions> time_options;
  for (const Case& c : cases)
    time_options.push_back(config::feTimeOptionsFromConfig(config, *c.model));
  const unsigned threads =
      context.threads > 0 ? context.threads : std::max(1u, std::thread::hardware_concurrency());
  std::vector<std::thread> pool;
  std::atomic<std::size_t> next{0};
  std::vector<std::exception_ptr> errors(cases.size());
  for (unsigned t = 0; t < std::min<std::size_t>(threads, cases.size()); ++t) {
    pool.emplace_back([&] {
      for (std::size_t i; (i = next++) < cases.size();) {
        try {
          cases[i].response = solveFeRotorTimeResponse(*cases[i].model, time_options[i]);
        } catch (...) {
          errors[i] = std::current_exception();
        }
      }
    });
  }
  for (auto& t : pool) t.join();
  for (const auto& e : errors)
    if (e) std::rethrow_exception(e);

  io::CsvTable harmonics(
      {"model", "channel", "unit", "order", "frequency_hz", "displacement", "acceleration"});
  io::CsvTable spectra(
      {"model", "channel", "unit", "frequency_hz", "displacement", "acceleration"});
  io::CsvTable stiffness({"model", "mesh_fraction", "stiffness_normal_n_per_m"});
  nlohmann::ordered_json per_model = nlohmann::ordered_json::object();
  std::vector<SteadyAnalysis> analyses;
  bool ok = true;
  for (Case& c : cases) {
    summary.warnings.insert(summary.warnings.end(), c.warnings.begin(), c.warnings.end());
    reportDivergence(c.response, summary.warnings);
    if (!c.response.converged()) {
      ok = false;
      analyses.emplace_back();
      continue;
    }
    const auto names = channelNames(*c.model, c.response);
    const SteadyAnalysis a = analyseSteady(config, *c.model, c.response);
    addHarmonicRows(harmonics, c.name, names, a);
    addSpectrumRows(spectra, c.name, names, a, spectrumLimit(config, a));
    for (int k = 0; k <= 200; ++k)
      stiffness.addRow({c.name, k / 200.0, c.model->meshStiffness(k / 200.0)});
    const MeshStiffnessSummary s =
        summarizeMeshStiffness(*c.model->train().meshes().front().stiffness, 1);
    per_model[c.name] = {{"mean_stiffness_n_per_m", c.mean},
                         {"min_stiffness_n_per_m", s.min},
                         {"max_stiffness_n_per_m", s.max},
                         {"last_period_change", a.last_change},
                         {"harmonics", harmonicsJson(names, a)}};
    analyses.push_back(a);
  }
  result.addTable("compare_harmonics.csv", harmonics);
  result.addTable("compare_spectra.csv", spectra);
  result.addTable("compare_stiffness.csv", stiffness);

  // Ratios to the reference model, per channel and order (acceleration: the bearing plots).
  const std::string reference = config.string("compare.reference");
  const auto ref_it = std::find(models.begin(), models.end(), reference);
  io::CsvTable ratios({"model", "channel", "order", "displacement_ratio", "acceleration_ratio"});
  nlohmann::ordered_json ratio_json = nlohmann::ordered_json::object();
  if (ref_it != models.end() && ok) {
    const std::size_t r = ref_it - models.begin();
    const auto names = channelNames(*cases[r].model, cases[r].response);
    for (std::size_t m = 0; m < cases.size(); ++m) {
      if (m == r) continue;
      double below = 0, above = 0, total = 0;
      for (std::size_t c = 0; c < names.size(); ++c) {
        for (std::size_t h = 0; h < analyses[r].orders.size(); ++h) {
          const double d = analyses[m].displacement[c][h] / analyses[r].displacement[c][h];
          const double acc = analyses[m].acceleration[c][h] / analyses[r].acceleration[c][h];
          ratios.addRow({cases[m].name, names[c], analyses[r].orders[h], d, acc});
          ++total;
          below += acc < 1.0;
          above += acc > 1.0;
        }
      }
      ratio_json[cases[m].name] = {{"share_of_peaks_above_reference", above / total},
                                   {"share_of_peaks_below_reference", below / total}};
    }
    result.addTable("compare_ratios.csv", ratios);
  }
  summary.results["model"] = modelJson(*cases.front().model, "(per case)");
  summary.results["compare"] = {
      {"reference", reference}, {"models", per_model}, {"against_reference", ratio_json}};
  for (const Case& c : cases) {
    double largest = 0.0;
    if (per_model.contains(c.name)) {
      for (const auto& [ch, h] : per_model[c.name]["harmonics"].items())
        for (double x : h["acceleration"]) largest = std::max(largest, x);
    }
    text +=
        fmt::format("  {:<18s} mean k {:.4e} N/m, largest mesh-order acceleration {:.4g} m/s^2\n",
                    c.name, c.mean, largest);
  }
  return ok ? kOk : kFailed;
}

}  // namespace

AnalysisResult feRotorAnalysis(const config::Config& config, const AnalysisContext& context) {
  AnalysisResult result("rotor", config, context);
  io::RunSummary& summary = result.summary;
  const std::string analysis = config.string("analysis.type");
  std::string text = fmt::format("finite-element geared rotor: {} analysis\n", analysis);
  int code = kOk;
  if (analysis == "time") code = runTime(config, context, summary, result, text);
  if (analysis == "modal") code = runFeRotorModal(config, summary, result, text);
  if (analysis == "campbell") code = runFeRotorCampbell(config, summary, result, text);
  if (analysis == "compare_stiffness") code = runCompare(config, context, summary, result, text);
  summary.status = code == kOk ? "ok" : "diverged";
  for (const auto& w : summary.warnings) {
    if (w.rfind("Newmark: ", 0) != 0) {
      context.warning(w);
    } else {
      result.errors.push_back("diverged: " + w.substr(9));
    }
  }
  result.report = text;
  result.summary.numerical_failure = code != kOk;
  return result;
}

}  // namespace geardyn::analysis

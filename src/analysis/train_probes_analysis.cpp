/// [probes] of `geardyn train`'s time analysis: simulated probe records of any train.
///
/// Sampling: the Newmark steps of the recorded window (whole common periods after the
/// transient) are resampled at the probe rate by cubic Hermite interpolation between the two
/// steps around each sample — q from (q, q̇), q̇ from (q̇, q̈); q̈ by the cubic through the four
/// steps around it. The interpolation error is at most (ωΔt)⁴/384 of a component of angular
/// frequency ω (the Hermite remainder Δt⁴/384 max|f⁗|): 1.5e-8 at 128 steps per period of
/// that component, far below Newmark's own relative frequency error ~(ωΔt)²/12 (2.0e-4 there).

#include "train_probes_analysis.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <map>
#include <numbers>
#include <random>

#include "geardyn/config/did_you_mean.h"
#include "geardyn/error.h"
#include "geardyn/io/probe_record.h"
#include "geardyn/signal/full_spectrum.h"
#include "geardyn/signal/gear_whirl.h"

namespace geardyn::analysis::detail {
namespace {

using Json = nlohmann::ordered_json;
constexpr double kTwoPi = 2.0 * std::numbers::pi;

std::string unitOf(const std::string& quantity) {
  return quantity == "displacement" ? "m" : quantity == "velocity" ? "m/s" : "m/s^2";
}

/// The highest tracked frequency: probes.mesh_harmonics × the fastest mesh frequency [Hz].
double highestTracked(const GearTrainModel& model, const config::Config& analysis, double speed) {
  double fastest = 0.0;
  for (const TrainMesh& m : model.meshes()) fastest = std::max(fastest, m.frequency_ratio);
  return static_cast<double>(analysis.integer("probes.mesh_harmonics")) * fastest * std::abs(speed);
}

double sampleRate(const GearTrainModel& model, const config::Config& analysis, double speed) {
  if (auto given = analysis.optionalReal("probes.sample_rate")) return *given;
  return std::ceil(8.0 * highestTracked(model, analysis, speed));
}

/// The keyphasor's body (−1: none).
int keyphasorBody(const GearTrainModel& model, const config::Config& analysis,
                  const std::vector<ProbeStation>& stations) {
  const std::string name = analysis.string("probes.keyphasor");
  if (name == "none") return -1;
  if (name.empty()) return stations.front().body;
  std::vector<std::string> shafts;
  for (std::size_t i = 0; i < model.spec().shafts.size(); ++i) {
    shafts.push_back(model.spec().shafts[i].name);
    if (shafts.back() == name) return model.shaftBody(static_cast<int>(i));
  }
  const auto match = config::closestMatch(name, shafts);
  throw InputError("probes.keyphasor", "\"" + name + "\"",
                   fmt::format("a shaft name ({}) or \"none\"{}", fmt::join(shafts, ", "),
                               match ? fmt::format("; did you mean \"{}\"?", *match) : ""));
}

/// Values of column `dof` at time t by cubic interpolation in the recorded window (Hermite on
/// (f, f') when `rate` is given, else the cubic through the four surrounding steps).
double interpolate(const Eigen::MatrixXd& f, const Eigen::MatrixXd* rate, int dof, double t0,
                   double dt, double t) {
  const Eigen::Index last = f.rows() - 1;
  const double x = (t - t0) / dt;
  Eigen::Index k = std::clamp<Eigen::Index>(static_cast<Eigen::Index>(std::floor(x)), 0, last - 1);
  const double s = x - static_cast<double>(k);
  if (rate) {
    const double h00 = (1 + 2 * s) * (1 - s) * (1 - s), h10 = s * (1 - s) * (1 - s);
    const double h01 = s * s * (3 - 2 * s), h11 = s * s * (s - 1);
    return h00 * f(k, dof) + h10 * dt * (*rate)(k, dof) + h01 * f(k + 1, dof) +
           h11 * dt * (*rate)(k + 1, dof);
  }
  const Eigen::Index b = std::clamp<Eigen::Index>(k - 1, 0, std::max<Eigen::Index>(0, last - 3));
  const double u = x - static_cast<double>(b);  // nodes at 0, 1, 2, 3
  double value = 0.0;
  for (int i = 0; i < 4; ++i) {
    double w = 1.0;
    for (int j = 0; j < 4; ++j)
      if (j != i) w *= (u - j) / static_cast<double>(i - j);
    value += w * f(b + i, dof);
  }
  return value;
}

/// Forward/backward whirl of every station at every tracked mesh order from the frequency-domain
/// steady state: x = Re(X e^{jωt}), y = Re(Y e^{jωt}) with X = 2 X_h(y DOF) (and (jω)^p for
/// velocity, acceleration), Y = σ 2 X_h(z DOF); circles by whirlCircles (full_spectrum.h).
Json steadyStateWhirl(const GearTrainModel& model, const config::Config& analysis,
                      const std::vector<ProbeStation>& stations, const TrainSteadyState& s) {
  const int harmonics = static_cast<int>(analysis.integer("probes.mesh_harmonics"));
  const std::string quantity = analysis.string("probes.quantity");
  const int power = quantity == "displacement" ? 0 : quantity == "velocity" ? 1 : 2;
  // Base harmonic h -> the mesh orders at that frequency ("stage1_1", …), ascending.
  std::map<int, std::vector<std::string>> orders;
  for (std::size_t m = 0; m < model.meshes().size(); ++m) {
    for (int k = 1; k <= harmonics; ++k) {
      const int h = k * s.mesh_multiple[m];
      if (h <= s.harmonics) orders[h].push_back(fmt::format("{}_{}", model.meshes()[m].name, k));
    }
  }
  Json json = Json::object();
  for (const ProbeStation& st : stations) {
    const int y = model.translationDof(st.body);
    Json list = Json::array();
    for (const auto& [h, names] : orders) {
      const double omega = kTwoPi * h * s.base_frequency;
      const std::complex<double> d = std::pow(std::complex<double>(0.0, omega), power);
      const std::complex<double> X = 2.0 * d * s.harmonic(y, h);
      const std::complex<double> Y = st.rotation_sign * 2.0 * d * s.harmonic(y + 1, h);
      const auto [forward, backward] = whirlCircles(X, Y);
      list.push_back({{"frequency_hz", h * s.base_frequency},
                      {"orders", names},
                      {"forward_amplitude", std::abs(forward)},
                      {"backward_amplitude", std::abs(backward)}});
    }
    json[st.name] = list;
  }
  return json;
}

}  // namespace

std::vector<ProbeStation> probeStations(const GearTrainModel& model, const config::Config& analysis,
                                        double speed) {
  const auto names = analysis.stringList("probes.stations");
  if (!names.empty() && model.spec().dofs == TrainDofs::kTorsional) {
    throw InputError("gearbox.dofs", "\"torsional\"",
                     "\"planar\" or \"full\" for probes: a torsional train has no lateral motion");
  }
  const auto& spec = model.spec();
  std::vector<ProbeStation> stations;
  for (const std::string& given : names) {
    const auto at = given.find('@');
    const std::string name = given.substr(0, at);
    const std::string key = "probes.stations";
    ProbeStation st{given, -1, 1.0};
    for (std::size_t i = 0; i < spec.shafts.size(); ++i) {
      if (spec.shafts[i].name != name) continue;
      if (at == std::string::npos) {
        st.body = model.shaftBody(static_cast<int>(i));
      } else {
        double position = 0.0;
        try {
          position = std::stod(given.substr(at + 1));
        } catch (const std::exception&) {
          throw InputError(key, "\"" + given + "\"", "\"shaft@position\" with a position in m");
        }
        try {
          st.body = model.bodyAt(static_cast<int>(i), position, key);
        } catch (const InputError& e) {
          std::vector<std::string> nodes;  // positions from the shaft's first section start
          for (int b : model.shaftNodes(static_cast<int>(i)))
            nodes.push_back(
                fmt::format("{:g}", model.bodies()[b].axial - spec.shafts[i].axial_offset));
          throw InputError(
              key, "\"" + given + "\"",
              fmt::format("{} (nodes at [{}] m)", e.allowed(), fmt::join(nodes, ", ")));
        }
      }
    }
    for (const TrainBearingSpec& b : spec.bearings) {
      if (st.body >= 0 || b.name != name || at != std::string::npos) continue;
      for (std::size_t i = 0; i < spec.shafts.size(); ++i)
        if (spec.shafts[i].name == b.shaft)
          st.body = model.bodyAt(static_cast<int>(i), b.position, key);
    }
    if (st.body < 0 && at == std::string::npos) st.body = model.bodyIndex(name);  // a planet
    if (st.body < 0) {
      std::vector<std::string> known;
      for (const auto& s : spec.shafts) known.push_back(s.name);
      for (const auto& b : spec.bearings) known.push_back(b.name);
      const auto match = config::closestMatch(name, known);
      throw InputError(key, "\"" + given + "\"",
                       fmt::format("a shaft (optionally \"shaft@position\") or bearing name "
                                   "({}){}",
                                   fmt::join(known, ", "),
                                   match ? fmt::format("; did you mean \"{}\"?", *match) : ""));
    }
    if (model.rotatingFrame(st.body) >= 0) {
      throw InputError(key, "\"" + given + "\"",
                       fmt::format("a body whose translations are in the fixed frame: {} moves in "
                                   "the rotating carrier frame of its planetary stage (not "
                                   "supported by probes yet)",
                                   model.bodies()[st.body].name));
    }
    st.rotation_sign = model.bodies()[st.body].speed_ratio * speed < 0.0 ? -1.0 : 1.0;
    stations.push_back(st);
  }
  return stations;
}

void checkTrainProbes(const GearTrainModel& model, const config::Config& analysis, double speed) {
  const auto stations = probeStations(model, analysis, speed);
  if (stations.empty()) return;
  const double fs = sampleRate(model, analysis, speed);
  const double highest = highestTracked(model, analysis, speed);
  if (fs <= 2.0 * highest) {
    throw InputError("probes.sample_rate", fmt::format("{:g} Hz", fs),
                     fmt::format("more than twice the highest tracked frequency ({:.6g} Hz: "
                                 "probes.mesh_harmonics × the fastest mesh frequency)",
                                 highest));
  }
  const int key_body = keyphasorBody(model, analysis, stations);
  if (key_body >= 0) {
    // The recorded window: time.record_periods common periods of the meshes.
    const double window = static_cast<double>(analysis.integer("time.record_periods")) /
                          (trainBaseFrequency(model, 1, 1000000000).ratio * std::abs(speed));
    const double key_speed = std::abs(model.bodies()[key_body].speed_ratio * speed) / kTwoPi;
    if (window * key_speed < 2.0) {  // spectrum needs two pulses
      throw InputError(
          "time.record_periods", std::to_string(analysis.integer("time.record_periods")),
          fmt::format("a recorded window of at least two revolutions of the keyphasor shaft "
                      "({:.6g} s; the window is {:.6g} s: at least {} common periods)",
                      2.0 / key_speed, window,
                      std::ceil(2.0 / key_speed / window *
                                static_cast<double>(analysis.integer("time.record_periods")))));
    }
  }
  const auto formats = analysis.stringList("probes.formats");
  if (std::find(formats.begin(), formats.end(), "wav") != formats.end() && std::round(fs) != fs) {
    throw InputError("probes.sample_rate", fmt::format("{:g} Hz", fs),
                     "a whole number of Hz for probes.formats \"wav\" (the WAV header's rate)");
  }
}

void writeTrainProbes(const GearTrainModel& model, const config::Config& analysis, double speed,
                      const TrainTimeResponse& r, const TrainSteadyState* steady,
                      AnalysisResult& result, std::string& text) {
  const auto stations = probeStations(model, analysis, speed);
  if (stations.empty()) return;
  const double fs = sampleRate(model, analysis, speed);
  const std::string quantity = analysis.string("probes.quantity");
  const int key_body = keyphasorBody(model, analysis, stations);
  // Keyphasor shaft speed [rev/s] (its rigid-body rotation: the Newmark DOFs are vibrations
  // about it).
  const double key_speed =
      key_body >= 0 ? std::abs(model.bodies()[key_body].speed_ratio * speed) / kTwoPi : 0.0;
  const double dt = r.time_step, t0 = r.t(0);
  const double window = r.t(r.t.size() - 1) - t0;
  const auto samples = static_cast<std::size_t>(std::floor(window * fs + 1e-9)) + 1;
  const Eigen::MatrixXd& f = quantity == "displacement" ? r.displacement
                             : quantity == "velocity"   ? r.velocity
                                                        : r.acceleration;
  const Eigen::MatrixXd* rate = quantity == "displacement" ? &r.velocity
                                : quantity == "velocity"   ? &r.acceleration
                                                           : nullptr;
  io::ProbeRecord record;
  record.sample_rate = fs;
  record.start_time = t0;
  // The CSV columns carry the unit (x1_m, x1_m_per_s or x1_m_per_s2); spectrum reads x1.
  const std::string unit = quantity == "displacement" ? "m"
                           : quantity == "velocity"   ? "m_per_s"
                                                      : "m_per_s2";
  for (std::size_t i = 0; i < stations.size(); ++i) {
    record.names.push_back(fmt::format("x{}", i + 1));
    record.names.push_back(fmt::format("y{}", i + 1));
    record.units.insert(record.units.end(), 2, unit);
  }
  if (key_body >= 0) {
    record.names.push_back("keyphasor");
    record.units.push_back("");
  }
  record.channels.assign(record.names.size(), std::vector<double>(samples));
  for (std::size_t j = 0; j < samples; ++j) {
    const double t = t0 + static_cast<double>(j) / fs;
    for (std::size_t i = 0; i < stations.size(); ++i) {
      const int y = model.translationDof(stations[i].body);
      record.channels[2 * i][j] = interpolate(f, rate, y, t0, dt, t);
      record.channels[2 * i + 1][j] =
          stations[i].rotation_sign * interpolate(f, rate, y + 1, t0, dt, t);
    }
    if (key_body >= 0) record.channels.back()[j] = keyphasorSignal(t, key_speed, fs);
  }
  const double noise = analysis.real("probes.noise_level");
  const auto seed = static_cast<std::uint64_t>(analysis.integer("probes.seed"));
  if (noise > 0.0) {
    std::mt19937_64 rng(seed);
    for (std::size_t c = 0; c < 2 * stations.size(); ++c)
      addRelativeNoise(record.channels[c], noise, rng);
    result.summary.seed = seed;
  }
  Json files = Json::array();
  for (const auto& name : analysis.stringList("probes.formats")) {
    const std::string file = name == "hdf5" ? "probes.h5" : "probes." + name;
    const io::RecordFormat format = io::recordFormatOf(file, "probes.formats");
    result.files.push_back({file, [format, record](const std::filesystem::path& path) {
                              io::writeProbeRecord(path, format, record);
                            }});
    files.push_back(file);
  }
  Json channels = Json::array();
  for (std::size_t i = 0; i < stations.size(); ++i) {
    const ProbeStation& st = stations[i];
    const TrainBody& b = model.bodies()[st.body];
    channels.push_back(
        {{"station", st.name},
         {"body", b.name},
         {"x", fmt::format("x{} = {}.y", i + 1, b.name)},
         {"y", fmt::format("y{} = {}{}.z", i + 1, st.rotation_sign < 0 ? "-" : "", b.name)},
         {"speed_ratio", b.speed_ratio},
         {"speed_rpm", b.speed_ratio * speed * 60.0 / kTwoPi}});
  }
  Json json = {{"files", files},
               {"quantity", quantity},
               {"unit", unitOf(quantity)},
               {"sample_rate_hz", fs},
               {"start_s", t0},
               {"samples", samples},
               {"duration_s", static_cast<double>(samples - 1) / fs},
               {"interpolation", "cubic Hermite between Newmark steps, error <= (ω Δt)^4/384"},
               {"noise_level", noise},
               {"channels", channels},
               {"keyphasor", nullptr}};
  if (noise > 0.0) json["seed"] = seed;
  if (key_body >= 0) {
    json["keyphasor"] = {{"shaft", model.bodies()[key_body].name},
                         {"speed_hz", key_speed},
                         {"pulse", "rising through 0.5 at the shaft's rigid-body angle 2 pi k"}};
  }
  if (steady) json["steady_state_whirl"] = steadyStateWhirl(model, analysis, stations, *steady);
  result.summary.results["probes"] = json;
  text += fmt::format("probes: {} stations, {} samples of {} at {:g} Hz ({})\n", stations.size(),
                      samples, quantity, fs, fmt::join(files, ", "));
}

}  // namespace geardyn::analysis::detail

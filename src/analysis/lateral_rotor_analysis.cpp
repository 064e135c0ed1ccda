/// `rotor` (no [model]): the lateral geared rotor of Rao 2023 in time and frequency domain,
/// its full spectra, simulated probe records and the parametric study of §4.5.

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <numbers>
#include <numeric>
#include <random>

#include "geardyn/analysis/analyses.h"
#include "geardyn/analysis/rotor_results.h"
#include "geardyn/config/rotor_config.h"
#include "geardyn/config/rotor_gearbox.h"
#include "geardyn/error.h"
#include "geardyn/io/probe_record.h"
#include "geardyn/signal/gear_whirl.h"
#include "geardyn/solvers/train_periodic_record.h"
#include "geardyn/solvers/train_response.h"
#include "geardyn/system/lateral_rotor_reduction.h"

namespace geardyn::analysis {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

GearWhirlSetup setupOf(const LateralRotorModel& model) {
  const auto& s = model.spec();
  return {s.pinion_speed, s.pinion_teeth, s.gear_teeth, model.harmonics()};
}

/// Sampling must resolve the highest component (mesh harmonic n) without aliasing.
/// `key` = `shown` (the value as the user gave it) must give a sample rate above Nyquist.
void requireNyquist(const LateralRotorModel& model, double sample_rate, const std::string& key,
                    const std::string& shown) {
  const double highest = model.meshOmega() * std::max(1, model.harmonics()) / kTwoPi;
  if (sample_rate <= 2.0 * highest) {
    throw InputError(key, shown,
                     fmt::format("too few: the sampling rate {:.6g} Hz must exceed twice the "
                                 "highest mesh harmonic ({:.6g} Hz)",
                                 sample_rate, highest));
  }
}

/// The gearbox the rotor is (config/rotor_gearbox.h): what its frequency and time domains solve,
/// built once per rotor.
struct RotorGearbox {
  RotorGearbox(const LateralRotorSpec& spec, const std::string& source)
      : train(config::lateralRotorGearTrain(spec, source, warnings)),
        probes(config::lateralRotorProbeDofs(train)) {}
  std::vector<std::string> warnings;  // the translation's gearbox warns about nothing it holds
  GearTrainModel train;
  std::vector<int> probes;  // x₁, y₁, x₂, y₂ (the gearbox's y, z of pinion and gear)
};

/// The rotor recorded from rest by the train's Dormand–Prince (train_periodic_record.h).
TrainRecord recordRotor(const LateralRotorModel& model, const RotorGearbox& gearbox,
                        const TrainRecordOptions& options) {
  return recordTrainFromRest(gearbox.train, gearbox.train.inputSpeed(), gearbox.probes,
                             model.commonPeriod(), options);
}

/// The four probe channels x₁, y₁, x₂, y₂ over the steady window of a time record.
std::array<std::vector<double>, 4> steadyChannels(const TrainRecord& r) {
  std::array<std::vector<double>, 4> channels;
  for (int c = 0; c < 4; ++c)
    for (long long k = r.window_begin; k < r.window_end; ++k)
      channels[c].push_back(r.displacement(k, c));
  return channels;
}

/// The whirl components of the rotor from the steady state of the gearbox it is
/// (config/rotor_gearbox.h) by the train's harmonic balance over the common period: with
/// q(t) = Re[X₀ + 2 Σ X_h e^{i h ω₀ t}], z = y + i z of a centre has X_h^y + i X_h^z at +h ω₀
/// and conj X_h^y + i conj X_h^z at −h ω₀ (the thesis's x, y are the gearbox's y, z). Named and
/// ordered as LateralRotorModel::whirlForcing(); a component sharing its frequency with a forced
/// one (t_p = t_g: the two 1× circles) is the forced one's, the other 0.
std::vector<RotorWhirlResponse> gearboxWhirlResponse(const LateralRotorModel& model,
                                                     const RotorGearbox& gearbox) {
  const GearTrainModel& train = gearbox.train;
  // No meshes: H is the highest excitation multiple, n_h t_p t_g/gcd (2800 for Table 4.1);
  // every harmonic is a 6 × 6 solve, so any tooth counts are accepted.
  const LateralRotorSpec& r = model.spec();
  TrainSteadyOptions options;
  options.mesh_harmonics = 1;
  options.max_base_harmonics = std::max(
      options.max_base_harmonics, std::max(1, model.harmonics()) * r.pinion_teeth * r.gear_teeth /
                                      std::gcd(r.pinion_teeth, r.gear_teeth));
  const TrainSteadyState s = solveTrainSteadyState(train, train.inputSpeed(), options);
  const int dofs[2] = {train.translationDof(train.bodyIndex("pinion")),
                       train.translationDof(train.bodyIndex("gear"))};
  const double w0 = kTwoPi * s.base_frequency;
  const auto forcing = model.whirlForcing();
  std::vector<RotorWhirlResponse> out;
  for (const WhirlForcing& f : forcing) {
    bool shared = false;
    for (const WhirlForcing& other : forcing) {
      shared = shared || (&other != &f && other.omega == f.omega && f.force.norm() == 0.0 &&
                          other.force.norm() > 0.0);
    }
    const long long h = std::llround(std::abs(f.omega) / w0);
    Eigen::Vector2cd z = Eigen::Vector2cd::Zero();
    for (int c = 0; c < 2 && !shared && h <= s.harmonics; ++c) {
      const std::complex<double> y = s.harmonic(dofs[c], h), w = s.harmonic(dofs[c] + 1, h);
      z(c) = f.omega >= 0.0 ? y + std::complex<double>(0.0, 1.0) * w
                            : std::conj(y) + std::complex<double>(0.0, 1.0) * std::conj(w);
    }
    out.push_back({f.name, f.omega, z});
  }
  return out;
}

struct StudyCase {
  std::string name, group;
  double factor = 1.0;
  LateralRotorSpec spec;
};

std::vector<StudyCase> studyCases(const config::Config& config, const LateralRotorSpec& base) {
  const double zeta_m_known = base.mesh_damping / std::sqrt(base.mesh_stiffness);
  std::vector<StudyCase> cases{{"baseline", "baseline", 1.0, base}};
  for (double f : config.realList("study.speed_factors")) {
    if (!(f > 0.0)) throw InputError("study.speed_factors", fmt::format("{:g}", f), "factors > 0");
    StudyCase c{fmt::format("speed_x{:g}", f), "speed", f, base};
    c.spec.pinion_speed *= f;
    cases.push_back(c);
  }
  const double d = config.real("study.stiffness_te_change");
  for (int sign : {+1, -1}) {
    StudyCase c{sign > 0 ? fmt::format("stiffness_up_{:g}_te_down", d)
                         : fmt::format("stiffness_down_{:g}_te_up", d),
                "stiffness_te", 1.0 + sign * d, base};
    c.spec.mesh_stiffness *= 1.0 + sign * d;
    // Thesis §4.5: the mesh damping follows the stiffness, c_m = 2 ζ_m √(k_m m).
    c.spec.mesh_damping = zeta_m_known * std::sqrt(c.spec.mesh_stiffness);
    for (auto* list : {&c.spec.te_x, &c.spec.te_y})
      for (auto& h : *list) h.amplitude *= 1.0 - sign * d;
    c.spec.mean_te *= 1.0 - sign * d;
    cases.push_back(c);
  }
  for (double f : config.realList("study.runout_factors")) {
    if (!(f >= 0.0)) throw InputError("study.runout_factors", fmt::format("{:g}", f), ">= 0");
    StudyCase c{fmt::format("runout_x{:g}", f), "runout", f, base};
    c.spec.pinion_runout *= f;
    c.spec.gear_runout *= f;
    cases.push_back(c);
  }
  for (double f : config.realList("study.mesh_damping_factors")) {
    if (!(f >= 0.0)) throw InputError("study.mesh_damping_factors", fmt::format("{:g}", f), ">= 0");
    StudyCase c{fmt::format("mesh_damping_x{:g}", f), "mesh_damping", f, base};
    c.spec.mesh_damping *= f;
    cases.push_back(c);
  }
  return cases;
}

/// RMS of a shaft's whirl components whose names start with `prefix` ("mesh_": the gear-mesh
/// vibration; "": every dynamic component): √(Σ |c|²) over them, the static one excluded [m].
double whirlRms(const std::vector<WhirlComponent>& peaks, const std::string& prefix) {
  double sum = 0.0;
  for (const auto& c : peaks)
    if (c.name != "static" && c.name.rfind(prefix, 0) == 0) sum += std::norm(c.value);
  return std::sqrt(sum);
}

/// The time response (Dormand–Prince), its steady-window full spectrum and its comparison with
/// the exact frequency-domain peaks `exact`; false when the integration failed.
bool addTimeDomain(const config::Config& config, const AnalysisContext& context,
                   const LateralRotorModel& model, const RotorGearbox& gearbox,
                   const GearPairSpectrumOptions& spectrum_options,
                   const std::array<std::vector<WhirlComponent>, 2>& exact, AnalysisResult& result,
                   TrainRecord& time, std::string& text) {
  io::RunSummary& summary = result.summary;
  const GearWhirlSetup setup = setupOf(model);
  const double max_frequency =
      config.optionalReal("spectrum.max_frequency")
          .value_or(1.25 * setup.meshFrequency() * std::max(1, model.harmonics()));
  const std::uint64_t seed = static_cast<std::uint64_t>(config.integer("spectrum.seed"));
  const double noise = config.real("spectrum.noise_level");
  bool ok = true;
  context.checkBudget("rotor_time");
  TrainRecordOptions time_options = config::rotorTimeOptionsFromConfig(config, model.spec());
  time_options.integrator.progress = context.progressFor("rotor: time response", "s simulated");
  // Checked before integrating: the grid's rate (snapped to the common period) is within a
  // sample per period of duration/(samples − 1).
  const std::string samples_shown =
      fmt::format("{} (over time.duration = {:g} s{})", time_options.samples, time_options.duration,
                  config.has("time.samples") ? "" : "; derived from the highest mesh harmonic");
  requireNyquist(model, (time_options.samples - 1) / time_options.duration * (1.0 - 1e-3),
                 "time.samples", samples_shown);
  const auto start = std::chrono::steady_clock::now();
  time = recordRotor(model, gearbox, time_options);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  requireNyquist(model, time.sample_rate, "time.samples", samples_shown);
  summary.results["time_domain"] = {{"status", toString(time.status)},
                                    {"message", time.message},
                                    {"wall_time_s", seconds},
                                    {"steps", time.steps},
                                    {"rhs_evaluations", time.rhs_evaluations},
                                    {"sample_rate_hz", time.sample_rate},
                                    {"samples", time.t.size()},
                                    {"transient_end_s", time.t[time.transient_end]},
                                    {"window_start_s", time.t[time.window_begin]},
                                    {"window_periods", time.window_periods}};
  // Displacements of the pinion (1) and gear (2) centres [m] (Rao 2023, Fig. 2.1 axes).
  io::CsvTable history({"t_s", "x1_m", "y1_m", "x2_m", "y2_m", "steady"});
  for (std::size_t k = 0; k < time.t.size(); ++k) {
    const auto e = time.displacement.row(static_cast<Eigen::Index>(k));
    history.addRow({time.t[k], e(0), e(1), e(2), e(3),
                    static_cast<long long>(static_cast<long long>(k) >= time.window_begin &&
                                           static_cast<long long>(k) < time.window_end)});
  }
  result.addTable("time_history.csv", history);
  text +=
      fmt::format("  time domain: {} ({} steps, {:.3g} s)\n", time.message, time.steps, seconds);
  if (!time.converged()) {
    ok = false;
    result.errors.push_back(time.message);
  } else {
    auto channels = steadyChannels(time);
    if (noise > 0.0) {
      std::mt19937_64 rng(seed);
      for (auto& channel : channels) addRelativeNoise(channel, noise, rng);
    }
    const GearPairSpectrum spectrum = analyseGearPairRecord(
        channels, time.sample_rate, time.t[time.window_begin], 0.0, setup, spectrum_options);
    result.addTable("spectrum_peaks.csv", analysis::whirlPeaksTable(spectrum.peaks));
    result.addTable("full_spectrum.csv",
                    analysis::fullSpectrumTable(spectrum.display, max_frequency));
    // Time domain against the exact solution, component by component.
    double largest = 0.0, amplitude_error = 0.0, phase_error = 0.0;
    for (int sh = 0; sh < 2; ++sh)
      for (const auto& c : exact[sh]) largest = std::max(largest, std::abs(c.value));
    for (int sh = 0; sh < 2; ++sh) {
      for (std::size_t i = 0; i < exact[sh].size(); ++i) {
        const auto a = spectrum.peaks[sh][i].value, b = exact[sh][i].value;
        if (std::abs(b) < 1e-3 * largest) continue;  // phases of vanishing peaks mean nothing
        amplitude_error = std::max(amplitude_error, std::abs(std::abs(a) / std::abs(b) - 1.0));
        phase_error = std::max(phase_error, std::abs(std::arg(a / b)));
      }
    }
    summary.results["coefficient_noise"] = {{"pinion", spectrum.coefficient_sigma[0]},
                                            {"gear", spectrum.coefficient_sigma[1]}};
    summary.results["time_domain"]["extraction"] =
        spectrum.method == WhirlExtraction::kExactBins ? "exact_bins" : "least_squares";
    summary.results["time_domain"]["peaks"] = analysis::whirlPeaksJson(spectrum.peaks);
    summary.results["time_vs_frequency"] = {
        {"max_relative_amplitude_difference", amplitude_error},
        {"max_phase_difference_rad", phase_error},
        {"note", "over peaks above 1e-3 of the largest; includes the noise when noise_level > 0"}};
    text += fmt::format(
        "  time vs frequency domain: relative amplitudes within {:.2e} [-], phases within "
        "{:.2e} rad\n",
        amplitude_error, phase_error);
  }
  return ok;
}

/// The exact periodic response superposed from its whirl components at the time run's steady
/// samples (or over one common period) (frequency_history.csv).
void addSuperposedHistory(const LateralRotorModel& model,
                          const std::vector<RotorWhirlResponse>& parts, const TrainRecord& time,
                          AnalysisResult& result) {
  std::vector<double> times;
  if (!time.t.empty()) {
    times.assign(time.t.begin() + time.window_begin, time.t.begin() + time.window_end);
  } else {
    const int n = 4096;
    for (int k = 0; k < n; ++k) times.push_back(model.commonPeriod() * k / n);
  }
  const auto history = superposeWhirlResponse(parts, times);
  io::CsvTable table({"t_s", "x1_m", "y1_m", "x2_m", "y2_m"});
  for (std::size_t k = 0; k < times.size(); ++k) {
    const auto& e = history[k];
    table.addRow({times[k], e(0), e(1), e(2), e(3)});
  }
  result.addTable("frequency_history.csv", table);
}

/// Simulated probe records x₁, y₁, x₂, y₂ with a keyphasor (measurement.*) of the rotor's
/// gearbox integrated from rest (Dormand–Prince), in the formats `spectrum` reads; false when
/// the integration failed.
bool addProbeRecords(const config::Config& config, const LateralRotorModel& model,
                     const RotorGearbox& gearbox, const TrainRecord& time, AnalysisResult& result) {
  io::RunSummary& summary = result.summary;
  const auto& s = model.spec();
  const auto formats = config.stringList("measurement.formats");
  if (formats.empty()) return true;
  const double fs = config.real("measurement.sample_rate");
  requireNyquist(model, fs, "measurement.sample_rate", fmt::format("{:g} Hz", fs));
  const double period = model.commonPeriod();
  double start = 0.0;
  if (auto given = config.optionalReal("measurement.start")) {
    start = *given;
  } else if (!time.t.empty() && time.converged()) {
    start = std::ceil(time.t[time.transient_end] / period - 1e-9) * period;
  } else {
    throw InputError("measurement.start", "(not set)",
                     "give a start time, or enable [time] so the transient is detected");
  }
  const double duration = config.optionalReal("measurement.duration").value_or(2.0 * period);
  const auto n = static_cast<long long>(std::floor(duration * fs));
  // Two samples before the start so the first pulse's rising edge is fully sampled.
  std::vector<double> times;
  for (long long k = -2; k < n; ++k) times.push_back(start + static_cast<double>(k) / fs);
  if (times.front() < 0.0) {
    throw InputError("measurement.start", fmt::format("{:g}", start),
                     fmt::format(">= {:g} s (two samples)", 2.0 / fs));
  }
  TrainDormandPrinceOptions integrator;
  integrator.relative_tolerance = config.real("time.relative_tolerance");
  integrator.absolute_tolerance = config.real("time.absolute_tolerance");
  io::ProbeRecord record;
  record.sample_rate = fs;
  record.start_time = times.front();
  record.names = {"x1", "y1", "x2", "y2", "keyphasor"};
  record.units = {"m", "m", "m", "m", ""};
  record.channels.assign(5, std::vector<double>(times.size()));
  const TrainDormandPrinceRun run = integrateTrainDormandPrince(
      gearbox.train, gearbox.train.inputSpeed(), times, gearbox.probes, integrator,
      [&](std::size_t k, const Eigen::VectorXd& q, const Eigen::VectorXd&, const Eigen::VectorXd&) {
        for (int c = 0; c < 4; ++c) record.channels[c][k] = q(c);
      });
  if (!run.finite) {
    result.errors.push_back("measurement: the integration produced non-finite values");
    return false;
  }
  for (std::size_t k = 0; k < times.size(); ++k)
    record.channels[4][k] = keyphasorSignal(times[k], s.pinion_speed, fs);
  const double measurement_noise = config.real("measurement.noise_level");
  if (measurement_noise > 0.0) {
    std::mt19937_64 rng(static_cast<std::uint64_t>(config.integer("measurement.seed")));
    for (int c = 0; c < 4; ++c) addRelativeNoise(record.channels[c], measurement_noise, rng);
    summary.seed = static_cast<std::uint64_t>(config.integer("measurement.seed"));
  }
  nlohmann::ordered_json files = nlohmann::ordered_json::array();
  for (const auto& f : formats) {
    const auto format = f == "csv"   ? io::RecordFormat::kCsv
                        : f == "wav" ? io::RecordFormat::kWav
                                     : io::RecordFormat::kHdf5;
    const std::string name = f == "hdf5" ? "measurement.h5" : fmt::format("measurement.{}", f);
    result.files.push_back({name, [format, record](const std::filesystem::path& path) {
                              io::writeProbeRecord(path, format, record);
                            }});
    files.push_back(name);
  }
  summary.results["measurement"] = {{"files", files},
                                    {"sample_rate_hz", fs},
                                    {"start_s", record.start_time},
                                    {"samples", times.size()},
                                    {"noise_level", measurement_noise},
                                    {"keyphasor",
                                     "pulse at each pinion revolution, rising "
                                     "through 0.5 at pinion angle 2 pi k"}};
  return true;
}

/// The parametric study of Rao (2023) §4.5: speed, mesh stiffness with TE, runouts and mesh
/// damping varied one at a time; each case's whirl peaks and their RMS change against the
/// baseline; false when a time-domain case failed.
bool addParametricStudy(const config::Config& config, const LateralRotorModel& model,
                        const GearPairSpectrumOptions& spectrum_options, AnalysisResult& result,
                        std::vector<std::string>& warnings, std::string& text) {
  io::RunSummary& summary = result.summary;
  const auto& s = model.spec();
  bool ok = true;
  const bool in_time = config.string("study.method") == "time";
  io::CsvTable table({"case", "group", "factor", "shaft", "component", "frequency_hz",
                      "amplitude_m", "phase_rad"});
  io::CsvTable totals({"case", "group", "factor", "shaft", "mesh_rms_m", "mesh_relative_change",
                       "dynamic_rms_m", "dynamic_relative_change"});
  // Two measures: the gear-mesh vibration (mesh harmonics) and the whole dynamic orbit
  // (mesh harmonics + 1x runout circles).
  std::array<std::array<double, 2>, 2> baseline{};  // [measure][shaft]
  std::array<std::map<std::string, double>, 2> group_change;
  nlohmann::ordered_json cases_json = nlohmann::ordered_json::array();
  for (const StudyCase& c : studyCases(config, model.spec())) {
    const LateralRotorModel m(c.spec);
    const RotorGearbox gearbox(c.spec, config.source() + " " + c.name);
    std::array<std::vector<WhirlComponent>, 2> peaks;
    if (in_time) {
      // Derived samples follow the case's speed; given ones are scaled up with it.
      TrainRecordOptions o = config::rotorTimeOptionsFromConfig(config, c.spec);
      if (config.has("time.samples"))
        o.samples =
            static_cast<long long>(o.samples * std::max(1.0, c.spec.pinion_speed / s.pinion_speed));
      const TrainRecord r = recordRotor(m, gearbox, o);
      if (!r.converged()) {
        warnings.push_back(fmt::format("study case {}: {}", c.name, r.message));
        ok = false;
        continue;
      }
      peaks = analyseGearPairRecord(steadyChannels(r), r.sample_rate, r.t[r.window_begin], 0.0,
                                    setupOf(m), spectrum_options)
                  .peaks;
    } else {
      peaks =
          analysis::frequencyDomainPeaks(gearboxWhirlResponse(m, gearbox), spectrum_options.frame);
    }
    nlohmann::ordered_json case_json = {{"case", c.name}, {"group", c.group}, {"factor", c.factor}};
    for (int sh = 0; sh < 2; ++sh) {
      for (const auto& p : peaks[sh]) {
        table.addRow({c.name, c.group, c.factor, std::string(analysis::kShaftNames[sh]), p.name,
                      p.frequency, std::abs(p.value), std::arg(p.value)});
      }
      std::array<double, 2> rms{whirlRms(peaks[sh], "mesh_"), whirlRms(peaks[sh], "")};
      std::array<double, 2> change{0.0, 0.0};
      for (int k = 0; k < 2; ++k) {
        if (c.group == "baseline") baseline[k][sh] = rms[k];
        change[k] = baseline[k][sh] > 0.0 ? rms[k] / baseline[k][sh] - 1.0 : 0.0;
        if (c.group != "baseline")
          group_change[k][c.group] = std::max(group_change[k][c.group], std::abs(change[k]));
      }
      totals.addRow({c.name, c.group, c.factor, std::string(analysis::kShaftNames[sh]), rms[0],
                     change[0], rms[1], change[1]});
      case_json[analysis::kShaftNames[sh]] = {{"mesh_rms_m", rms[0]},
                                              {"mesh_relative_change", change[0]},
                                              {"dynamic_rms_m", rms[1]},
                                              {"dynamic_relative_change", change[1]}};
    }
    cases_json.push_back(case_json);
  }
  result.addTable("study.csv", table);
  result.addTable("study_totals.csv", totals);
  std::array<nlohmann::ordered_json, 2> rankings;
  std::array<std::string, 2> dominant;
  for (int k = 0; k < 2; ++k) {
    std::vector<std::pair<std::string, double>> ranking(group_change[k].begin(),
                                                        group_change[k].end());
    std::sort(ranking.begin(), ranking.end(),
              [](const auto& a, const auto& b) { return a.second > b.second; });
    rankings[k] = nlohmann::ordered_json::array();
    for (const auto& [group, change] : ranking)
      rankings[k].push_back({{"group", group}, {"max_relative_change", change}});
    if (!ranking.empty())
      dominant[k] =
          fmt::format("{} ({:.1f} %)", ranking.front().first, 100 * ranking.front().second);
  }
  summary.results["study"] = {
      {"method", in_time ? "time" : "frequency"},
      {"measures",
       {{"mesh_rms",
         "sqrt(sum |c|^2) over the mesh harmonics, forward and backward: the "
         "gear-mesh vibration"},
        {"dynamic_rms",
         "the same over every dynamic component (mesh harmonics and the 1x "
         "runout circles)"}}},
      {"cases", cases_json},
      {"ranking_mesh", rankings[0]},
      {"ranking_dynamic", rankings[1]}};
  text += fmt::format("  study: dominant source of the mesh vibration {}, of the whole orbit {}\n",
                      dominant[0], dominant[1]);
  return ok;
}

}  // namespace

AnalysisResult lateralRotorAnalysis(const config::Config& config, const AnalysisContext& context) {
  AnalysisResult result("rotor", config, context);
  // The file's rotor is a gearbox (config/rotor_gearbox.h), which the frequency and time domains
  // solve; the whirl bookkeeping (components, common period) is the 4-DOF rotor that gearbox
  // reduces to (system/lateral_rotor_reduction.h), not the file's own reading.
  const RotorGearbox gearbox(config::lateralRotorSpecFromConfig(config), config.source());
  const LateralRotorModel model(lateralRotorReduction(gearbox.train.spec()));
  const GearPairSpectrumOptions spectrum_options =
      config::gearPairSpectrumOptionsFromConfig(config);
  const GearWhirlSetup setup = setupOf(model);
  const std::uint64_t seed = static_cast<std::uint64_t>(config.integer("spectrum.seed"));
  const double noise = config.real("spectrum.noise_level");
  std::vector<std::string> warnings;

  io::RunSummary& summary = result.summary;
  if (noise > 0.0) summary.seed = seed;
  const auto& s = model.spec();
  summary.results["frequencies"] = {{"pinion_hz", s.pinion_speed},
                                    {"gear_hz", setup.gearSpeed()},
                                    {"mesh_hz", setup.meshFrequency()},
                                    {"common_period_s", model.commonPeriod()}};
  nlohmann::ordered_json te_x = nlohmann::ordered_json::array(), te_y = te_x;
  for (const auto& h : s.te_x) te_x.push_back({{"amplitude", h.amplitude}, {"phase", h.phase}});
  for (const auto& h : s.te_y) te_y.push_back({{"amplitude", h.amplitude}, {"phase", h.phase}});
  summary.results["mesh"] = {
      {"stiffness", s.mesh_stiffness}, {"mean_te", s.mean_te}, {"te_x", te_x}, {"te_y", te_y}};
  summary.results["damping"] = {{"pinion_shaft", s.pinion_shaft_damping},
                                {"gear_shaft", s.gear_shaft_damping},
                                {"mesh", s.mesh_damping}};
  summary.results["conventions"] = analysis::whirlConventionsJson(
      spectrum_options.frame,
      "t = 0 of the simulation (≡ any multiple of the common period in steady state), where the "
      "pinion and gear angles are their runout phases");

  // Frequency domain: the exact steady state of the gearbox this file is, by the train's
  // harmonic balance (tests/system/train_excitation_test.cpp: the 4-DOF closed form to 1e-10).
  const auto t0 = std::chrono::steady_clock::now();
  const auto parts = gearboxWhirlResponse(model, gearbox);
  const double frequency_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const auto exact = analysis::frequencyDomainPeaks(parts, spectrum_options.frame);
  result.addTable("frequency_components.csv", analysis::whirlPeaksTable(exact));
  summary.results["frequency_domain"] = {{"wall_time_s", frequency_seconds},
                                         {"peaks", analysis::whirlPeaksJson(exact)}};

  std::string text = fmt::format(
      "lateral geared rotor: pinion {:.6g} Hz, gear {:.6g} Hz, mesh {:.6g} Hz, common period "
      "{:.6g} s\n",
      s.pinion_speed, setup.gearSpeed(), setup.meshFrequency(), model.commonPeriod());
  TrainRecord time;
  bool ok =
      !config.boolean("time.enabled") ||
      addTimeDomain(config, context, model, gearbox, spectrum_options, exact, result, time, text);
  if (config.boolean("frequency.superpose")) addSuperposedHistory(model, parts, time, result);
  if (!addProbeRecords(config, model, gearbox, time, result)) ok = false;
  if (config.boolean("study.enabled") &&
      !addParametricStudy(config, model, spectrum_options, result, warnings, text))
    ok = false;

  summary.status = ok ? "ok" : (time.converged() ? "study_incomplete" : toString(time.status));
  summary.warnings = warnings;
  context.warnings(warnings);
  for (int sh = 0; sh < 2; ++sh) {
    double mesh1 = 0.0;
    for (const auto& c : exact[sh])
      if (c.name.rfind("mesh_1_", 0) == 0) mesh1 = std::max(mesh1, std::abs(c.value));
    text += fmt::format("  {} shaft: static |z| {:.4g} m, largest 1st-mesh whirl {:.4g} m\n",
                        analysis::kShaftNames[sh], std::abs(exact[sh].front().value), mesh1);
  }
  result.report = text;
  result.summary.numerical_failure = !ok;
  return result;
}

}  // namespace geardyn::analysis

#include "geardyn/config/rotor_config.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

#include "geardyn/config/geometry_config.h"
#include "geardyn/config/ltca_config.h"
#include "geardyn/config/output_section.h"
#include "geardyn/error.h"
#include "geardyn/identify/dte_identification.h"

namespace geardyn::config {
namespace {
constexpr double kDegPerRad = 180.0 / std::numbers::pi;  // the file's degrees, the model's radians

void addSpectrumSection(ConfigSchema& schema) {
  schema.section("spectrum",
                 "Full spectrum of each shaft (z = x + jy, FFT scaled 1/N: 0-peak whirl radii).");
  schema.string("spectrum.frame")
      .choices({"probe", "shaft"})
      .defaultValue("probe")
      .doc(
          "probe: both shafts in the probe frame (+f = +z, counter-clockwise from x to y); shaft: "
          "each shaft relative to its own rotation (thesis Fig. 4.2: the pinion, turning in -z, "
          "is conjugated)");
  schema.string("spectrum.method")
      .choices({"auto", "exact_bins", "least_squares"})
      .defaultValue("auto")
      .doc(
          "how peaks are read: FFT bins when every component falls on one (whole common "
          "periods), else a least-squares fit at the known frequencies");
  schema.string("spectrum.display_window")
      .choices({"hann", "rectangular"})
      .defaultValue("hann")
      .doc("window of full_spectrum.csv and its plot (peaks are never windowed)");
  schema.real("spectrum.max_frequency")
      .unit("Hz")
      .positive()
      .optional()
      .doc("highest |f| in full_spectrum.csv; default 1.25 × the highest mesh harmonic");
  schema.real("spectrum.noise_level")
      .unit("-")
      .min(0.0)
      .max(10.0)
      .defaultValue(0.0)
      .doc(
          "white Gaussian noise added to each channel before the analysis, standard deviation = "
          "level × std(channel) (thesis §4.4: 0.05)");
  schema.integer("spectrum.seed").min(0).defaultValue(1).doc("seed of the noise generator");
}

std::vector<TeHarmonic> harmonicsOf(const Config& config, const std::string& amplitudes,
                                    const std::string& phases) {
  const auto a = config.realList(amplitudes);
  const auto p = config.realList(phases);
  if (p.size() != 1 && p.size() != a.size()) {
    throw InputError(
        phases, fmt::format("{} values", p.size()),
        fmt::format("one phase for every harmonic, or one per harmonic ({})", a.size()));
  }
  std::vector<TeHarmonic> out;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!(a[i] >= 0.0) || !std::isfinite(a[i])) {
      throw InputError(amplitudes, fmt::format("{:g} (harmonic {})", a[i], i + 1),
                       "amplitudes must be finite and >= 0 [m]");
    }
    out.push_back({a[i], (p.size() == 1 ? p[0] : p[i]) / kDegPerRad});  // [deg] → [rad]
  }
  return out;
}

/// k_m, e_m and the TE harmonics from the loaded tooth contact at mesh.ltca_force: the mesh
/// linearised about the load (Özgüven & Houser: a constant stiffness with the loaded STE as
/// displacement excitation), δ(φ) = e_m + Σ |c_i| sin(2πiφ + arg c_i + π/2), split along the
/// line of action at angle α from y (Rao Fig. 2.1): e_x = δ sin α, e_y = δ cos α.
void ltcaMesh(const Config& config, LateralRotorSpec& s) {
  if (!hasGearPair(config)) {
    throw InputError("mesh.from_ltca", "true",
                     "needs the gear pair: [pinion], [gear] (and [pair])");
  }
  if (!config.has("mesh.ltca_force")) {
    throw InputError("mesh.ltca_force", "(not set)", "needed by mesh.from_ltca [N]");
  }
  const GearPair pair(gearPairSpecFromConfig(config));
  if (pair.spec().pinion.teeth != s.pinion_teeth || pair.spec().gear.teeth != s.gear_teeth) {
    throw InputError("pinion.teeth",
                     fmt::format("{}/{}", pair.spec().pinion.teeth, pair.spec().gear.teeth),
                     fmt::format("must match rotor.pinion_teeth/gear_teeth ({}/{})", s.pinion_teeth,
                                 s.gear_teeth));
  }
  const auto contact = loadedContactFromConfig(config, pair, 1);
  const int n = static_cast<int>(config.integer("mesh.ltca_positions"));
  const auto points = contact->sweep(config.real("mesh.ltca_force"), n);
  const double alpha = config.has("mesh.line_of_action_angle_deg")
                           ? config.real("mesh.line_of_action_angle_deg") / kDegPerRad
                           : pair.operatingPressureAngle();
  const int harmonics = std::max<int>(1, static_cast<int>(s.te_x.size()));
  double k_mean = 0.0, mean = 0.0;
  for (const auto& p : points) {
    k_mean += p.tangent / n;
    mean += p.ste / n;
  }
  const auto c = steHarmonics(points, harmonics);
  s.mesh_stiffness = k_mean;
  s.mean_te = mean;
  s.te_x.clear();
  s.te_y.clear();
  const double sa = std::sin(alpha), ca = std::cos(alpha);
  for (const auto& ci : c) {
    const double phase = std::arg(ci) + 0.5 * std::numbers::pi;
    s.te_x.push_back({std::abs(ci * sa), phase + (sa < 0.0 ? std::numbers::pi : 0.0)});
    s.te_y.push_back({std::abs(ci * ca), phase + (ca < 0.0 ? std::numbers::pi : 0.0)});
  }
}

}  // namespace

void addRotorSection(ConfigSchema& schema, bool with_speed) {
  schema.section("rotor", "Masses at mid-span of shafts on rigid bearings (Table 4.1).");
  schema.real("rotor.pinion_mass").unit("kg").positive().defaultValue(0.310).doc("m1");
  schema.real("rotor.gear_mass").unit("kg").positive().defaultValue(1.270).doc("m2");
  schema.real("rotor.pinion_shaft_stiffness")
      .unit("N/m")
      .positive()
      .defaultValue(1e6)
      .doc("k_s1, lateral stiffness of the input shaft at the pinion");
  schema.real("rotor.gear_shaft_stiffness")
      .unit("N/m")
      .positive()
      .defaultValue(1e6)
      .doc("k_s2, lateral stiffness of the output shaft at the gear");
  schema.real("rotor.shaft_damping_ratio")
      .unit("-")
      .min(0.0)
      .lessThan(1.0)
      .defaultValue(0.01)
      .doc("zeta_s: c_s1 = 2 zeta_s sqrt(k_s1 m1), c_s2 = 2 zeta_s sqrt(k_s2 m2)");
  schema.real("rotor.pinion_shaft_damping")
      .unit("N s/m")
      .min(0.0)
      .optional()
      .doc("c_s1 given directly (overrides the ratio)");
  schema.real("rotor.gear_shaft_damping")
      .unit("N s/m")
      .min(0.0)
      .optional()
      .doc("c_s2 given directly (overrides the ratio)");
  schema.real("rotor.gravity")
      .unit("m/s^2")
      .min(0.0)
      .defaultValue(9.81)
      .doc(
          "g, downwards: along −z as in a gearbox and the FE rotor, which is the model's −y "
          "(thesis Fig. 2.1: shaft along z, y up)");
  schema.integer("rotor.pinion_teeth").min(2).max(100000).defaultValue(16).doc("t_p");
  schema.integer("rotor.gear_teeth").min(2).max(100000).defaultValue(35).doc("t_g");
  if (with_speed) {
    schema.real("rotor.speed_rpm")
        .unit("rpm")
        .positive()
        .defaultValue(660.0)
        .doc("pinion speed N_p; the pinion turns in -z, the gear in +z (Rao eq. 2.2)");
    schema.alias("rotor.pinion_speed_rpm", "rotor.speed_rpm");
  }
}

/// Mesh spring, damper and transmission error (Rao 2023 eqs. 2.6-2.9).
static void addRotorMeshSection(ConfigSchema& schema) {
  schema.section("mesh", "Mesh spring, damper and transmission error (eqs. 2.6-2.9).");
  schema.real("mesh.stiffness").unit("N/m").positive().defaultValue(6e8).doc("k_m");
  schema.real("mesh.damping_ratio")
      .unit("-")
      .min(0.0)
      .lessThan(1.0)
      .defaultValue(0.01)
      .doc("zeta_m: c_m = 2 zeta_m sqrt(k_m m_mesh)");
  schema.string("mesh.damping_mass")
      .choices({"effective", "arithmetic_mean"})
      .defaultValue("effective")
      .doc(
          "m_mesh for the ratio: effective m1 m2/(m1 + m2), the thesis's \"average gearing mass\" "
          "(eq. 4.9), or arithmetic_mean (m1 + m2)/2");
  schema.real("mesh.damping")
      .unit("N s/m")
      .min(0.0)
      .optional()
      .doc("c_m given directly (overrides the ratio)");
  schema.real("mesh.mean_te").unit("m").defaultValue(50e-6).doc("e_m, in x and in y");
  schema.realList("mesh.te_x")
      .unit("m")
      .defaultValue(nlohmann::ordered_json::array({40e-6, 25e-6, 35e-6, 20e-6, 10e-6}))
      .doc("e_fx,i: amplitudes of the mesh harmonics i = 1..n in x");
  schema.realList("mesh.te_x_phase_deg")
      .unit("deg")
      .defaultValue(nlohmann::ordered_json::array({0.785 * kDegPerRad}))
      .doc("phi_ex,i: one phase for all harmonics or one per harmonic (the thesis's 0.785 rad)");
  schema.alias("mesh.te_x_phase",
               "mesh.te_x_phase_deg");  // value converted (config/renamed_keys.h)
  schema.realList("mesh.te_y")
      .unit("m")
      .defaultValue(nlohmann::ordered_json::array({30e-6, 15e-6, 25e-6, 10e-6, 5e-6}))
      .doc("e_fy,i in y (as many as te_x)");
  schema.realList("mesh.te_y_phase_deg")
      .unit("deg")
      .defaultValue(nlohmann::ordered_json::array({1.570 * kDegPerRad}))
      .doc("phi_ey,i (the thesis's 1.570 rad)");
  schema.alias("mesh.te_y_phase",
               "mesh.te_y_phase_deg");  // value converted (config/renamed_keys.h)

  schema.boolean("mesh.from_ltca")
      .defaultValue(false)
      .doc(
          "take k_m, e_m and the TE harmonics from the loaded tooth contact of the gear pair in "
          "[pinion], [gear], [pair] with [modifications] at mesh.ltca_force: k_m = mean tangent "
          "stiffness, e = loaded STE (mean and harmonics) split along the line of action "
          "(overrides stiffness, mean_te, te_x, te_y)");
  schema.real("mesh.ltca_force")
      .unit("N")
      .positive()
      .optional()
      .doc("from_ltca: transmitted force along the line of action");
  schema.integer("mesh.ltca_positions")
      .min(16)
      .max(100000)
      .defaultValue(400)
      .doc("from_ltca: mesh positions per period");
  schema.real("mesh.line_of_action_angle_deg")
      .unit("deg")
      .optional()
      .doc(
          "from_ltca: angle of the line of action from the y axis (Rao Fig. 2.1): e_x = e sin, "
          "e_y = e cos; default the operating pressure angle");
  schema.alias("mesh.line_of_action_angle",
               "mesh.line_of_action_angle_deg");  // value converted (config/renamed_keys.h)
}

/// Gear runouts and the Dormand-Prince time response.
static void addRotorRunoutAndTimeSections(ConfigSchema& schema) {
  schema.section("runout", "Gear runouts (eccentricities) and their phases (eqs. 2.2-2.4).");
  schema.real("runout.pinion").unit("m").min(0.0).defaultValue(200e-6).doc("e_p");
  schema.real("runout.pinion_phase_deg")
      .unit("deg")
      .defaultValue(1.047 * kDegPerRad)
      .doc("phi_p (the thesis's 1.047 rad)");
  schema.alias("runout.pinion_phase",
               "runout.pinion_phase_deg");  // value converted (config/renamed_keys.h)
  schema.real("runout.gear").unit("m").min(0.0).defaultValue(300e-6).doc("e_g");
  schema.real("runout.gear_phase_deg")
      .unit("deg")
      .defaultValue(2.094 * kDegPerRad)
      .doc("phi_g (the thesis's 2.094 rad)");
  schema.alias("runout.gear_phase",
               "runout.gear_phase_deg");  // value converted (config/renamed_keys.h)

  schema.section("time", "Dormand-Prince 5(4) from rest (the thesis's ode45).");
  schema.boolean("time.enabled").defaultValue(true).doc("integrate in time");
  schema.real("time.duration").unit("s").positive().defaultValue(15.0).doc("simulated time");
  schema.integer("time.samples")
      .min(16)
      .max(200000000)
      .optional()
      .doc(
          "samples over the duration; default: the smallest power of two with 2.2 samples per "
          "period of the highest mesh harmonic (2^15 for the thesis's rig)");
  schema.boolean("time.align_to_common_period")
      .defaultValue(true)
      .doc("snap the sample interval to a whole number of samples per common period");
  schema.real("time.relative_tolerance")
      .unit("-")
      .greaterThan(0.0)
      .lessThan(0.1)
      .defaultValue(1e-8);
  schema.real("time.absolute_tolerance")
      .unit("-")
      .greaterThan(0.0)
      .defaultValue(1e-8)
      .doc("in units of the response scale L (displacements) and L n omega_e (velocities)");
  schema.real("time.steady_tolerance")
      .unit("-")
      .greaterThan(0.0)
      .lessThan(1.0)
      .defaultValue(1e-6)
      .doc("steady once |z(t + T_c) - z(t)| <= tol max|z| for the rest of the record");
}

/// The exact steady state, the spectrum, the gear pair and the modifications.
static void addRotorFrequencySections(ConfigSchema& schema) {
  schema.section("frequency", "Exact steady state, one complex solve per whirl component.");
  schema.boolean("frequency.superpose")
      .defaultValue(false)
      .doc("write frequency_history.csv: the components superposed on the analysis window");

  addSpectrumSection(schema);
  addGearPairSections(schema, false);
  addModificationsSection(schema);
}

/// Simulated measurement records and the parametric study of §4.5.
static void addRotorMeasurementSections(ConfigSchema& schema) {
  schema.section("measurement",
                 "Simulated probe records (x1, y1, x2, y2, keyphasor) for `geardyn spectrum`.");
  schema.stringList("measurement.formats")
      .choices({"csv", "wav", "hdf5"})
      .defaultValue(nlohmann::ordered_json::array())
      .doc("files to write: measurement.csv / .wav (64-bit float) / .h5");
  schema.real("measurement.sample_rate")
      .unit("Hz")
      .positive()
      .defaultValue(5000.0)
      .doc("the rig's 5 kS/s (thesis §5.4)");
  schema.real("measurement.duration")
      .unit("s")
      .positive()
      .optional()
      .doc("default: two common periods");
  schema.real("measurement.start")
      .unit("s")
      .min(0.0)
      .optional()
      .doc("default: the first common-period boundary after the detected transient");
  schema.real("measurement.noise_level")
      .unit("-")
      .min(0.0)
      .max(10.0)
      .defaultValue(0.0)
      .doc("white Gaussian noise in the probe channels: level x std(channel) (not the keyphasor)");
  schema.integer("measurement.seed").min(0).defaultValue(1).doc("seed of the measurement noise");

  schema.section("study", "Parametric study of §4.5: which source dominates the response.");
  schema.boolean("study.enabled").defaultValue(false);
  schema.string("study.method")
      .choices({"frequency", "time"})
      .defaultValue("frequency")
      .doc("exact frequency-domain steady states, or Dormand-Prince runs (slower)");
  schema.realList("study.speed_factors")
      .unit("-")
      .defaultValue(nlohmann::ordered_json::array({2.0, 4.0}))
      .doc("pinion speed x factor (thesis: 660, 1320, 2640 rpm)");
  schema.real("study.stiffness_te_change")
      .unit("-")
      .greaterThan(0.0)
      .lessThan(1.0)
      .defaultValue(0.2)
      .doc("k_m x (1 + c) with TE x (1 - c), and the reverse (thesis: 20 %)");
  schema.realList("study.runout_factors")
      .unit("-")
      .defaultValue(nlohmann::ordered_json::array({0.5, 2.0}))
      .doc("both runouts x factor");
  schema.realList("study.mesh_damping_factors")
      .unit("-")
      .defaultValue(nlohmann::ordered_json::array({0.5, 2.0}))
      .doc("mesh damping x factor");
}

ConfigSchema rotorSchema() {
  ConfigSchema schema("rotor",
                      "Lateral geared rotor with asymmetric transmission error (Rao 2023, "
                      "Fig. 2.1): Dormand-Prince response from rest, exact frequency-domain "
                      "steady state, orbits, full spectra, simulated probe records, parametric "
                      "study. Defaults are the thesis's Table 4.1.");
  schema.string("title").optional().doc("free text describing the study");
  addRotorSection(schema, true);

  addRotorMeshSection(schema);
  addRotorRunoutAndTimeSections(schema);
  addRotorFrequencySections(schema);
  addRotorMeasurementSections(schema);
  addOutputSection(schema);
  return schema;
}

ConfigSchema spectrumSchema() {
  ConfigSchema schema("spectrum",
                      "Full spectra of measured (or simulated) probe records x1, y1, x2, y2 with "
                      "a keyphasor: whole shaft cycles, phase compensation, whirl peaks (Rao 2023 "
                      "§4.3-4.4, §5.4-5.5).");
  schema.string("title").optional().doc("free text describing the study");
  schema.section("input", "The record.");
  schema.string("input.file")
      .required()
      .doc("a .csv (header, optional time column), .wav or .h5/.hdf5 file; relative to the config");
  schema.stringList("input.channels")
      .defaultValue(nlohmann::ordered_json::array({"x1", "y1", "x2", "y2", "keyphasor"}))
      .doc(
          "channel names (CSV columns, HDF5 datasets), in the file's order for WAV; x1, y1, x2, "
          "y2 must be among them, keyphasor optional");
  schema.real("input.sample_rate")
      .unit("Hz")
      .positive()
      .optional()
      .doc("when the file has none; must agree with the file's otherwise");
  schema.string("input.time_column")
      .defaultValue("")
      .doc("CSV: the time column [s]; empty: the first of t_s, time, time_s, t in the header");
  schema.real("input.scale")
      .unit("m/unit")
      .defaultValue(1.0)
      .doc("multiplies every probe value (e.g. 1/sensitivity; PCM WAV is first scaled to [-1, 1))");

  schema.section("gears", "The gear pair whose components are sought.");
  schema.integer("gears.pinion_teeth").min(2).max(100000).required().doc("t_p");
  schema.integer("gears.gear_teeth").min(2).max(100000).required().doc("t_g");
  schema.integer("gears.harmonics").min(0).max(1000).defaultValue(5).doc("mesh harmonics n");
  schema.real("gears.speed_rpm")
      .unit("rpm")
      .positive()
      .optional()
      .doc("pinion speed: needed without a keyphasor; with one, checked against it (1 %)");
  schema.alias("gears.pinion_speed_rpm", "gears.speed_rpm");

  schema.section("keyphasor", "Once-per-revolution reference on the input (pinion) shaft.");
  schema.boolean("keyphasor.enabled")
      .defaultValue(true)
      .doc("use the keyphasor channel: whole pinion cycles, phases referred to its first pulse");
  schema.real("keyphasor.threshold")
      .optional()
      .doc("rising-edge threshold; default halfway between the channel's extremes");
  schema.real("keyphasor.max_speed_variation")
      .unit("-")
      .greaterThan(0.0)
      .lessThan(1.0)
      .defaultValue(0.05)
      .doc("largest relative deviation of a revolution's duration from the median");

  addSpectrumSection(schema);
  addOutputSection(schema);
  return schema;
}

LateralRotorSpec knownRotorFromConfig(const Config& config) {
  LateralRotorSpec s;
  s.pinion_mass = config.real("rotor.pinion_mass");
  s.gear_mass = config.real("rotor.gear_mass");
  s.pinion_shaft_stiffness = config.real("rotor.pinion_shaft_stiffness");
  s.gear_shaft_stiffness = config.real("rotor.gear_shaft_stiffness");
  s.gravity = config.real("rotor.gravity");
  s.pinion_teeth = static_cast<int>(config.integer("rotor.pinion_teeth"));
  s.gear_teeth = static_cast<int>(config.integer("rotor.gear_teeth"));
  if (config.resolved()["rotor"].contains("speed_rpm"))
    s.pinion_speed = config.real("rotor.speed_rpm") / 60.0;
  lateralRotorDamping(s, config.real("rotor.shaft_damping_ratio"), 0.0);
  if (auto c = config.optionalReal("rotor.pinion_shaft_damping")) s.pinion_shaft_damping = *c;
  if (auto c = config.optionalReal("rotor.gear_shaft_damping")) s.gear_shaft_damping = *c;
  s.te_x.clear();
  s.te_y.clear();
  return s;
}

LateralRotorSpec lateralRotorSpecFromConfig(const Config& config) {
  LateralRotorSpec s = knownRotorFromConfig(config);
  s.mesh_stiffness = config.real("mesh.stiffness");
  s.mean_te = config.real("mesh.mean_te");
  s.te_x = harmonicsOf(config, "mesh.te_x", "mesh.te_x_phase_deg");
  s.te_y = harmonicsOf(config, "mesh.te_y", "mesh.te_y_phase_deg");
  if (s.te_x.size() != s.te_y.size()) {
    throw InputError("mesh.te_y", fmt::format("{} harmonics", s.te_y.size()),
                     fmt::format("as many as mesh.te_x ({})", s.te_x.size()));
  }
  if (config.boolean("mesh.from_ltca")) ltcaMesh(config, s);
  s.pinion_runout = config.real("runout.pinion");
  s.pinion_runout_phase = config.real("runout.pinion_phase_deg") / kDegPerRad;
  s.gear_runout = config.real("runout.gear");
  s.gear_runout_phase = config.real("runout.gear_phase_deg") / kDegPerRad;
  const MeshDampingMass kind = config.string("mesh.damping_mass") == "effective"
                                   ? MeshDampingMass::kEffective
                                   : MeshDampingMass::kArithmeticMean;
  s.mesh_damping =
      config.optionalReal("mesh.damping")
          .value_or(dashpotFromRatio(config.real("mesh.damping_ratio"), s.mesh_stiffness,
                                     meshDampingMass(s.pinion_mass, s.gear_mass, kind)));
  s.validate();
  return s;
}

long long rotorTimeSamples(const Config& config, const LateralRotorSpec& spec) {
  if (config.has("time.samples")) return config.integer("time.samples");
  // The highest frequency of the response: the highest mesh harmonic h f_m, f_m = t_p N_p.
  const double highest_hz =
      spec.pinion_speed * spec.pinion_teeth * std::max<double>(1.0, spec.te_x.size());
  const double needed = kRotorSamplesPerHighestPeriod * highest_hz * config.real("time.duration");
  // At most the largest power of two the key allows (2e8): beyond it the analysis's Nyquist
  // check says the rate is too low for time.duration.
  long long samples = 16;
  while (static_cast<double>(samples) < needed && 2 * samples <= 200000000) samples *= 2;
  return samples;
}

TrainRecordOptions rotorTimeOptionsFromConfig(const Config& config, const LateralRotorSpec& spec) {
  TrainRecordOptions o;
  o.duration = config.real("time.duration");
  o.samples = rotorTimeSamples(config, spec);
  o.align_to_common_period = config.boolean("time.align_to_common_period");
  o.integrator.relative_tolerance = config.real("time.relative_tolerance");
  o.integrator.absolute_tolerance = config.real("time.absolute_tolerance");
  o.steady_tolerance = config.real("time.steady_tolerance");
  o.validate();
  return o;
}

GearPairSpectrumOptions gearPairSpectrumOptionsFromConfig(const Config& config) {
  GearPairSpectrumOptions o;
  o.frame = config.string("spectrum.frame") == "shaft" ? WhirlFrame::kShaft : WhirlFrame::kProbe;
  const std::string method = config.string("spectrum.method");
  o.method = method == "exact_bins"      ? WhirlExtraction::kExactBins
             : method == "least_squares" ? WhirlExtraction::kLeastSquares
                                         : WhirlExtraction::kAuto;
  o.display_window = config.string("spectrum.display_window") == "hann"
                         ? SpectrumWindow::kHann
                         : SpectrumWindow::kRectangular;
  return o;
}

}  // namespace geardyn::config

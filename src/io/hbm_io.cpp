#include "geardyn/io/hbm_io.h"

#include <cmath>

namespace geardyn::io {

ConfigSchema hbmSchema() {
  ConfigSchema schema("hbm",
                      "Harmonic-balance forced response of the gear-pair model (coupled static/"
                      "dynamic, AFT), continued in frequency through folds, with stability.");
  schema.string("title").optional().doc("free text describing the study");
  schema.section("hbm", "Harmonic balance.");
  schema.integer("hbm.harmonics")
      .min(1)
      .max(512)
      .defaultValue(14)
      .doc("H, harmonics of the mesh frequency");
  schema.integer("hbm.samples_per_period")
      .min(3)
      .max(1 << 20)
      .defaultValue(256)
      .doc("N, AFT samples per period (> 2H)");
  schema.real("hbm.tolerance")
      .unit("-")
      .positive()
      .defaultValue(1e-10)
      .doc("relative residual ‖R‖ / (|F| + k̄‖q‖ + ‖F_ext‖)");
  schema.integer("hbm.max_iterations").min(1).defaultValue(40).doc("Newton iterations per point");
  schema.realList("hbm.detail_frequencies")
      .unit("Hz")
      .min(0.0)
      .defaultValue(nlohmann::ordered_json::array())
      .doc(
          "frequencies at which one period of response, contact force and mesh stiffness is "
          "written");
  schema.section("sweep", "Continuation in the mesh frequency.");
  schema.real("sweep.start")
      .unit("Hz")
      .positive()
      .required()
      .doc("lower end of the range (nondimensional: Ω)");
  schema.real("sweep.stop").unit("Hz").positive().required().doc("upper end of the range");
  schema.real("sweep.initial_step")
      .unit("Hz")
      .positive()
      .optional()
      .doc("first arclength step (in frequency units); absent: derived (a fifth of max_step)");
  schema.real("sweep.min_step")
      .unit("Hz")
      .positive()
      .optional()
      .doc("smallest step before a failure is reported; absent: derived (1e-6 max_step)");
  schema.real("sweep.max_step")
      .unit("Hz")
      .positive()
      .optional()
      .doc(
          "largest step; absent: derived from the problem, min(range / 50, zeta f_n / j) with j "
          "the highest superharmonic order (<= H) whose resonance f_n / j lies in the range");
  schema.real("sweep.fold_tolerance")
      .unit("Hz")
      .positive()
      .optional()
      .doc(
          "how far the branch must go back in frequency to confirm a fold; absent: 1e-3 of "
          "the range");
  schema.string("sweep.direction")
      .choices({"up", "down", "both"})
      .defaultValue("both")
      .doc("sweep up from start, down from stop, or both");
  schema.boolean("sweep.stability").defaultValue(true).doc("stability of every point");
  schema.string("sweep.stability_method")
      .choices({"hill", "monodromy"})
      .defaultValue("monodromy")
      .doc(
          "the sampled monodromy matrix (O(N), the default), or Hill's method (sorted Floquet "
          "exponents, ~40x dearer; the cross-check)");
  schema.realList("sweep.newmark_frequencies")
      .unit("Hz")
      .min(0.0)
      .defaultValue(nlohmann::ordered_json::array())
      .doc("frequencies checked by Newmark time integration (overlaid on the plot)");
  addGearPairDynamicsSections(schema);
  return schema;
}

HarmonicBalanceOptions harmonicBalanceOptionsFromConfig(const Config& config) {
  HarmonicBalanceOptions o;
  o.harmonics = static_cast<int>(config.integer("hbm.harmonics"));
  o.samples_per_period = static_cast<int>(config.integer("hbm.samples_per_period"));
  o.tolerance = config.real("hbm.tolerance");
  o.max_iterations = static_cast<int>(config.integer("hbm.max_iterations"));
  o.validate();
  return o;
}

SweepRow sweepRow(HarmonicBalance& hbm, const GearPairModel& model, const SweepPoint& point,
                  const std::string& sweep, double frequency_scale) {
  SweepRow row;
  row.sweep = sweep;
  row.frequency = point.solution.omega / frequency_scale;
  row.branch = point.branch;
  row.stable = point.solution.stable;
  row.newton_iterations = point.solution.iterations;
  const std::vector<double> x = hbm.timeSignal(point.solution.q);
  const int n = static_cast<int>(x.size());
  row.max = -HUGE_VAL;
  row.min = HUGE_VAL;
  int lost = 0;
  std::vector<double> y(n);
  for (int i = 0; i < n; ++i) {
    const double phase = model.spec().initial_phase + static_cast<double>(i) / n;
    y[i] = x[i] - model.transmissionError().value(phase);
    row.max = std::max(row.max, y[i]);
    row.min = std::min(row.min, y[i]);
    row.mean += y[i] / n;
    row.rms += y[i] * y[i] / n;
    double slope = 0.0;
    model.contactLaw(y[i], &slope);
    lost += slope == 0.0;
  }
  row.rms = std::sqrt(row.rms);
  row.p2p = row.max - row.min;
  row.contact_loss = static_cast<double>(lost) / n;
  // Harmonic amplitudes of y = x − e from the samples by one real FFT (y is band-limited to
  // the H harmonics of x plus those of e, sampled well above Nyquist).
  Eigen::VectorXd coefficients = Eigen::VectorXd::Zero(2 * hbm.harmonics() + 1);
  hbm.coefficientsOf(y, coefficients);
  row.harmonics.push_back(std::abs(coefficients[0]));
  for (int h = 1; h <= hbm.harmonics(); ++h) {
    row.harmonics.push_back(std::hypot(coefficients[2 * h - 1], coefficients[2 * h]));
  }
  return row;
}

CsvTable sweepTable(const std::vector<SweepRow>& rows, int harmonics) {
  std::vector<std::string> columns = {
      "frequency",         "branch",       "p2p",  "mean", "max", "min", "rms", "stable",
      "newton_iterations", "contact_loss", "sweep"};
  for (int h = 0; h <= harmonics; ++h) columns.push_back("h" + std::to_string(h));
  CsvTable table(columns);
  for (const auto& r : rows) {
    std::vector<CsvCell> cells = {r.frequency,
                                  static_cast<long long>(r.branch),
                                  r.p2p,
                                  r.mean,
                                  r.max,
                                  r.min,
                                  r.rms,
                                  static_cast<long long>(r.stable),
                                  static_cast<long long>(r.newton_iterations),
                                  r.contact_loss,
                                  r.sweep};
    for (double a : r.harmonics) cells.emplace_back(a);
    table.addRow(std::move(cells));
  }
  return table;
}

}  // namespace geardyn::io

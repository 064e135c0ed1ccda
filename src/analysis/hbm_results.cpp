#include "geardyn/analysis/hbm_results.h"

#include <cmath>

#include "geardyn/config/hbm_config.h"

namespace geardyn::analysis {

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

io::CsvTable sweepTable(const std::vector<SweepRow>& rows, int harmonics, bool nondimensional) {
  // x along the transverse line of action; the unit ends each name ("nondim": Ω/ω_n and x₀).
  const std::string x = nondimensional ? "_transverse_nondim" : "_transverse_m";
  std::vector<std::string> columns = {nondimensional ? "frequency_nondim" : "frequency_hz",
                                      "branch",
                                      "p2p" + x,
                                      "mean" + x,
                                      "max" + x,
                                      "min" + x,
                                      "rms" + x,
                                      "stable",
                                      "newton_iterations",
                                      "contact_loss",
                                      "sweep"};
  for (int h = 0; h <= harmonics; ++h) columns.push_back("h" + std::to_string(h) + x);
  io::CsvTable table(columns);
  for (const auto& r : rows) {
    std::vector<io::CsvCell> cells = {r.frequency,
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

}  // namespace geardyn::analysis

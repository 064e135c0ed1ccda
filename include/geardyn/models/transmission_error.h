#pragma once
/// \file
/// A periodic excitation over the mesh period — the static transmission error or gear error
/// e(φ) — as a sum of a Fourier series in mesh orders, a rectangular wave and a table.
/// Convention (issue #4, config [model.transmission_error]):
///   e(φ) = Σ_r a_r cos(2π r φ + φ_r) + rectangular + table,   φ the mesh phase.

#include <string>
#include <vector>

namespace geardyn {

class TransmissionError {
 public:
  /// Zero everywhere.
  TransmissionError() = default;

  /// Adds Σ a_r cos(2π r φ + φ_r), r = 1, 2, ...: amplitudes [m] (any sign) and phases [rad],
  /// one per amplitude, or none (every φ_r = 0: the one rule of every input that has a
  /// series, issue #33). Throws InputError naming `amplitudes_key` or `phases_key` (the keys
  /// as the user wrote them) for mismatched or non-finite values.
  void addFourier(std::vector<double> amplitudes, std::vector<double> phases,
                  const std::string& amplitudes_key = "transmission_error.amplitudes",
                  const std::string& phases_key = "transmission_error.phases_deg");
  /// Adds a rectangular wave: `amplitude` for φ in [start, start + duty) (mod 1), 0 elsewhere;
  /// duty in (0, 1).
  void addRectangular(double amplitude, double duty, double start,
                      const std::string& key = "transmission_error");
  /// Adds a table over one period: ascending phases in [0, 1), values [m]; periodic linear
  /// interpolation (after the last point it runs to the first point + 1).
  void addTable(std::vector<double> phases, std::vector<double> values,
                const std::string& key = "transmission_error");

  double value(double phase) const;
  /// de/dφ [m per mesh period] (the rectangular wave's jumps contribute nothing; on a table
  /// point, where the table's slope jumps, the mean of the slopes on either side).
  double derivative(double phase) const;
  bool isZero() const noexcept;
  /// The same excitation times `factor` (e.g. a transverse error e_t as the normal one
  /// e_t cos β_b of a helical pair).
  TransmissionError scaled(double factor) const;

 private:
  struct TableSegment {
    std::size_t lo, hi;  // table points around the phase
    double x0, x1, x;    // their phases and the phase, unwrapped so that x0 <= x < x1
  };
  TableSegment tableSegment(double phase) const;

  std::vector<double> amplitudes_, phases_;
  double rect_amplitude_ = 0.0, rect_duty_ = 0.0, rect_start_ = 0.0;
  std::vector<double> table_phases_, table_values_;
};

}  // namespace geardyn

#pragma once
/// \file
/// The whirl components a gear pair's lateral response holds (Rao 2023 §4.4): static, the mesh
/// harmonics forward and backward, and the 1× of each shaft, at frequencies fixed by the pinion
/// speed and the teeth numbers; their common period; the keyphasor-referenced analysis of a
/// record (§5.4–5.5: whole shaft cycles, phase compensation) and the change to a shaft's own
/// rotation frame.

#include <array>
#include <string>
#include <vector>

#include "geardyn/signal/full_spectrum.h"

namespace geardyn {

/// Speeds and teeth of a gear pair: ω_e = t_p ω_p = t_g ω_g; the pinion turns in the −z sense
/// and the gear in the +z sense of the probe frame (x → y counter-clockwise), as in Rao eq. 2.2.
struct GearWhirlSetup {
  double pinion_speed = 0.0;  ///< [rev/s]
  int pinion_teeth = 0;
  int gear_teeth = 0;
  int harmonics = 0;  ///< mesh harmonics n

  void validate() const;
  double gearSpeed() const { return pinion_speed * pinion_teeth / gear_teeth; }  ///< [rev/s]
  double meshFrequency() const { return pinion_speed * pinion_teeth; }           ///< [Hz]
  /// t_g/d pinion revolutions, d = gcd(t_p, t_g) [s].
  double commonPeriod() const;
};

/// static, mesh_1_fwd, mesh_1_bwd, …, mesh_n_bwd, pinion_1x_fwd, pinion_1x_bwd, gear_1x_fwd,
/// gear_1x_bwd, with signed frequencies in the probe frame (fwd > 0) [Hz]; values zero.
std::vector<WhirlComponent> gearWhirlComponents(const GearWhirlSetup& setup);

/// Reference frame of reported whirl components.
enum class WhirlFrame {
  kProbe,  ///< z = x + jy for both shafts (forward = +z, the probe frame)
  kShaft,  ///< each shaft relative to its own rotation (thesis Fig. 4.2): the pinion shaft's
           ///< record is conjugated (z = x − jy), so its forward is the pinion's spin sense
};

/// A component seen in another frame: for a shaft turning in −z, the frequency changes sign, the
/// value is conjugated and fwd/bwd in the name swap.
WhirlComponent inShaftFrame(const WhirlComponent& probe_frame_component, bool shaft_turns_negative);

/// The whirl components of both shafts of a gear pair from a record (x₁, y₁ at the pinion,
/// x₂, y₂ at the gear), with phases referred to one time and reported in a frame.
struct GearPairSpectrumOptions {
  WhirlFrame frame = WhirlFrame::kProbe;
  WhirlExtraction method = WhirlExtraction::kAuto;
  SpectrumWindow display_window = SpectrumWindow::kHann;  ///< for the displayed full spectra
};

struct GearPairSpectrum {
  /// [0] pinion shaft, [1] gear shaft: the components of gearWhirlComponents() (names and
  /// frequencies in the reported frame), values = complex 0-peak radius at the reference time.
  std::array<std::vector<WhirlComponent>, 2> peaks;
  std::array<FullSpectrum, 2> display;  ///< full spectra for display (frame applied)
  /// Standard deviation of each complex peak value from the noise left after the components
  /// are removed: √(Σ|r|² / (N − m)) / √N, r the residual record [m] (the weights and
  /// confidence intervals of the identification).
  std::array<double, 2> coefficient_sigma{0.0, 0.0};
  WhirlExtraction method = WhirlExtraction::kAuto;  ///< the method used
};

/// Analyses the samples [begin, end) of the four channels, sample k at time t₀ + k/f_s; phases
/// are referred to `reference_time` (c_ref = c(t_first) e^{j2πf(t_ref − t_first)}, exact for
/// the steady components).
GearPairSpectrum analyseGearPairRecord(const std::array<std::vector<double>, 4>& channels,
                                       double sample_rate, double first_sample_time,
                                       double reference_time, const GearWhirlSetup& setup,
                                       const GearPairSpectrumOptions& options);

/// Both shafts' peaks (probe frame) reported in `frame`: the pinion shaft turns in −z.
std::array<std::vector<WhirlComponent>, 2> inFrame(std::array<std::vector<WhirlComponent>, 2> peaks,
                                                   WhirlFrame frame);

/// Keyphasor (once-per-revolution) pulses.
struct KeyphasorPulses {
  std::vector<double> times;  ///< rising threshold crossings, linear interpolation [s]
  double threshold = 0.0;
  double speed = 0.0;  ///< revolutions per second from the first and last pulse [rev/s]
};

/// Finds the rising crossings of `threshold` (NaN: halfway between the channel's extremes) in a
/// keyphasor channel sampled at `sample_rate`, time of sample 0 = `start_time`. Throws
/// InputError when fewer than two pulses are found or when the intervals between pulses vary
/// by more than `max_speed_variation` (relative) — a missing pulse or a speed change.
KeyphasorPulses findKeyphasorPulses(const std::vector<double>& keyphasor, double sample_rate,
                                    double start_time, double threshold = 0.0 / 0.0,
                                    double max_speed_variation = 0.05);

/// A simulated once-per-revolution keyphasor at time t [s] of a shaft turning at `speed`
/// [rev/s] (angle 2π·speed·t): 0 → 1 at each revolution, with linear edges 4 samples (of
/// `sample_rate` [Hz]) wide centred on the revolution, high for 10 % of a revolution (an
/// eddy-current probe over a key: findKeyphasorPulses recovers the crossing of 0.5 exactly by
/// linear interpolation).
double keyphasorSignal(double t, double speed, double sample_rate);

}  // namespace geardyn

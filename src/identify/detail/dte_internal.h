#pragma once
/// \file
/// Internals shared by the three-step and joint DTE estimators (not installed).

#include <Eigen/Core>
#include <complex>
#include <string>
#include <vector>

#include "geardyn/identify/dte_identification.h"

namespace geardyn::detail {

/// The value of a named component of one shaft (InputError if absent).
const std::complex<double>& peakOf(const MeasuredWhirlPeaks& data, int shaft,
                                   const std::string& name);
/// Mesh harmonics present (mesh_1_fwd, mesh_2_fwd, … on the pinion shaft).
int harmonicsIn(const MeasuredWhirlPeaks& data);
/// K₂ − Ω²M₂ + jΩC₂ of the spec.
Eigen::Matrix2cd systemMatrix(const LateralRotorSpec& spec, double omega);
/// value ± 1.96 sd; identifiable when 1.96 sd ≤ width × |value| (relative) or ≤ width.
IdentifiedValue fromLinear(double value, double sd, double width, bool relative);
/// Amplitude and phase of a complex estimate with the 2×2 covariance of (Re, Im) (delta
/// method); `conjugate_phase`: the phase is −arg c (a runout e e^{−jϕ}).
IdentifiedPhasor phasorFrom(std::complex<double> c, const Eigen::Matrix2d& covariance, double width,
                            bool conjugate_phase);
/// Copies the identified values into r.spec.
void writeBack(DteIdentification& r);

DteIdentification jointIdentification(const LateralRotorSpec& known,
                                      const std::vector<MeasuredWhirlPeaks>& data, int harmonics,
                                      const IdentificationOptions& options,
                                      const DteIdentification& start);

}  // namespace geardyn::detail

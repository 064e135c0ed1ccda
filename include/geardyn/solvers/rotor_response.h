#pragma once
/// \file
/// The frequency-domain form of the lateral geared rotor (system/lateral_rotor.h, Rao 2023
/// ch. 3): the exact steady state, one 2×2 complex solve (K − Ω²M + jΩC) p = s per whirl
/// component (thesis eqs. 3.135–3.138), superposed to a time history on request — the closed
/// form the identification inverts (identify/). Its time domain is the gearbox the rotor is
/// (config/rotor_gearbox.h) recorded by the train's Dormand–Prince (train_periodic_record.h).

#include <Eigen/Core>
#include <string>
#include <vector>

#include "geardyn/system/lateral_rotor.h"

namespace geardyn {

/// One steady whirl component of the response: z_s(t) ∋ p_s e^{jΩt}, s = 1 (pinion), 2 (gear).
struct RotorWhirlResponse {
  std::string name;           ///< as in LateralRotorModel::whirlForcing(), probe frame
  double omega = 0.0;         ///< signed [rad/s]
  Eigen::Vector2cd response;  ///< complex 0-peak radius at t = 0 of (z₁, z₂) [m]
};

/// The exact steady state, component by component.
std::vector<RotorWhirlResponse> solveRotorFrequencyResponse(const LateralRotorModel& model);

/// Σ p e^{jΩt} at the given times: (x₁, y₁, x₂, y₂) per time.
std::vector<Eigen::Vector4d> superposeWhirlResponse(const std::vector<RotorWhirlResponse>& parts,
                                                    const std::vector<double>& times);

}  // namespace geardyn

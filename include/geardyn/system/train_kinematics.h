#pragma once
/// \file
/// Kinematics of a gear train: the speed of every shaft, carrier and planet per unit input
/// speed, from the constraints its connections impose:
///
///   fixed-axis external mesh   ω_a z_a + ω_b z_b = 0        internal mesh  ω_a z_a − ω_b z_b = 0
///   sun–planet (Willis)        (ω_s − ω_c) z_s + (ω_p − ω_c) z_p = 0
///   ring–planet                (ω_r − ω_c) z_r − (ω_p − ω_c) z_p = 0
///   coupling, torsional bearing between shafts   ω_a = ω_b;   torsional bearing to the housing ω =
///   0
///
/// The constraints are linear in the speeds; with the input's speed set to 1 they are solved in
/// the least-squares sense (complete orthogonal decomposition). A residual means a loop of
/// constraints that contradict each other — the train is locked — and it sits exactly on the
/// constraints of that loop, which the message names; a null space means bodies whose speed the
/// input does not determine (not connected, or a differential with two free members).

#include <string>
#include <vector>

namespace geardyn {

/// One kinematic constraint Σ coefficient_i ω_{body_i} = 0, with where it comes from.
struct SpeedConstraint {
  std::vector<int> bodies;
  std::vector<double> coefficients;
  std::string source;  ///< "meshes.stage1", "couplings.motor", "bearings.ring_support", …
};

struct TrainKinematics {
  std::vector<double> speed_ratio;  ///< ω_body / Ω_input [-], per body
};

/// The speeds for `input_body` at speed ratio 1. Throws InputError when the train is locked
/// (naming the constraints and bodies of the loop) or a body's speed is undetermined (naming
/// the bodies).
TrainKinematics solveKinematics(const std::vector<std::string>& body_names,
                                const std::vector<SpeedConstraint>& constraints, int input_body,
                                const std::string& input_key);

}  // namespace geardyn

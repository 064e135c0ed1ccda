#pragma once
/// \file
/// Rao's 4-DOF lateral geared rotor (system/lateral_rotor.h) as the fast path of a gearbox of its
/// form, as the gear-pair model is of a one-mesh train (system/sdof_reduction.h). The gearbox is
/// the one `geardyn rotor --print-gearbox` writes (config/rotor_gearbox.h; docs/theory/
/// lateral_rotor.md, "The gearbox it is"): planar DOFs, two rigid shafts (pinion = the operating
/// input, gear = the output) tied by a gear ratio −t_p/t_g and nothing else torsionally, each held
/// to the housing by an isotropic spring (k_s, c_s), the thesis's mesh as an isotropic spring
/// between them (k_m, c_m in y and z), and as excitations:
///
///   - on the mesh spring, referred to the pinion: the mean TE e_m (mean_y = mean_z) and its
///     harmonics at orders i t_p, e_{x,i} sin(i ω_e t + ϕ_{x,i}) = cos(· + ϕ_{x,i} − 90°) in y and
///     the e_y ones in z (eqs. 2.8–2.9);
///   - the pinion runout −w_p at order 1 of the pinion on the mesh spring and on the pinion's
///     spring, e_p (cos(ϕ_p + 180°), cos(ϕ_p − 90°)) in (y, z), with the unbalance m₁ e_p at
///     phase −ϕ_p;
///   - the gear runout +w_g on the mesh spring, e_g (cos ϕ_g, cos(ϕ_g − 90°)), −w_g on the gear's
///     spring, e_g (cos(ϕ_g + 180°), cos(ϕ_g + 90°)), with the unbalance m₂ e_g at phase ϕ_g;
///   - gravity g along −z (the thesis's −y); the pinion turning about −x at N_p.
///
/// Excitations of one spring at one order of one shaft are summed (a user may split or merge the
/// tables), so any gearbox of this form reduces, whatever its names. A runout acts in three places
/// in the model (eq. 2.3 and the energies 2.14–2.16): the three must describe one offset, to
/// 1e-9 of its size, or the gearbox is not of this form. The teeth come from the TE orders and the
/// ratio (t_p the smallest TE order; without TE orders, the smallest integers of the ratio). A TE
/// whose amplitudes are all zero states t_p only (the writer's form of a rotor without TE
/// harmonics): the rotor has no harmonics then.

#include <string>

#include "geardyn/system/gear_train.h"
#include "geardyn/system/lateral_rotor.h"

namespace geardyn {

/// Why `train` is not of the lateral rotor's form (empty: it is), naming the gearbox key.
std::string lateralRotorReductionObstacle(const GearTrainSpec& train);

/// The lateral rotor of a gearbox of its form; throws InputError naming what stands in the way
/// (lateralRotorReductionObstacle). Inverse of config::lateralRotorGearTrain to round-off.
LateralRotorSpec lateralRotorReduction(const GearTrainSpec& train);

}  // namespace geardyn

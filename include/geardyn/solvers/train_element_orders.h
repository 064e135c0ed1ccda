#pragma once
/// \file
/// The force an element (a bearing, a coupling) transmits at one harmonic of a train's
/// common-period steady state (train_response.h), straight from its coefficients: with
/// q(t) = Re[X_0 + 2 Σ_{h≥1} X_h e^{i h ω₀ t}] and the element's force k J q[dofs] (its spring
/// force; TrainElement), harmonic h of the force is F_h = 2 k J X_h[dofs] (h ≥ 1), and its
/// amplitude the norm over the force rows (the moment rows left out: they are N m):
/// |F_h| = sqrt(Σ_rows |F_h,row|²) [N], the length of the force vector's harmonic (for a bearing,
/// the radial force of that order an accelerometer on its seat would see, as (y, z) amplitudes
/// combined). Gear whine reaches the housing through these: per mesh order l of mesh m the
/// harmonic is h = l × the mesh's multiple of the base frequency.

#include "geardyn/solvers/train_response.h"
#include "geardyn/system/gear_train_model.h"

namespace geardyn {

/// |F_h| of `element` [N] at harmonic h (1..state.harmonics) of `state`.
double elementForceHarmonic(const TrainElement& element, const TrainSteadyState& state, int h);

}  // namespace geardyn

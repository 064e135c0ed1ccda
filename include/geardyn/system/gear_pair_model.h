#pragma once
/// \file
/// Single-degree-of-freedom gear pair along the line of action (Gelman et al. 2005, eq. before
/// (1); contact laws after Saletti et al. 2025):
///
///   m x″ + c (x′ − e′(t)) + k(t) g(x − e(t)) = F + Σ f_j cos(ω_j t + ψ_j),
///
/// x the dynamic transmission error [m], e(t) the static transmission error / gear error,
/// k(t) = k(φ(t)) the mesh stiffness at mesh phase φ = f_m t, and g the contact law of the
/// relative deflection y = x − e. In Gelman's nondimensional form (eqs. 2–3) the same equation
/// holds with m = 1, c = 2ζ, k̄ = 1, F = a and time t₁ = ω_n t.
///
/// The model knows nothing of solvers; it exposes the forces and their Jacobian.

#include <memory>
#include <string>
#include <vector>

#include "geardyn/models/mesh_contact_elements.h"
#include "geardyn/models/transmission_error.h"
#include "geardyn/stiffness/mesh_stiffness.h"

namespace geardyn {

/// The contact law g(y) of the mesh.
enum class ContactLaw {
  kLinear,    ///< g(y) = y (teeth never separate)
  kOneSided,  ///< g(y) = y for y > 0, 0 otherwise (contact loss, no back-side contact)
  kBacklash,  ///< g(y) = y − b (y > b), 0 (|y| <= b), y + b (y < −b): half clearance b
};

/// An extra harmonic force f cos(ω t + ψ) [N, rad/s, rad].
struct HarmonicForce {
  double amplitude = 0.0;
  double angular_frequency = 0.0;
  double phase = 0.0;
};

struct GearPairModelSpec {
  double mass = 0.0;        ///< equivalent mass m = I₁I₂/(I₁R₂² + I₂R₁²) [kg]
  double damping = 0.0;     ///< c [N s/m]
  double mean_force = 0.0;  ///< F = T₁/R₁ [N]
  ContactLaw contact = ContactLaw::kLinear;
  double backlash = 0.0;  ///< half clearance b [m] (kBacklash)
  std::shared_ptr<const MeshStiffness> stiffness;
  double mesh_frequency = 0.0;           ///< f_m: mesh periods per unit time [Hz]
  double initial_phase = 0.0;            ///< mesh phase at t = 0 [mesh periods]
  TransmissionError transmission_error;  ///< e(φ) [m]
  std::vector<HarmonicForce> extra_forces;
  /// Contact elements: when given, the mesh force is Σ_j k_j max(0, y − g_j) and `contact` is
  /// not used; `stiffness` stays the nominal k(φ) (for scales, k̄ and the linear start).
  std::shared_ptr<const MeshContactElements> contact_elements;
};

/// Equivalent mass of two gears on the line of action: I₁I₂ / (I₁R₂² + I₂R₁²) [kg] for polar
/// inertias [kg m²] and base radii [m].
double equivalentMass(double inertia1, double base_radius1, double inertia2, double base_radius2);

class GearPairModel {
 public:
  /// Validates the data (positive mass, non-negative damping, finite values, b >= 0).
  explicit GearPairModel(GearPairModelSpec spec);

  /// The data the model was built from (to derive a variant, e.g. at another speed).
  const GearPairModelSpec& spec() const noexcept { return spec_; }
  double mass() const noexcept { return spec_.mass; }
  double damping() const noexcept { return spec_.damping; }
  double meanForce() const noexcept { return spec_.mean_force; }
  ContactLaw contact() const noexcept { return spec_.contact; }
  double backlash() const noexcept { return spec_.backlash; }
  double meshFrequency() const noexcept { return spec_.mesh_frequency; }
  const MeshStiffness& meshStiffness() const noexcept { return *spec_.stiffness; }
  const TransmissionError& transmissionError() const noexcept { return spec_.transmission_error; }

  double meshPhase(double t) const noexcept {
    return spec_.initial_phase + spec_.mesh_frequency * t;
  }
  double stiffness(double t) const { return spec_.stiffness->stiffness(meshPhase(t)); }
  double error(double t) const { return spec_.transmission_error.value(meshPhase(t)); }
  double errorRate(double t) const {
    return spec_.transmission_error.derivative(meshPhase(t)) * spec_.mesh_frequency;
  }

  /// The contact law g(y) and, if slope != nullptr, dg/dy.
  double contactLaw(double y, double* slope = nullptr) const noexcept;

  /// The elastic mesh force k(t) g(x − e(t)) [N]; its derivative with respect to x in
  /// *dforce_dx if given.
  double meshForce(double t, double x, double* dforce_dx = nullptr) const;

  bool hasContactElements() const noexcept { return spec_.contact_elements != nullptr; }
  const MeshContactElements* contactElements() const noexcept {
    return spec_.contact_elements.get();
  }

  /// Everything on the right-hand side that does not depend on the state:
  /// F + c e′(t) + Σ f_j cos(ω_j t + ψ_j) [N].
  double externalForce(double t) const;

  /// Acceleration x″ for the state (x, v) at t [m/s²].
  double acceleration(double t, double x, double v) const;

 private:
  GearPairModelSpec spec_;
};

// Inline: it is the inner loop of the AFT (harmonic_balance.cpp) and of the integrators.
inline double GearPairModel::contactLaw(double y, double* slope) const noexcept {
  switch (spec_.contact) {
    case ContactLaw::kLinear:
      if (slope) *slope = 1.0;
      return y;
    case ContactLaw::kOneSided:
      if (slope) *slope = y > 0.0 ? 1.0 : 0.0;
      return y > 0.0 ? y : 0.0;
    case ContactLaw::kBacklash: {
      const double b = spec_.backlash;
      if (y > b) {
        if (slope) *slope = 1.0;
        return y - b;
      }
      if (y < -b) {
        if (slope) *slope = 1.0;
        return y + b;
      }
      if (slope) *slope = 0.0;
      return 0.0;
    }
  }
  return y;
}

}  // namespace geardyn

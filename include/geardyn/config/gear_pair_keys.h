#pragma once
/// \file
/// The one reading of a gear-pair file (`simulate`, `hbm`, `stats`; issue #31): its [model],
/// [model.stiffness], [model.transmission_error], [excitation] and optional [pinion], [gear],
/// [pair], read in named steps into the quantities the gearbox translation writes
/// (config/gear_pair_gearbox.h). Nothing here builds the gear-pair model: the commands run on
/// the reduction of the translated gearbox (system/sdof_reduction.h).

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "geardyn/config/config.h"
#include "geardyn/geometry/gear_pair.h"
#include "geardyn/stiffness/mesh_stiffness.h"
#include "geardyn/system/gear_pair_model.h"

namespace geardyn::config {

/// The loaded tooth contact linearised about the mean force (model.stiffness.type = "ltca"):
/// its tangent stiffness K(φ) and error E(φ) = δ − F/K tabulated at its positions.
struct LinearisedContactTables {
  std::vector<double> phases;   ///< mesh phases in [0, 1)
  std::vector<double> tangent;  ///< K [N/m]
  std::vector<double> error;    ///< E [m]
  double contact_ratio = 0.0;   ///< of the loaded contact's stiffness
};

/// What a gear-pair file says, in the gear-pair model's (transverse) terms.
struct GearPairKeys {
  bool nondimensional = false;
  std::optional<GearPair> pair;     ///< [pinion], [gear], [pair] when given
  double mass = 0.0;                ///< equivalent mass m_e [kg] (1 when nondimensional)
  double mean_force = 0.0;          ///< F = T₁/R₁ [N]
  double pinion_base_radius = 0.0;  ///< R₁ [m] when given or from the pair (0: not known)
  double mesh_frequency = 0.0;    ///< f_m [Hz] (Ω/2π when nondimensional; 0: left to the caller)
  double initial_phase = 0.0;     ///< mesh phase at t = 0 [mesh periods]
  std::optional<double> damping;  ///< c [N s/m] when given
  double damping_ratio = 0.0;     ///< ζ when c is not given
  ContactLaw contact = ContactLaw::kLinear;
  double backlash = 0.0;  ///< full normal clearance j [m] (contact = backlash)
  /// The stiffness given as numbers (fourier, step, gear_pair_contacts); null when it is
  /// computed from the gears (potential_energy, api, iso6336, ltca, gear_pair_ltca).
  std::shared_ptr<const MeshStiffness> numeric_stiffness;
  std::optional<LinearisedContactTables> linearised;  ///< model.stiffness.type = "ltca"
  bool tooth_pairs = false;  ///< model.type = "gear_pair_ltca": tooth-pair contact elements
  TransmissionError error;   ///< the file's series, rectangular wave and table [m]
  std::vector<HarmonicForce> extra_forces;
  std::vector<std::string> warnings;  ///< about the keys (the model's own come after reduction)
};

/// Reads the file's keys (InputError naming the key, the value and what is allowed).
/// `require_speed` false: [excitation] may be left out (harmonic balance sweeps the frequency).
GearPairKeys readGearPairKeys(const Config& config, bool require_speed);

/// The gear-pair model assembled from the keys directly (the stiffness model named by
/// model.stiffness.type computed from the gears, for gear_pair_ltca with the tooth-pair contact
/// elements; c = 2ζ√(k̄ m)): without the gearbox: the independent check of the
/// translation and reduction (tests/config/gear_pair_gearbox_test.cpp). Appends the stiffness
/// model's warnings.
GearPairModelSpec directGearPairModel(const Config& config, const GearPairKeys& keys,
                                      std::vector<std::string>& warnings);

}  // namespace geardyn::config

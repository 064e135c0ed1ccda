#pragma once
/// \file
/// The gearbox a gear-pair file is (issue #31): the [model] of `simulate`, `hbm` and `stats`
/// (with its [model.stiffness], [model.transmission_error], [excitation] and optional [pinion],
/// [gear], [pair]) translated into gearbox TOML — two rigid shafts with torsional DOFs, one
/// external spur mesh — that config::gearboxSchema() reads and `geardyn train` analyses. The
/// gear-pair commands read the file once (config/gear_pair_keys.h), translate it and reduce the
/// gearbox (gearPairFromGearbox): the
/// single-degree-of-freedom model is the one-pair train's fast path (system/sdof_reduction.h).

#include <string>

#include "geardyn/config/config.h"
#include "geardyn/config/gear_pair_keys.h"
#include "geardyn/config/simulate_config.h"
#include "geardyn/system/gear_pair_model.h"

namespace geardyn::config {

/// The gearbox TOML text of the keys read from `config`: the equivalent mass as the two
/// shafts' polar inertias I = 2 m_e r_b² (gear bodies off), the mean force as the input torque
/// F r_b, the mesh frequency as the pinion speed 60 f_m / z [rpm], the stiffness, damping (the
/// dashpot c [N s/m] or the ratio ζ), transmission error and contact law of the mesh
/// (backlash: the gearbox's full normal clearance j); a helical pair's mesh has
/// stiffness_plane = "transverse" (the file's k, c, e, j are transverse). A file without gear
/// geometry gets a nominal spur pair (z = 25, m_n = 3 mm, α_n = 20°, b = 20 mm, ratio 1); its
/// comments say so. Doubles are written in their shortest round-trip form. Requires an empty
/// obstacle; the extra harmonic forces (model.extra_force_*) are not in it.
std::string gearPairGearboxToml(const Config& config, const GearPairKeys& keys);

/// `geardyn simulate|hbm|stats FILE --print-gearbox`: the translated gearbox text. InputError
/// naming the key when the file has extra harmonic forces (no gearbox form yet) or holds no
/// gear-pair model (stats with source = "moments" or "csv").
std::string gearPairGearbox(const Config& config);

/// The gear-pair model of a gearbox text: read with gearboxSchema(), assembled as a train and
/// reduced (sdofReduction). `source` names the text in messages; `warnings` (optional) gets
/// the stiffness models' warnings.
GearPairModelSpec gearPairFromGearbox(const std::string& toml, const std::string& source,
                                      std::vector<std::string>* warnings = nullptr);

}  // namespace geardyn::config

#pragma once
/// \file
/// The gearbox a finite-element geared rotor file is (issue #31): a `geardyn rotor` file with
/// `[model] type = "fe_geared_rotor"` (fe_rotor_config.h, Visnadi & de Castro 2021 §3)
/// translated into gearbox description text (gearbox_config.h) — full DOFs, the two shafts
/// flexible with one section per element and their β as stiffness_proportional_damping, the
/// bearings and disks (the gear bodies among them) at their nodes' positions, one mesh with the
/// file's stiffness model and [mesh_stiffness.<model>] options, dashpot and transmission error,
/// the line of action where [mesh] puts it, and the operating point (speed, torque at the drive
/// and load nodes). Doubles are printed so that they read back exactly (fmt "{}").
///
/// The unbalances become the gearbox's [unbalances.<shaft>_unbalance<i>]. What does not
/// translate is refused with an InputError naming the key: a helical pair without model.axial
/// (the FE rotor holds the axial DOFs the helical mesh loads; a gearbox keeps them) and
/// pair.driver = "gear"; model.contact_point = "base_tangent_points" with a helical pair is
/// refused by every analysis (feRotorFromConfig: the gearbox mesh acts at one point). Gravity is
/// the gearbox's, which weighs the shafts as well as the disks (docs/guide/fe_rotor.md, "Which
/// gearbox this file is").

#include <optional>
#include <string>
#include <vector>

#include "geardyn/config/config.h"
#include "geardyn/system/gear_train.h"

namespace geardyn::config {

/// The gearbox description text of an FE rotor configuration (feRotorSchema()); it is accepted
/// by gearboxSchema() and describes the train of feRotorFromConfig.
std::string feRotorGearboxToml(const Config& config);

/// `rotor FILE --print-gearbox`: the gearbox text when `config` is an FE rotor file ([model]
/// type = "fe_geared_rotor"), nullopt otherwise.
std::optional<std::string> feRotorGearbox(const Config& config);

/// The gear train of an FE rotor configuration, read from its translated text by the gearbox
/// reader (gearTrainFromConfig); the reader's warnings are appended.
GearTrainSpec feRotorGearTrain(const Config& config, std::vector<std::string>& warnings);

}  // namespace geardyn::config

#pragma once
/// \file
/// Configuration of `geardyn rotor` with `[model] type = "fe_geared_rotor"` (issue #8, Visnadi
/// 2021 §3–4): the shafts, bearings, disks and unbalances, the gear pair and its mesh-stiffness
/// model, loads, speed profile and the analyses (time, modal, campbell, compare_stiffness).

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "geardyn/config/config.h"
#include "geardyn/config/config_schema.h"
#include "geardyn/solvers/fe_rotor_response.h"
#include "geardyn/system/fe_rotor_model.h"
#include "geardyn/system/gear_train.h"

namespace geardyn::config {

/// The schema of the FE geared rotor (`geardyn rotor` when [model] type = "fe_geared_rotor").
ConfigSchema feRotorSchema();

/// The string at a dotted key of a TOML file without validating it (empty when absent or not a
/// string): how `geardyn rotor` picks its schema from [model] type.
std::string peekConfigString(const std::filesystem::path& file, const std::string& key);

/// The gearbox a configuration describes and the file's numbering of it, with the
/// mesh-stiffness model `stiffness_model` (a name of [mesh_stiffness] models,
/// "fourier_beam_mean" for the one-term sinusoid around the beam model's mean (Visnadi Fig. 7),
/// or "" for [mesh] stiffness): two flexible shafts (one section per element, their β as
/// stiffness_proportional_damping), the bearings, disks (the gear bodies among them) and
/// unbalances at their nodes' positions, one mesh where [mesh] puts the line of action, the
/// drive and load torques at their nodes. InputErrors name the file's keys.
struct FeRotorBuild {
  GearTrainSpec train;
  FeRotorLayout layout;
  std::string stiffness_model;
  std::vector<std::string> warnings;
};
FeRotorBuild feRotorFromConfig(const Config& config, const std::string& stiffness_model = "");

/// FeRotorModel of feRotorFromConfig.
FeRotorModel feRotorModelFromConfig(const Config& config, const std::string& stiffness_model = "");

/// The Newmark options of [time]; checks the record length with checkRecordLength.
FeTimeOptions feTimeOptionsFromConfig(const Config& config, const FeRotorModel& model);

/// Refuses (InputError naming time.duration, the mesh period and the minimum) a record too short
/// for its post-processing, before anything runs: at constant speed > 0 it must hold the steady
/// window of time.window_mesh_periods mesh periods, along a run-up one time.runup_window.
void checkRecordLength(const Config& config, const FeRotorModel& model, double duration);

/// The output channels of [time] outputs ("pinion_shaft.1.uy", …) as active DOF indices;
/// default: the gear nodes' u_y, u_z and the first bearing node of each shaft (Visnadi Figs.
/// 3–6). InputError naming time.outputs for an unknown or removed DOF.
std::vector<int> feOutputChannels(const Config& config, const FeRotorModel& model);

/// Pinion speeds [rad/s] of [campbell].
std::vector<double> campbellSpeedsFromConfig(const Config& config);

}  // namespace geardyn::config

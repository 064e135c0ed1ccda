#pragma once
/// \file
/// The modes of a `rotor` file with [model] type = "fe_geared_rotor" come from the gear train's
/// modal solver (train_modal.h, issue #31): the file is translated into its gearbox
/// (config/fe_rotor_gearbox.h), read by the gearbox reader and assembled as a GearTrainModel;
/// the train's modes and Campbell diagram are reported on the FE rotor's DOFs and order lines.
/// `geardyn rotor` and the Python `FeGearedRotor.modal` / `.campbell` use these.

#include <memory>
#include <string>
#include <vector>

#include "geardyn/config/config.h"
#include "geardyn/solvers/train_modal.h"
#include "geardyn/system/fe_rotor_model.h"
#include "geardyn/system/gear_train_model.h"

namespace geardyn::analysis {

/// The train of an FE rotor file and where each of the FE rotor's active DOFs is in it.
struct FeRotorTrain {
  std::unique_ptr<GearTrainModel> model;
  std::vector<int> train_dof;  ///< train DOF of each FeRotorModel DOF
  /// The file has no axial DOFs (model.axial = false, a spur pair: the train's axial motion is
  /// uncoupled): its purely axial modes are not the file's and are left out.
  bool without_axial = false;
};

/// Builds the train of `config` (unbalances omitted: the modes do not depend on them) and maps
/// `fe`'s DOFs into it; the gearbox reader's warnings are appended to `warnings`.
FeRotorTrain feRotorTrain(const config::Config& config, const FeRotorModel& fe,
                          std::vector<std::string>& warnings);

/// The lowest `modes` elastic modes at pinion speed Ω [rad/s] (modes more damped than
/// `max_damping_ratio` skipped), ascending in frequency.
std::vector<TrainMode> feRotorModes(const FeRotorTrain& train, double pinion_speed, int modes,
                                    double max_damping_ratio);

/// The FE rotor's order lines: 1× pinion, 1× gear (z_p/z_g) and the mesh (z_p), as slopes.
std::vector<TrainOrderLine> feRotorOrderLines(const FeRotorModel& fe);

/// The Campbell diagram over pinion speeds [rad/s] with `modes` tracked modes.
TrainCampbell feRotorCampbell(const FeRotorTrain& train, const FeRotorModel& fe,
                              const std::vector<double>& speeds, int modes,
                              double max_damping_ratio);

}  // namespace geardyn::analysis

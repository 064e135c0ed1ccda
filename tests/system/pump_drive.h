#pragma once
/// \file
/// A gearbox as a user writes it from the guide, for the tests and benchmarks of Hill's method
/// below the frequency its harmonics resolve (issue 39), and reading gearbox text into a spec.

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "geardyn/analysis/analyses.h"
#include "geardyn/config/gearbox_config.h"

namespace geardyn::testing {

/// The gear train of a TOML gearbox file's text (written to a temporary file `name`, read as
/// `geardyn train` reads it).
inline GearTrainSpec specOf(const std::string& text, const std::string& name) {
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / (std::to_string(::getpid()) + "_" + name);
  std::ofstream(file) << text;
  std::vector<std::string> warnings;
  const analysis::TrainInputs inputs = analysis::loadTrainInputs(file, {});
  std::filesystem::remove(file);
  return config::gearTrainFromConfig(inputs.gearbox, warnings);
}

/// A 29/47 spur pump drive, planar (its shafts' lateral modes on 3e8 and 5e8 N/m bearings
/// damped by 2e3 N s/m), 3 µm backlash and two TE orders, as a user writes it from the guide.
inline GearTrainSpec pumpDrive() {
  return specOf(
      "[gearbox]\nname = \"pump drive\"\ndofs = \"planar\"\n"
      "[operating_point]\ninput = \"motor\"\noutput = \"pump\"\nspeed_rpm = 2900.0\n"
      "torque = 60.0\n"
      "[shafts.motor]\nsection_lengths = [0.2]\nouter_diameters = [0.035]\n"
      "[shafts.pump]\nsection_lengths = [0.25]\nouter_diameters = [0.045]\n"
      "[gears.pinion]\nshaft = \"motor\"\nteeth = 29\nmodule = 2.5e-3\nface_width = 0.025\n"
      "[gears.wheel]\nshaft = \"pump\"\nteeth = 47\nmodule = 2.5e-3\nface_width = 0.025\n"
      "[meshes.stage]\ngears = [\"pinion\", \"wheel\"]\ndamping_ratio = 0.04\n"
      "backlash = 3e-6\nte_amplitudes = [4e-6, 1e-6]\n"
      "[bearings.motor_bearing]\nshaft = \"motor\"\nkyy = 3e8\nkzz = 3e8\ncyy = 2e3\n"
      "czz = 2e3\n"
      "[bearings.pump_bearing]\nshaft = \"pump\"\nkyy = 5e8\nkzz = 5e8\ncyy = 2e3\n"
      "czz = 2e3\n",
      "geardyn_hill_pump_drive.toml");
}

}  // namespace geardyn::testing

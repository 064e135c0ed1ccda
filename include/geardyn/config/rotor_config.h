#pragma once
/// \file
/// Configuration and result tables of `geardyn rotor` (the lateral geared rotor of Rao 2023)
/// and `geardyn spectrum` (full spectra of probe records): schemas, the model and options built
/// from a configuration, and the whirl-component tables both commands write.

#include <array>
#include <nlohmann/json.hpp>
#include <vector>

#include "geardyn/config/config.h"
#include "geardyn/config/config_schema.h"
#include "geardyn/io/csv_table.h"
#include "geardyn/signal/gear_whirl.h"
#include "geardyn/solvers/rotor_response.h"
#include "geardyn/solvers/train_periodic_record.h"
#include "geardyn/system/lateral_rotor.h"

namespace geardyn::config {

/// Adds [rotor]: masses, shaft stiffness and damping, gravity, teeth (and the pinion speed).
void addRotorSection(ConfigSchema& schema, bool with_speed);
/// The rotor's known physical data from [rotor] (DTE fields left at their defaults; the pinion
/// speed only when the section has it).
LateralRotorSpec knownRotorFromConfig(const Config& config);

/// `geardyn rotor`: [rotor], [mesh], [runout], [time], [frequency], [spectrum], [measurement],
/// [study], [output].
ConfigSchema rotorSchema();
/// `geardyn spectrum`: [input], [gears], [keyphasor], [spectrum], [output].
ConfigSchema spectrumSchema();

LateralRotorSpec lateralRotorSpecFromConfig(const Config& config);
TrainRecordOptions rotorTimeOptionsFromConfig(const Config& config);
GearPairSpectrumOptions gearPairSpectrumOptionsFromConfig(const Config& config);

}  // namespace geardyn::config

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
/// Samples per period of the highest mesh harmonic that the default time.samples gives at least:
/// above Nyquist's 2 with a 10 % margin, so a 1.25 × wide spectrum view still fits below it.
inline constexpr double kRotorSamplesPerHighestPeriod = 2.2;
/// time.samples as given, or derived from the rotor `spec` (issue 31 follow-up: a fixed 2^15
/// aliased any rig faster than the thesis's): the smallest power of two (at most 2e8) with
/// kRotorSamplesPerHighestPeriod samples per period of the highest mesh harmonic h t_p N_p over
/// time.duration. 2^15 for the thesis's rig (Table 4.1: 880 Hz over 15 s needs 29 040).
long long rotorTimeSamples(const Config& config, const LateralRotorSpec& spec);
/// [time] of `geardyn rotor`, time.samples by rotorTimeSamples for `spec`.
TrainRecordOptions rotorTimeOptionsFromConfig(const Config& config, const LateralRotorSpec& spec);
GearPairSpectrumOptions gearPairSpectrumOptionsFromConfig(const Config& config);

}  // namespace geardyn::config

#pragma once
/// \file
/// The gearbox file's `[housing]` (issue #37): a flexible housing from a CalculiX deck (or K and
/// M in MatrixMarket with the deck's nodes and sets), reduced by Craig–Bampton
/// (config/housing_source.h, cached next to the deck) and joined to the train at its bearings
/// (system/train_housing.h). Every bearing from a shaft to the housing sits in the deck's node
/// set of its own name (`*NSET, NSET=<BEARING NAME>`, names compared without case) or in the set
/// `housing.seats.<bearing>` names.

#include <string>
#include <vector>

#include "geardyn/config/config.h"
#include "geardyn/config/config_schema.h"
#include "geardyn/config/housing_source.h"
#include "geardyn/system/gear_train.h"
#include "geardyn/system/train_housing.h"

namespace geardyn::config {

/// Declares [housing] and [housing.mounts.<set>] (gearbox schema).
void addHousingKeys(ConfigSchema& schema);

/// The gearbox has a [housing] with a deck.
bool hasHousing(const Config& gearbox);

/// [housing] as a HousingSource (paths relative to the gearbox file) and the bearing → seat
/// links. The cut-off is housing.cutoff_hz, else `default_cutoff_hz` [Hz] (the caller's 2 × the
/// highest frequency its analyses ask for). InputError naming the key or set: units not
/// declared, a seat set that names no bearing, a bearing to the housing without a seat.
HousingSource housingSourceFromConfig(const Config& gearbox, const GearTrainSpec& spec,
                                      double default_cutoff_hz, std::vector<HousingLink>& links);

/// Loads (or reads from the cache) the housing of `gearbox` and puts it into spec.housing;
/// `memory_limit` [B] refuses a mesh too big before ccx runs. Returns a line for the report
/// (modes kept, first mode, cache file), "" without a housing.
std::string attachHousing(const Config& gearbox, GearTrainSpec& spec, double default_cutoff_hz,
                          double memory_limit);

}  // namespace geardyn::config

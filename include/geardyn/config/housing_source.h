#pragma once
/// \file
/// A housing from its CalculiX deck to its Craig–Bampton model, cached (issue #37): the deck is
/// read (nodes, sets), checked against the memory limit, assembled by ccx, scaled to SI and
/// reduced (models/housing_superelement.h). The reduced model is stored next to the deck as
/// `<deck>.reduced-<hash>.bin`, the hash (FNV-1a, 64 bit) over the deck's bytes (not those of
/// files it *INCLUDEs: edit the deck, or delete the cache, when only those change), the units, the
/// seat and point set names, the cut-off and the mode count; a changed deck or setting gives
/// another hash and is reduced again. A cache file that cannot be written (a read-only folder) is
/// skipped with the reduction kept in memory.

#include <string>
#include <utility>
#include <vector>

#include "geardyn/models/housing_superelement.h"

namespace geardyn::config {

/// What the [housing] section names.
struct HousingSource {
  std::string deck;                 ///< the CalculiX deck (.inp)
  std::string units = "si";         ///< "si" or "mm_t_s" (FeUnits)
  std::vector<std::string> seats;   ///< seat node set names (the deck's *NSET names)
  std::vector<std::string> points;  ///< response point node set names
  CraigBamptonOptions reduction;    ///< cut-off or mode count; key "housing"
  /// Mounting points held rigidly in x, y, z (node set names; a `*BOUNDARY` added to ccx's job).
  std::vector<std::string> fixed_mounts;
  /// Elastic mounting points: a node set and its total stiffness [N/m] in each of x, y, z, spread
  /// evenly over the set's nodes (springs to the ground added to the assembled K).
  std::vector<std::pair<std::string, double>> elastic_mounts;
  /// K and M from another tool (MatrixMarket) with their `node.direction` DOF map, instead of
  /// ccx's assembly; the deck then only gives the nodes and node sets. Empty: ccx.
  std::string stiffness_matrix, mass_matrix, dof_map;
  double memory_limit_bytes = 0.0;  ///< > 0: refuse a larger mesh before ccx runs
};

/// The result and where it came from.
struct LoadedHousing {
  ReducedHousing housing;
  std::string cache_file;  ///< the cache file used or written ("" when none could be written)
  bool from_cache = false;
  double assembly_s = 0.0;  ///< ccx's run (or reading the matrices) [s]; 0 from the cache
};

/// Loads the cached reduction of `source`, or assembles, reduces and caches it. InputError
/// naming "housing.deck" (deck, ccx), "housing.units", "housing.seats"/"housing.points" (a set the
/// deck does not define, with did-you-mean), "housing.cutoff_hz" (no mode below it).
LoadedHousing loadHousing(const HousingSource& source);

/// The cache key of `source` (hex): what loadHousing names its cache file by.
std::string housingCacheKey(const HousingSource& source);

}  // namespace geardyn::config

#pragma once
/// \file
/// Gear trains whose meshes are tooth-pair contact elements (issue 17: contact = "tooth_pairs"):
/// the nonlinear fixtures of nonlinear_sample_trains.h with each fixed-axis mesh's k(φ) the
/// potential-energy stiffness of its pair and its nonlinear force the elements of the pair's
/// loaded tooth contact, a long linear tip relief designed for a load as the gaps.

#include <memory>

#include "geardyn/contact/loaded_contact.h"
#include "geardyn/contact/profile_modification.h"
#include "geardyn/geometry/gear_pair.h"
#include "geardyn/stiffness/potential_energy_stiffness.h"
#include "system/nonlinear_sample_trains.h"

namespace geardyn::testing::nonlinear {

/// The potential-energy stiffness of the external pair (pinion, gear) at its zero-backlash
/// centre distance.
inline std::shared_ptr<const PotentialEnergyMeshStiffness> pairStiffness(GearSpec pinion,
                                                                         GearSpec gear) {
  // The fillet-foundation model needs a bore: 0.3 of the reference diameter where none is set
  // (this copy only; the train's gear bodies keep theirs).
  for (GearSpec* g : {&pinion, &gear}) {
    if (g->bore_diameter <= 0.0) g->bore_diameter = 0.3 * g->teeth * g->normal_module;
  }
  GearPairSpec pair;
  pair.pinion = pinion;
  pair.gear = gear;
  return std::make_shared<const PotentialEnergyMeshStiffness>(GearPair(pair));
}

/// That of the fixed-axis mesh `mesh` of `spec` (pinion: gear a).
inline std::shared_ptr<const PotentialEnergyMeshStiffness> pairStiffness(
    const GearTrainSpec& spec, const TrainMeshSpec& mesh) {
  GearSpec a, b;
  for (const auto& g : spec.gears) {
    if (g.name == mesh.gear_a) a = g.gear;
    if (g.name == mesh.gear_b) b = g.gear;
  }
  return pairStiffness(a, b);
}

/// The tooth-pair contact of a pair: one element per tooth pair (spur: one slice), a long
/// linear tip relief on both gears designed for `design_load` [N] (0: none).
inline TrainMeshContact toothPairs(const std::shared_ptr<const PotentialEnergyMeshStiffness>& k,
                                   double design_load) {
  const PairModifications modifications =
      design_load > 0.0 ? designedTipRelief(*k, design_load, true, ReliefShape::kLinear)
                        : PairModifications{};
  TrainMeshContact c;
  c.law = ContactLaw::kOneSided;
  c.tooth_pairs = std::make_shared<LoadedContactElements>(
      std::make_shared<const LoadedToothContact>(k, modifications, 1));
  return c;
}

/// Every fixed-axis mesh m of `spec` with its pair's potential-energy k(φ) and tooth pairs with
/// a long tip relief designed for design_loads[m] [N] (0: no relief).
inline GearTrainSpec withToothPairs(GearTrainSpec spec, const std::vector<double>& design_loads) {
  for (std::size_t m = 0; m < spec.meshes.size(); ++m) {
    auto k = pairStiffness(spec, spec.meshes[m]);
    spec.meshes[m].stiffness = k;
    spec.meshes[m].contact = toothPairs(k, design_loads[m]);
  }
  return spec;
}

}  // namespace geardyn::testing::nonlinear

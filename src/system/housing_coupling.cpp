/// A gear train joined to a reduced housing at its bearings (housing_coupling.h): the model
/// built again with the housing in its spec (train_housing.cpp does the joining).

#include "geardyn/system/housing_coupling.h"

#include <memory>

namespace geardyn {

HousedTrain coupleHousing(const GearTrainModel& model, const ReducedHousing& housing,
                          const std::vector<HousingLink>& links, double input_speed, double beta) {
  GearTrainSpec spec = model.spec();
  auto h = std::make_shared<TrainHousingSpec>();
  h->reduced = housing;
  h->links = links;
  h->stiffness_proportional_damping = beta;
  spec.housing = std::move(h);
  const GearTrainModel housed(std::move(spec));
  HousedTrain out;
  out.housing_first_dof = housed.housingFirstDof();
  out.M = housed.mass();
  out.K = housed.meanStiffnessAt(input_speed);
  out.C = housed.dampingAt(input_speed);
  return out;
}

}  // namespace geardyn

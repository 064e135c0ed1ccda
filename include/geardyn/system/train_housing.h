#pragma once
/// \file
/// A flexible housing in the machine (issue #37): a reduced finite-element housing
/// (models/housing_superelement.h) whose seats carry the gearbox's bearings. GearTrainModel
/// appends the housing's coordinates after the bodies' DOFs (interface DOFs of each seat, then
/// the fixed-interface modal coordinates) and joins each linked bearing between its shaft and
/// its seat instead of the ground (docs/theory/housing_superelement.md §5):
///   d = J q_shaft − J_h q_seat,   J_h: the seat's rigid motion at the bearing point,
/// so the bearing's element gains the seat's six DOFs and its stiffness becomes
/// [J, −J_h]ᵀ k [J, −J_h] (likewise its damping). The housing's own damping is
/// stiffness-proportional, β_h K_h.

#include <string>
#include <vector>

#include "geardyn/models/housing_superelement.h"

namespace geardyn {

/// A bearing of the train and the seat it sits in.
struct HousingLink {
  std::string bearing;  ///< TrainBearingSpec::name
  std::string seat;     ///< ReducedHousing::seats entry
};

/// The housing of a GearTrainSpec (GearTrainSpec::housing).
struct TrainHousingSpec {
  ReducedHousing reduced;          ///< in SI, seats' centres in the gearbox's coordinates
  std::vector<HousingLink> links;  ///< every seat carries at least one bearing
  /// β_h [s]: the housing's damping C_h = β_h K_h.
  double stiffness_proportional_damping = 0.0;
  std::string source;       ///< where it came from (the deck), for reports
  std::string cache_file;   ///< the cache it was read from or written to ("" none)
  bool from_cache = false;  ///< read from the cache (no ccx run, no reduction)
  double assembly_s = 0.0;  ///< ccx's run [s] (0 from the cache); the reduction's in `reduced`
};

/// The seat's rigid motion at r = p − c [m] in the components a bearing element of kind
/// `part` measures ("" lateral (u_y, u_z); ".axial"; ".torsion", ".tilt_y", ".tilt_z"), over
/// the seat's DOFs (u_x, u_y, u_z, θ_x, θ_y, θ_z).
Eigen::Matrix<double, Eigen::Dynamic, 6> seatJacobian(const std::string& part,
                                                      const Eigen::Vector3d& r);

class GearTrainModel;

/// The rows of the bearings joined to the housing, stacked (r rows): their deformation
/// d = J q_t − J_H q_h on the train's DOFs q_t and the housing's q_h, with each row's stiffness
/// and damping (block diagonal, the damping with the gearbox's β k). What the forced response's
/// exact condensation of the housing needs (solvers/detail/housing_condensation.h).
struct HousingLinkTerms {
  Eigen::MatrixXd J;   ///< r × n_t
  Eigen::MatrixXd JH;  ///< r × n_h
  Eigen::MatrixXd k;   ///< r × r [N/m, N m/rad]
  Eigen::MatrixXd c;   ///< r × r [N s/m, N m s/rad]
};
HousingLinkTerms housingLinkTerms(const GearTrainModel& model);

/// The name of the housing's DOF i (0: its first): "housing.<seat>.x" … ".theta_z", then
/// "housing.mode<k>" (k from 1).
std::string housingDofName(const ReducedHousing& housing, int i);

}  // namespace geardyn

#pragma once
/// \file
/// Internals shared by the gear-train assembly files (gear_train_model.cpp, train_meshes.cpp,
/// train_loads.cpp): references by name, the kinematics of material points, frames.

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "geardyn/system/gear_train_model.h"

namespace geardyn::detail {

/// The in-plane displacement (y, z) of a material point: J q[dofs] [m].
struct PointJacobian {
  std::vector<int> dofs;
  Eigen::Matrix<double, 2, Eigen::Dynamic> J;
};

/// A solid-of-revolution section of a shaft: start along the shaft, length, radii [m], mass [kg].
struct ShaftSection {
  double start = 0, length = 0, outer_radius = 0, inner_radius = 0, mass = 0;
};
/// The sections of a shaft (InputError naming the key when a value is not physical).
std::vector<ShaftSection> shaftSections(const TrainShaftSpec& shaft);
/// Σ section lengths [m] (0 without sections).
double shaftLength(const TrainShaftSpec& shaft);

/// Mass, polar inertia and the axial distribution of a rigid body's parts, for its mass centre
/// and its diametral inertia about it (positions along the shaft [m]).
struct MassSum {
  double mass = 0, first_moment = 0, polar_inertia = 0, diametral_about_origin = 0;
  void add(double m, double polar, double diametral, double x);
  double centre() const;
  double diametralAboutCentre() const;
};
void addSectionMasses(const std::vector<ShaftSection>& sections, MassSum& sum);

/// The index in spec.shafts of the shaft called `name`; InputError naming `key` otherwise.
int shaftIndexOf(const GearTrainSpec& spec, const std::string& name, const std::string& key);
/// The body of the shaft called `name` at `position` along it (GearTrainModel::bodyAt).
int bodyAtOf(const GearTrainModel& model, const std::string& name, const std::string& shaft_key,
             double position, const std::string& position_key);
/// The bodies a coupling joins: the end of shaft_a and the start of shaft_b.
std::pair<int, int> couplingBodies(const GearTrainModel& model, const TrainCouplingSpec& c);
/// The bodies the input and output torques act on.
int inputBody(const GearTrainModel& model);
int outputBody(const GearTrainModel& model);

/// The body of the shaft called `name`; InputError naming `key` with a did-you-mean otherwise.
int shaftBodyOf(const GearTrainModel& model, const GearTrainSpec& spec, const std::string& name,
                const std::string& key);
/// The index in spec.gears of the gear called `name`; InputError naming `key` otherwise.
int gearIndexOf(const GearTrainSpec& spec, const std::string& name, const std::string& key);

/// sign × the translation of body b's centre (with full DOFs: of its point `dx` along the axis
/// from the body's reference point, which adds the tilts). A planet with torsional DOFs only rides
/// on its carrier: its centre moves with the carrier's rotation (rigid pin).
PointJacobian translationJacobian(const GearTrainModel& model, int body, double sign,
                                  double dx = 0.0);
/// sign × the displacement of the material point at `point` (y, z) [m] of body b:
/// u + θ × (point − centre).
PointJacobian pointJacobian(const GearTrainModel& model, int body, const Eigen::Vector2d& point,
                            double sign, double dx = 0.0);
/// The sum of several point Jacobians over the union of their DOFs.
void stackJacobians(const std::vector<PointJacobian>& parts, std::vector<int>& dofs,
                    Eigen::MatrixXd& J);

/// A lateral connection between bodies formulated in different rotating frames is refused
/// (it would be time-varying): InputError naming `key`.
void requireSameFrame(const GearTrainModel& model, int a, int b, const std::string& key);

int carrierBody(const GearTrainModel& model, int stage);
double carrierSpeedRatio(const GearTrainModel& model, const GearTrainSpec& spec, int stage);

/// Input and output torques and the planet pins' position errors into F₀; the output torque
/// (lossless: T_out = −T_in Ω_in/Ω_out) [N m].
void applyOperatingLoads(const GearTrainModel& model, const GearTrainSpec& spec,
                         Eigen::VectorXd& F0, double& output_torque);

/// K_Ω (per Ω², [kg]) of planet body `planet` in its carrier frame turning at r_c Ω. A planet's
/// centrifugal load m Ω_c² R is carried by its pin and turns with the carrier, so the
/// centripetal term acts on u_p − θ_c (J R): the planet's translation less the part the
/// carrier's rotation θ_c gives its centre R. With Lin & Parker's −m Ω_c² u_p the stage's
/// rolling motion (no mesh or pin deflects: u_p = θ_c J R) gets the stiffness −Σ m_p Ω_c² R²
/// and diverges at speed; this form keeps it neutral at every speed, as the exact rotating
/// system is, and differs from the expansion about the centrifugally loaded equilibrium by
/// O(m_p Ω_c² / k_pin) (docs/theory/gear_trains.md).
void addPlanetCentripetal(const GearTrainModel& model, int planet, double rc,
                          Eigen::MatrixXd& Komega);

/// InputError unless `value` is finite and ≥ 0 (`unit` for the message).
void requireNonNegative(double value, const std::string& key, const std::string& unit);

}  // namespace geardyn::detail

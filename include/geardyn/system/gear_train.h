#pragma once
/// \file
/// The description of a gear train — any gearbox: shafts, gears on shafts, meshes, bearings,
/// couplings, planetary stages and the operating point — as plain data. It is what a gearbox
/// file (TOML) or a REXS import produces and what tests build in code (Pinocchio's parsers →
/// Model pattern); GearTrainModel (gear_train_model.h) validates it and assembles the machine.
///
/// Frames and conventions. Every shaft turns about an axis parallel to the global x axis; its
/// centre lies in the transverse (y, z) plane. Angles in the transverse plane are measured from
/// +y towards +z (positive about +x). Rotations are positive about +x. Speeds are signed.
/// SI units throughout; angles in radians.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "geardyn/contact/rolling_bearing.h"
#include "geardyn/geometry/gear.h"
#include "geardyn/models/transmission_error.h"
#include "geardyn/stiffness/mesh_stiffness.h"
#include "geardyn/system/gear_pair_model.h"

namespace geardyn {

/// Degrees of freedom of every body: its rotation only, or its rotation and the translation
/// of its centre in the transverse plane (the classic lumped gear model, Lin & Parker 1999).
/// kFull: six per node (axial, two lateral translations, torsion and two tilts), needed for
/// flexible (FE) shafts, helical axial forces and gyroscopic coupling.
enum class TrainDofs { kTorsional, kPlanar, kFull };

/// A rigid body turning about an axis parallel to x: a shaft with what is mounted on it, a
/// carrier, a ring held by the housing. Mass and inertia are its own; the bodies of its gears
/// are added from their geometry unless a gear says otherwise.
struct TrainShaftSpec {
  std::string name;
  double mass = 0.0;           ///< [kg]
  double polar_inertia = 0.0;  ///< about its axis [kg m²]
  /// Solid-of-revolution sections added to mass and inertia: lengths [m], outer and inner
  /// diameters [m] (one value or one per section), density [kg/m³].
  std::vector<double> section_lengths, outer_diameters, inner_diameters;
  double density = 7850.0;
  /// Flexible shaft: the sections become two-node Timoshenko beam elements (6 DOFs per node,
  /// requires TrainDofs::kFull); false: one rigid body.
  bool flexible = false;
  double youngs_modulus = 2.1e11;  ///< [Pa] (flexible shafts)
  double poisson_ratio = 0.3;      ///< [-] (flexible shafts; G = E / (2 (1 + ν)))
  /// Longest beam element [m]: sections longer than this are split evenly (flexible shafts;
  /// absent: one element per section, plus nodes at every gear, bearing and disk position).
  std::optional<double> max_element_length;
  /// Global x of the shaft's first section start [m] (positions along the shaft are measured
  /// from here).
  double axial_offset = 0.0;
  /// About a transverse axis through its mass centre [kg m²] (full DOFs, rigid shafts).
  double diametral_inertia = 0.0;
  /// β_s [s]: material (stiffness-proportional) damping of a flexible shaft's beam elements,
  /// C_e = β_s K_e, beside the gearbox's Rayleigh α M + β K (which also damps bearings and
  /// meshes); Visnadi & de Castro (2021) eq. (10), C = α M + β K_shafts. 0 on a rigid shaft.
  double stiffness_proportional_damping = 0.0;
};

/// A rigid disk (an inertia: flywheel, rotor of a motor, brake disk) on a shaft at an axial
/// position.
struct TrainDiskSpec {
  std::string name;
  std::string shaft;
  double position = 0.0;           ///< along the shaft from its first section start [m]
  double mass = 0.0;               ///< [kg]
  double polar_inertia = 0.0;      ///< about the shaft axis [kg m²]
  double diametral_inertia = 0.0;  ///< about a transverse axis [kg m²]
};

/// A gear on a shaft. `internal` makes it a ring gear (internal teeth, e.g. a planetary ring).
struct TrainGearSpec {
  std::string name;
  std::string shaft;
  GearSpec gear;
  bool internal = false;
  /// Add the gear body's mass and polar inertia (from its geometry) to the shaft.
  bool body = true;
  /// Axial position of the gear's mid-face along its shaft, from the shaft's first section
  /// start [m] (used by flexible shafts and full DOFs).
  double position = 0.0;
};

/// The tooth contact of a mesh (issue 17): kLinear (the teeth never separate: the linear
/// analyses), kOneSided (contact lost when the tooth deformation δ − e falls below 0) or
/// kBacklash (free play −j ≤ δ − e ≤ 0, then contact on the back flank). δ − e = 0 is contact
/// onset on the loaded flank, so a mesh that stays in contact gives the linear results.
///
/// Tooth pairs (`tooth_pairs` given, law kOneSided): the nonlinear analyses take the mesh force
/// as the sum of its tooth-pair contact elements (models/mesh_contact_elements.h), e.g. the
/// slices of the pair's loaded tooth contact with its flank modifications as gaps,
///     f = Σ_j k_j(φ) max(0, δ − e(φ) − g_j(φ)),
/// at the mesh's own phase φ; the mesh's k(φ) stays for the linear analyses and k̄.
struct TrainMeshContact {
  ContactLaw law = ContactLaw::kLinear;
  double backlash = 0.0;  ///< j: normal backlash along the line of action [m] (kBacklash)
  std::shared_ptr<const MeshContactElements> tooth_pairs;  ///< null: k(φ) g(δ − e)
};

/// A mesh between two gears on two shafts with fixed axes (a parallel-axis stage, an idler).
/// Planetary meshes are generated by their stage.
struct TrainMeshSpec {
  std::string name;
  std::string gear_a, gear_b;
  /// Direction from gear a's centre to gear b's centre in the transverse plane [rad].
  double position_angle = 0.0;
  /// Operating centre distance [m]; absent: the zero-backlash distance of the profile shifts.
  std::optional<double> centre_distance;
  /// k(φ) along the line of action [N/m]; built for this pair by the caller (any model).
  std::shared_ptr<const MeshStiffness> stiffness;
  TransmissionError transmission_error;  ///< e(φ) [m]
  double damping_ratio = 0.0;            ///< of the mesh's equivalent oscillator [-]
  /// Mesh phase at t = 0 [mesh periods]; absent: derived by mesh phasing (or 0).
  std::optional<double> phase;
  TrainMeshContact contact;  ///< linear unless given
  /// Mesh dashpot along the line of action [N s/m]; absent: from damping_ratio.
  std::optional<double> damping;
};

/// A linear bearing from a shaft to the housing or to another shaft (e.g. a planet on its pin
/// is generated by the stage). Translational stiffness in y and z with cross terms [N/m],
/// damping [N s/m], and a torsional spring/damper [N m/rad, N m s/rad] (to the housing: the
/// member is held, its speed is 0).
struct TrainBearingSpec {
  std::string name;
  std::string shaft;
  std::string other_shaft;  ///< empty: the housing (ground)
  double kyy = 0, kzz = 0, kyz = 0, kzy = 0;
  double cyy = 0, czz = 0, cyz = 0, czy = 0;
  double k_torsion = 0, c_torsion = 0;
  /// Axial stiffness/damping [N/m, N s/m] and tilt stiffness/damping about the two transverse
  /// axes [N m/rad, N m s/rad] (full DOFs only).
  double k_axial = 0, c_axial = 0, k_tilt = 0, c_tilt = 0;
  /// Axial position along `shaft` and along `other_shaft` from their first section starts [m].
  double position = 0.0, other_position = 0.0;
  /// Radial clearance c [m] (issue 17; planar and full DOFs): the radial stiffness acts only
  /// beyond it, f = k (|u| − c) u/|u| for |u| > c, else 0, on the relative radial displacement
  /// u = (u_y, u_z) (isotropic: needs kyy = kzz, no cross terms). The damping stays linear. Only
  /// the nonlinear analyses see it; the linear ones take the bearing as linear. 0: linear.
  double radial_clearance = 0.0;
  /// A rolling-element bearing from its geometry (issue 35; contact/rolling_bearing.h),
  /// instead of the stiffness keys: nonlinear, coupled over (u_y, u_z, u_x, θ_y, θ_z) of the
  /// shaft relative to the housing or `other_shaft`. The static analysis solves for its
  /// deflection; the linear analyses take it linearised there (GearTrainModel::linearisedAt).
  /// The damping keys still apply; the stiffness keys must be 0.
  std::shared_ptr<const RollingBearing> rolling;
  /// A linearised bearing: its 5×5 tangent stiffness over (u_y, u_z, u_x, θ_y, θ_z) [N/m,
  /// N/rad, N m/m, N m/rad], replacing the stiffness keys (GearTrainModel::linearisedAt).
  std::optional<Eigen::Matrix<double, 5, 5>> stiffness_matrix;
  /// bearings.<name>.model = "nonlinear" (a `rolling` bearing, planar DOFs): the nonlinear
  /// analyses (train nonlinear, time) take its full load–deflection law with the clearance
  /// (bearing_clearance.h); false ("linearised"): its tangent at the static deflection.
  bool full_law = false;
  /// Set by GearTrainModel::linearisedAt for a full-law bearing: the law the nonlinear solvers
  /// apply, the linear analyses using stiffness_matrix.
  std::shared_ptr<const RollingBearing> nonlinear_law;
};

/// A coupling between two coaxial shafts (motor to input, output to load): torsional and
/// lateral stiffness and damping. The two shafts turn at one speed.
struct TrainCouplingSpec {
  std::string name;
  std::string shaft_a, shaft_b;
  double k_torsion = 0, c_torsion = 0;  ///< [N m/rad], [N m s/rad]
  double k_lateral = 0, c_lateral = 0;  ///< [N/m], [N s/m]
  /// ω_b = ratio ω_a [-]: 1 for a coupling; another value makes it a kinematic gear ratio (the
  /// speeds of a stage whose mesh the model leaves out, e.g. Rao's lateral rotor, whose "mesh"
  /// is a bearing between the shafts); the torsional spring then acts on ratio θ_a − θ_b.
  double ratio = 1.0;
};

/// A mass unbalance on a shaft (or on a gear's body: give the gear's shaft and position): the
/// mass m at eccentricity e [kg m] at angle `phase` [rad] from +y towards +z at t = 0, turning
/// with the shaft at its signed speed ω; the rotating force m e (ψ̇² cos ψ + ψ̈ sin ψ,
/// ψ̇² sin ψ − ψ̈ cos ψ), ψ = ∫ω dt + phase (m e ω² (cos ψ, sin ψ) at constant speed) on the
/// shaft's centre (with full DOFs, at its axial position).
struct TrainUnbalanceSpec {
  std::string name;
  std::string shaft;
  double position = 0.0;           ///< along the shaft from its first section start [m]
  double mass_eccentricity = 0.0;  ///< m e [kg m]
  double phase = 0.0;              ///< [rad]
};

/// A gear's runout (geometric eccentricity): its centre sits `amplitude` [m] off the shaft's
/// axis at angle `phase` [rad] from +y towards +z at t = 0 and turns with the gear. On each of
/// its meshes the offset w(t) adds v_gᵀ w (its projection on the line of action) to the mesh
/// deflection: a displacement excitation at the gear's shaft order, the load
/// −v_m (k(φ) v_gᵀ w + c_m v_gᵀ ẇ).
struct TrainRunoutSpec {
  std::string name;
  std::string gear;
  double amplitude = 0.0;  ///< [m]
  double phase = 0.0;      ///< [rad]
};

/// A prescribed relative displacement d(t) across a linear bearing (its shaft against the other
/// shaft or the housing, in y and z): the bearing's spring and dashpot act on J q − d, which
/// loads the train with Jᵀ (K_b d + C_b ḋ). Harmonic i is
///   d_y = a_y,i cos(ν_i α + ϕ_y,i),  d_z = a_z,i cos(ν_i α + ϕ_z,i)
/// with ν_i α = orders_i × the reference's angle: a shaft's rotation ∫|ω| dt, or 2π × a mesh's
/// phase φ_m(t) (mesh periods, its phase at t = 0 included). This is Rao's "mesh" (thesis
/// eqs. 2.8–2.9: transmission error applied to an isotropic spring between the gear centres).
struct TrainBearingExcitationSpec {
  std::string name;
  std::string bearing;
  std::string reference;              ///< a shaft or a mesh the orders refer to
  double mean_y = 0.0, mean_z = 0.0;  ///< constant part [m]
  std::vector<double> orders;         ///< > 0, multiples of the reference's speed or mesh frequency
  std::vector<double> amplitude_y, phase_y, amplitude_z, phase_z;  ///< [m], [rad] per order
};

/// The planet set of a planetary (epicyclic) stage: sun and ring are gears on shafts, the
/// carrier is a shaft; the stage generates N planets (each a body in the carrier frame), their
/// pin bearings and 2N meshes.
struct PlanetaryStageSpec {
  std::string name;
  std::string sun, ring;  ///< gears (the ring has internal = true)
  std::string carrier;    ///< shaft
  GearSpec planet;        ///< planet gear (its body gives the planet's mass and inertia)
  int planets = 3;
  /// Planet position angles ψ_n in the carrier frame [rad]; empty: equally spaced 2π n/N.
  std::vector<double> planet_angles;
  double planet_mass = 0.0, planet_inertia = 0.0;  ///< extra to the gear body [kg, kg m²]
  bool planet_body = true;                         ///< add the planet gear body's mass and inertia
  double pin_radial_stiffness = 0.0, pin_tangential_stiffness = 0.0;  ///< [N/m]
  double pin_damping = 0.0;                                           ///< [N s/m]
  /// Full DOFs: the planet's diametral inertia extra to the gear body [kg m²]; < 0: that of a
  /// disk of the face width b carrying planet_mass and planet_inertia, I_p/2 + m b²/12.
  double planet_diametral_inertia = -1.0;
  /// Full DOFs: the pin's axial [N/m] and tilting [N m/rad] stiffness; < 0: derived, axially the
  /// mean of the radial and tangential ones, in tilt that k̄ spread uniformly over the face
  /// width, k̄ b²/12.
  double pin_axial_stiffness = -1.0, pin_tilt_stiffness = -1.0;
  /// Tangential pin position errors e_n [m], one per planet (empty: none): planet load
  /// sharing.
  std::vector<double> pin_position_errors;
  std::shared_ptr<const MeshStiffness> sun_planet_stiffness, ring_planet_stiffness;
  double sun_planet_damping_ratio = 0.0, ring_planet_damping_ratio = 0.0;
  TransmissionError sun_planet_error, ring_planet_error;
  TrainMeshContact sun_planet_contact, ring_planet_contact;  ///< of every planet's meshes
  /// Formulate the stage in its carrier frame with the Coriolis and centripetal terms of the
  /// carrier's rotation (Lin & Parker 1999); false: the classic lumped model without them.
  bool carrier_frame_terms = true;
};

/// Where the power goes in and out.
struct OperatingPoint {
  std::string input_shaft;
  double input_speed = 0.0;   ///< [rad/s], signed about +x
  double input_torque = 0.0;  ///< applied to the input shaft [N m], signed about +x
  std::string output_shaft;   ///< takes the balancing load torque (lossless train)
  /// Where the torques act along flexible shafts [m from the shaft's first section start];
  /// absent: the input at the shaft's start, the output at its end.
  std::optional<double> input_position, output_position;
};

struct TrainHousingSpec;  // system/train_housing.h

struct GearTrainSpec {
  std::string name;
  TrainDofs dofs = TrainDofs::kPlanar;
  std::vector<TrainShaftSpec> shafts;
  std::vector<TrainGearSpec> gears;
  std::vector<TrainMeshSpec> meshes;
  std::vector<TrainBearingSpec> bearings;
  std::vector<TrainCouplingSpec> couplings;
  std::vector<TrainDiskSpec> disks;
  std::vector<PlanetaryStageSpec> stages;
  /// Excitations beside the meshes' transmission errors (train_excitation.h).
  std::vector<TrainUnbalanceSpec> unbalances;
  std::vector<TrainRunoutSpec> runouts;
  std::vector<TrainBearingExcitationSpec> bearing_excitations;
  OperatingPoint operating;
  double mass_proportional_damping = 0.0;       ///< α [1/s]
  double stiffness_proportional_damping = 0.0;  ///< β [s]
  /// Where the first shaft's centre lies [m] (y, z); the others follow from the meshes.
  double origin_y = 0.0, origin_z = 0.0;
  /// Gravity along −z [m/s²] (planar and full DOFs; members in a rotating carrier frame
  /// cannot take it).
  double gravity = 0.0;
  /// A flexible housing carrying (some of) the bearings (train_housing.h); null: rigid ground.
  std::shared_ptr<const TrainHousingSpec> housing;
};

std::string toString(TrainDofs dofs);
TrainDofs parseTrainDofs(const std::string& text, const std::string& key);

}  // namespace geardyn

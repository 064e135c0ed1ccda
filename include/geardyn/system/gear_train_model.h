#pragma once
/// \file
/// The assembled gear train: bodies with their degrees of freedom, kinematics, mesh geometry
/// and phasing, and the matrices of
///
///   M q̈ + (C + Ω G₁) q̇ + (K + Ω² K_Ω + Σ_m k_m(φ_m) v_m v_mᵀ) q
///       = F₀ + Σ_m k_m(φ_m) e_m(φ_m) v_m,                                     φ_m = f_m t + φ_m0
///
/// with Ω the input speed [rad/s]; G₁ and K_Ω the Coriolis and centripetal terms of bodies
/// formulated in a rotating carrier frame, per unit input speed and per unit input speed squared
/// (Lin & Parker 1999, eq. 1); v_m the gradient of mesh m's deflection along its line of action
/// (docs/theory/gear_trains.md); K excludes the meshes. Immutable once built; validated on
/// construction (InputError naming the component and key); solvers keep their own workspace.
///
/// Degrees of freedom of a body: its rotation θ [rad] (TrainDofs::kTorsional), or the
/// translation (y, z) of its centre [m] and θ (kPlanar), or (y, z, θ, x, θ_y, θ_z) (kFull: the
/// axial translation and the tilts about y and z follow, so the first three keep their
/// meaning). Planets and the members of a planetary stage with carrier-frame terms have their
/// translations in the carrier frame. A flexible shaft is a chain of bodies, one per FE node
/// ("input.n0", "input.n1", …), joined by Timoshenko beam elements.

#include <Eigen/Dense>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "geardyn/models/timoshenko_shaft_element.h"
#include "geardyn/system/bearing_clearance.h"
#include "geardyn/system/gear_train.h"
#include "geardyn/system/train_excitation.h"
#include "geardyn/system/train_kinematics.h"

namespace geardyn {

enum class TrainBodyKind { kShaft, kPlanet };

struct TrainBody {
  std::string name;
  TrainBodyKind kind = TrainBodyKind::kShaft;
  double mass = 0.0;                                 ///< [kg]
  double polar_inertia = 0.0;                        ///< [kg m²]
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();  ///< (y, z) [m] (carrier frame: at t = 0)
  double speed_ratio = 0.0;                          ///< ω / Ω_input [-]
  int stage = -1;     ///< planetary stage whose carrier frame it uses; −1: fixed frame
  int planet = -1;    ///< planet index within its stage, −1 otherwise
  int first_dof = 0;  ///< index of its first DOF (y, or θ when torsional)
  bool grounded_torsion = false;   ///< held against rotation by the housing (speed 0)
  int shaft = -1;                  ///< the spec's shaft it belongs to (−1: a planet)
  double axial = 0.0;              ///< global x of its reference point (node, mass centre) [m]
  double diametral_inertia = 0.0;  ///< about a transverse axis (full DOFs) [kg m²]
};

/// What kind of mesh: a fixed-axis external or internal pair, or a planetary mesh.
enum class TrainMeshKind { kExternal, kInternal, kSunPlanet, kRingPlanet };
std::string toString(TrainMeshKind kind);

struct TrainMesh {
  std::string name;
  TrainMeshKind kind = TrainMeshKind::kExternal;
  int body_a = 0, body_b = 0;  ///< a drives the mesh's phase; for planetary meshes b = planet
  int teeth_a = 0, teeth_b = 0;
  int stage = -1, planet = -1;
  int gear_a = -1, gear_b = -1;                     ///< indices in spec().gears (−1: a planet)
  double centre_distance = 0.0;                     ///< a_w [m]
  double pressure_angle = 0.0;                      ///< operating α_wt [rad]
  double base_helix_angle = 0.0;                    ///< β_b [rad]
  double base_radius_a = 0.0, base_radius_b = 0.0;  ///< [m]
  double contact_ratio = 0.0;                       ///< ε_γ [-]
  Eigen::Vector2d pitch_point = Eigen::Vector2d::Zero();  ///< contact point c (y, z) [m]
  Eigen::Vector2d normal = Eigen::Vector2d::Zero();       ///< transverse line of action n_t (unit)
  /// ∂δ/∂q: the nonzero entries of v_m (DOF indices and coefficients; 2 or 6 entries).
  std::vector<int> dofs;
  std::vector<double> gradient;
  std::shared_ptr<const MeshStiffness> stiffness;  ///< k(φ) [N/m]
  double mean_stiffness = 0.0;                     ///< k̄ [N/m]
  TransmissionError transmission_error;            ///< e(φ) [m]
  double damping = 0.0;                            ///< c_m [N s/m]
  double damping_ratio = 0.0;                      ///< [-]
  double equivalent_mass = 0.0;  ///< m_e = 1 / Σ v_θ² / I over the two rotations [kg]
  /// Mesh frequency per unit input speed: f_m = frequency_ratio |Ω| [Hz per rad/s].
  double frequency_ratio = 0.0;
  double phase = 0.0;        ///< φ_m0 [mesh periods]
  TrainMeshContact contact;  ///< the tooth contact law and backlash
  /// g(y): the contact law applied to the tooth deformation y = δ − e [m], with dg/dy in *slope
  /// (gear_train.h, TrainMeshContact; 1 and y for a linear mesh).
  double contactDeflection(double y, double* slope = nullptr) const;
  bool nonlinear() const noexcept { return contact.law != ContactLaw::kLinear; }
  /// The mesh force comes from tooth-pair contact elements (TrainMeshContact::tooth_pairs).
  bool toothPairs() const noexcept { return contact.tooth_pairs != nullptr; }
  /// The nonlinear analyses' mesh force at phase φ [mesh periods] for the tooth deformation
  /// y = δ − e [m]: Σ_j k_j(φ) max(0, y − g_j(φ)) for tooth pairs, else k(φ) g(y) [N]; dF/dy
  /// [N/m] in *slope (virtual calls: for reports, not inner loops).
  double nonlinearForce(double phase, double y, double* slope = nullptr) const;
  /// Mesh phase at time t for the input speed Ω [rad/s].
  double phaseAt(double t, double input_speed) const;
  /// The mesh deflection vᵀq [m] of a state q (all the model's DOFs).
  double deflection(const Eigen::Ref<const Eigen::VectorXd>& q) const;
  /// The elastic mesh force k(φ) g(vᵀq − e(φ)) at time t [N] (g: the contact law).
  double force(double t, double input_speed, const Eigen::Ref<const Eigen::VectorXd>& q) const;
};

/// A stiffness/damping element for reports (strain energy per component): its DOFs and its
/// small symmetric stiffness matrix over them (the meshes are separate: k̄ v vᵀ).
struct TrainElement {
  std::string name;
  std::string kind;  ///< "bearing", "coupling", "pin", "support"
  std::vector<int> dofs;
  Eigen::MatrixXd stiffness;  ///< Jᵀ k J over `dofs`
  /// Its deformation d = J q[dofs] (relative displacement (y, z) [m], or relative rotation
  /// [rad]) and the force (or torque) k d it transmits [N, N m].
  Eigen::MatrixXd jacobian, local_stiffness;
  /// Per row of d: a rotation, whose k d is a moment [N m] (true), or a displacement, whose
  /// k d is a force [N] (false). An axial spring is one row of force; a torsional or tilt
  /// spring one of moment; a beam element twelve rows of both.
  std::vector<bool> moment_rows;
};

/// A rolling bearing from its geometry (TrainBearingSpec::rolling) in the assembled train: its
/// relative displacement q_b = J q[dofs] = (u_y, u_z, u_x, θ_y, θ_z) [m, rad] of the shaft's
/// bearing point against the housing or the other shaft (rows u_x, θ_y, θ_z are 0 unless the
/// DOFs are full). The train's internal force is Jᵀ F_b(q_b), its tangent Jᵀ K_b J.
struct TrainRollingBearing {
  std::string name;
  int spec_index = 0;  ///< in spec().bearings
  std::shared_ptr<const RollingBearing> bearing;
  std::vector<int> dofs;
  Eigen::Matrix<double, 5, Eigen::Dynamic> jacobian;
  /// q_b of the train's state q.
  Eigen::Matrix<double, 5, 1> displacement(const Eigen::Ref<const Eigen::VectorXd>& q) const;
};

class GearTrainModel {
 public:
  /// The dense n×n matrices a model of n DOFs holds (M, K, C, G, K_Ω, mean mesh stiffness),
  /// with the assembly's and the analyses' working copies (structure stiffness, K and D at a
  /// speed, two more): what `memory_limit` is checked against.
  static constexpr int kDenseMatrices = 10;

  /// Validates the description (InputError naming the component and key) and assembles.
  /// `memory_limit` [B]: a train whose kDenseMatrices n×n doubles would not fit is refused
  /// before its bodies and matrices are allocated (InputError naming the finest flexible
  /// shaft's max_element_length, or gearbox.dofs), e.g. analysis::memoryLimitBytes().
  explicit GearTrainModel(GearTrainSpec spec,
                          double memory_limit = std::numeric_limits<double>::infinity());

  const GearTrainSpec& spec() const noexcept { return spec_; }
  const TrainKinematics& kinematics() const noexcept { return kinematics_; }
  int dofCount() const noexcept { return dof_count_; }
  int dofsPerBody() const noexcept {
    return spec_.dofs == TrainDofs::kFull ? 6 : spec_.dofs == TrainDofs::kPlanar ? 3 : 1;
  }
  const std::vector<TrainBody>& bodies() const noexcept { return bodies_; }
  const std::vector<TrainMesh>& meshes() const noexcept { return meshes_; }
  /// Some mesh has contact loss or backlash (TrainMeshContact).
  bool hasNonlinearMeshes() const;
  /// The bearings with a radial clearance > 0 (bearing_clearance.h), in the spec's order. Their
  /// linear stiffness stays in K; the nonlinear solvers add their correction forces.
  const std::vector<TrainClearanceBearing>& clearanceBearings() const noexcept {
    return clearance_bearings_;
  }
  /// Some mesh is nonlinear or some bearing has a radial clearance.
  bool hasNonlinearElements() const { return hasNonlinearMeshes() || !clearance_bearings_.empty(); }
  /// W = [v_1 … v_r, J_1ᵀ … J_bᵀ] (n × (r + 2b)): the nonlinear coordinates Wᵀq are the mesh
  /// deflections δ, then (u_y, u_z) of every clearance bearing [m].
  Eigen::MatrixXd nonlinearVectors() const;
  const std::vector<TrainElement>& elements() const noexcept { return elements_; }
  /// The bearings described by their geometry (nonlinear; not in K): the static analysis
  /// solves for their deflection, the linear analyses use linearisedAt.
  const std::vector<TrainRollingBearing>& rollingBearings() const noexcept {
    return rolling_bearings_;
  }
  /// This train with every rolling bearing replaced by its tangent stiffness at the state q
  /// (TrainBearingSpec::stiffness_matrix): the linear model about a static deflection.
  GearTrainModel linearisedAt(const Eigen::Ref<const Eigen::VectorXd>& q) const;
  /// This train with `spec` in place of spec(), where `spec` differs from it only in mesh-stiffness
  /// models (TrainMeshSpec::stiffness, PlanetaryStageSpec::sun_planet_stiffness and
  /// ring_planet_stiffness: a new object for a changed mesh) and the operating point's input speed
  /// and torque — the parameters a design loop varies. Only what depends on them is reassembled
  /// (train_model_updates.cpp): a changed mesh's k̄, its dashpot when it follows from a damping
  /// ratio, Σ k̄ v vᵀ and C by rank-one updates; F₀ for a new operating point. A change that
  /// moves a mesh to its other flank or loads or unloads one (the torque's sign, the load path
  /// of a statically indeterminate train) builds the train anew from `spec`. Either way the
  /// result equals GearTrainModel(spec) to round-off.
  GearTrainModel withParameters(GearTrainSpec spec) const;
  int bodyIndex(const std::string& name) const;  ///< −1 when absent
  /// "input.y", "stage1.planet2.theta", … for DOF i.
  std::string dofName(int i) const;
  /// The θ DOF of body b; its y DOF (−1 when torsional).
  int rotationDof(int body) const;
  int translationDof(int body) const;
  /// The body of shaft i at `position` along it [m from its first section start]: the rigid
  /// shaft's one body, or the flexible shaft's node there (nodes are placed at every gear,
  /// bearing, disk and torque position). InputError naming `key` when outside the shaft.
  int bodyAt(int shaft, double position, const std::string& key) const;
  /// The bodies (nodes) of shaft i in axial order.
  const std::vector<int>& shaftNodes(int shaft) const { return shaft_nodes_[shaft]; }
  /// Beam elements of the flexible shafts (for reports and the strain energy).
  struct BeamElement {
    int shaft = 0;
    int index = 0;  ///< along its shaft
    int body_a = 0, body_b = 0;
    ShaftSegment segment;
  };
  const std::vector<BeamElement>& beams() const noexcept { return beams_; }
  /// Axial distance [m] from body b's reference point to `position` along shaft i (0 for the
  /// nodes of flexible shafts; the offset from the mass centre for rigid shafts).
  double axialOffsetOf(int body, int shaft, double position) const;
  /// The train's DOF indices of a beam element in FE order [u_x, u_y, u_z, θ_x, θ_y, θ_z] × 2.
  std::vector<int> beamDofs(const BeamElement& beam) const;

  const Eigen::MatrixXd& mass() const noexcept { return M_; }
  const Eigen::MatrixXd& stiffness() const noexcept { return K_; }   ///< without the meshes
  const Eigen::MatrixXd& damping() const noexcept { return C_; }     ///< incl. mesh dashpots
  const Eigen::MatrixXd& gyroscopic() const noexcept { return G_; }  ///< G₁ per unit Ω [kg]
  const Eigen::MatrixXd& centripetal() const noexcept { return Komega_; }  ///< K_Ω per Ω² [kg]
  /// Σ_m k̄_m v_m v_mᵀ.
  const Eigen::MatrixXd& meanMeshStiffness() const noexcept { return Kmesh_; }
  /// F₀: input and output torques, pin-position-error loads, weights and the prescribed mean
  /// bearing displacements' loads [N, N m].
  const Eigen::VectorXd& staticLoad() const noexcept { return F0_; }
  /// Unbalances, runouts and prescribed bearing displacements as harmonic forces
  /// (train_excitation.h); their constant parts are in staticLoad().
  const std::vector<TrainExcitationTerm>& excitations() const noexcept { return excitations_; }
  /// v_m as a dense vector.
  Eigen::VectorXd meshVector(int mesh) const;
  /// The operating input speed [rad/s] and torque [N m], and the output's load torque [N m].
  double inputSpeed() const noexcept { return spec_.operating.input_speed; }
  double outputTorque() const noexcept { return output_torque_; }

  /// K + Ω² K_Ω + Σ k̄ v vᵀ at input speed Ω [rad/s].
  Eigen::MatrixXd meanStiffnessAt(double input_speed) const;
  /// C + Ω G₁.
  Eigen::MatrixXd dampingAt(double input_speed) const;

  const std::vector<std::string>& warnings() const noexcept { return warnings_; }
  /// The first of the housing's DOFs (train_housing.h: after every body's), −1 without a
  /// flexible housing; dofCount() − housingFirstDof() housing DOFs.
  int housingFirstDof() const noexcept { return housing_first_dof_; }
  /// Body index of the spec's shaft i.
  int shaftBody(int shaft) const { return shaft_body_[shaft]; }
  /// The stage whose rotating carrier frame body b's translations are written in (−1: fixed
  /// frame, or a stage without carrier-frame terms).
  int rotatingFrame(int body) const;

 private:
  void buildBodies();
  void buildShaftNodes(int shaft);
  /// Throws InputError(key, value) when `dofs` DOFs of dense matrices exceed memory_limit_.
  void checkDenseFits(double dofs, const std::string& key, const std::string& value) const;
  void assembleBeams();
  void addBeamElements();
  void fullMeshGradient(const TrainMesh& m, std::vector<int>& dofs, Eigen::VectorXd& v) const;
  /// Polar inertia of a body for the mesh's equivalent mass (nodes: with half their beams').
  double rotatingInertia(int body) const;
  /// The meshes in named steps (train_meshes.cpp): geometry and constraints of fixed-axis
  /// meshes and planetary stages, kinematics, shaft centres, the meshes, their loaded flanks.
  struct MeshLayout;
  void buildMeshes();
  void addFixedAxisMeshGeometry(MeshLayout& layout);
  void addPlanetaryStageGeometry(MeshLayout& layout);
  void solveTrainKinematics(MeshLayout& layout);
  void placeShaftCentres(const MeshLayout& layout);
  void createMeshes(const MeshLayout& layout);
  std::vector<double> torsionalMeshForces() const;
  void orientMeshesByLoad();
  void buildElements();
  /// InputError on a bad bearings.<name>.radial_clearance (< 0, torsional DOFs, anisotropic k).
  void checkClearance(const TrainBearingSpec& bearing, const std::string& key) const;
  /// A bearing given by its geometry or its 5×5 matrix (train_rolling_bearings.cpp): body and
  /// other (−1: the housing) at axial offsets dx, other_dx from their reference points.
  void addRollingBearing(const TrainBearingSpec& bearing, const std::string& key, int body,
                         int other, double dx, double other_dx);
  void assemble();
  /// F₀ from the operating point, pin position errors and gravity (after M is assembled).
  void assembleLoads();
  /// Appends spec_.housing's DOFs and moves its linked bearings onto the seats
  /// (train_housing.cpp).
  void attachHousing();

  GearTrainSpec spec_;
  TrainKinematics kinematics_;
  std::vector<TrainBody> bodies_;
  std::vector<TrainMesh> meshes_;
  std::vector<TrainElement> elements_;
  std::vector<TrainClearanceBearing> clearance_bearings_;
  std::vector<TrainRollingBearing> rolling_bearings_;
  std::vector<Eigen::MatrixXd> element_damping_;  // over each element's DOFs
  std::vector<int> shaft_body_;                   // spec shaft index → body index
  std::vector<std::vector<int>> shaft_nodes_;     // spec shaft index → its bodies by x
  std::vector<BeamElement> beams_;
  int dof_count_ = 0;
  int housing_first_dof_ = -1;
  double memory_limit_ = std::numeric_limits<double>::infinity();  // [B]
  double output_torque_ = 0.0;
  Eigen::MatrixXd M_, K_, C_, G_, Komega_, Kmesh_;
  Eigen::VectorXd F0_;
  std::vector<TrainExcitationTerm> excitations_;
  std::vector<std::string> warnings_;
};

}  // namespace geardyn

#pragma once
/// \file
/// A rolling-element bearing from its internal geometry (ISO/TS 16281:2008; Harris & Kotzalas,
/// Rolling Bearing Analysis, 5th ed., ch. 7–8; Lim & Singh, J. Sound Vib. 139 (1990) 179–199):
/// every rolling element is a Hertzian contact — ball bearings a point contact with the
/// elliptic-integral constants (hertz_point_contact.h) and a contact angle that follows the
/// load, roller bearings a line contact cut in slices with the roller's crowned or logarithmic
/// profile, spherical roller bearings two rows of barrel rollers on a spherical outer raceway
/// (self-aligning: no tilt stiffness) — summed into the load–deflection relation of the inner ring
/// relative to the outer ring in five DOFs q = (u_y, u_z, u_x, θ_y, θ_z) [m, m, m, rad, rad] (x the
/// bearing axis; the rotation about x is free), its tangent 5×5 stiffness matrix ∂F/∂q (symmetric:
/// F is the gradient of the contacts' strain energy) and the load of every element.
///
/// Sign convention: F(q) = ∂U/∂q is the load [N, N, N, N m, N m] that holds the inner ring at
/// q; the bearing pushes the inner ring with −F. docs/theory/rolling_bearings.md.

#include <Eigen/Core>
#include <string>
#include <vector>

namespace geardyn {

enum class RollingBearingType {
  kDeepGrooveBall,
  kAngularContactBall,
  kCylindricalRoller,
  kTaperedRoller,
  /// Double row, barrel rollers, spherical outer raceway centred on the bearing's centre (Harris
  /// & Kotzalas 2006, vol. 1 §1.3 and §7.2): every contact normal passes through that centre,
  /// so a tilt of the inner ring approaches no contact (self-aligning). Two rows at ± the
  /// contact angle by construction: `arrangement` stays kSingle, `row_spacing` is derived.
  kSphericalRoller
};
/// Rows: one; two rows back to back (O, pressure centres outside the rows: large tilt
/// stiffness) or face to face (X: small tilt stiffness); a double-row bearing is two rows back
/// to back in one pair of rings.
enum class BearingArrangement { kSingle, kBackToBack, kFaceToFace };
enum class RollerProfile { kStraight, kCrowned, kLogarithmic };

std::string toString(RollingBearingType type);
std::string toString(BearingArrangement arrangement);
std::string toString(RollerProfile profile);

struct RollingBearingGeometry {
  RollingBearingType type = RollingBearingType::kDeepGrooveBall;
  BearingArrangement arrangement = BearingArrangement::kSingle;
  int elements = 0;               ///< Z, rolling elements per row [-]
  double element_diameter = 0.0;  ///< D_w (rollers: mean diameter D_we) [m]
  double pitch_diameter = 0.0;    ///< d_m [m]
  /// Nominal contact angle α₀ [rad]: of the touching position without clearance (ball
  /// bearings: the angle the load starts from; tapered rollers: the cup angle). 0 for deep
  /// groove and cylindrical roller bearings.
  double contact_angle = 0.0;
  /// Groove radii r_i, r_e of the inner and outer raceway (balls) [m], > D_w/2.
  double inner_groove_radius = 0.0, outer_groove_radius = 0.0;
  double roller_length = 0.0;  ///< effective length L_we (rollers) [m]
  RollerProfile profile = RollerProfile::kLogarithmic;
  double crown_drop = 0.0;  ///< crown drop at the roller ends, kCrowned [m]
  int slices = 20;          ///< slices of a roller [-]
  /// Radial operating clearance s_r (the diametral play) [m]; < 0: a preload (interference).
  double clearance = 0.0;
  double row_spacing = 0.0;  ///< axial distance of the two rows' centres (pairs) [m]
  /// A single row takes the shaft's axial load towards +x (its inner ring's shoulder faces
  /// −x); reversed: towards −x. Two single rows at a shaft's ends, one reversed, are a pair
  /// across the shaft (X or O).
  bool reversed = false;
  double youngs_modulus = 2.1e11, poisson_ratio = 0.3;                  ///< rings [Pa, -]
  double element_youngs_modulus = 2.1e11, element_poisson_ratio = 0.3;  ///< elements
  double dynamic_load_rating = 0.0;  ///< C [N] of the whole bearing; 0: no L10r
  /// InputError naming `key`.<field> for geometry that is not a bearing: elements that do not
  /// fit on the pitch circle, a groove radius below the ball radius, a preload beyond a fit's.
  void validate(const std::string& key) const;
  bool ball() const noexcept {
    return type == RollingBearingType::kDeepGrooveBall ||
           type == RollingBearingType::kAngularContactBall;
  }
  int rows() const noexcept {
    return type == RollingBearingType::kSphericalRoller ||
                   arrangement != BearingArrangement::kSingle
               ? 2
               : 1;
  }
  /// Radius of the spherical outer raceway R_e = d_m / (2 cos α₀) + D_we / 2 [m] (spherical
  /// roller bearings: the roller centres on the pitch circle, the contact normals through the
  /// bearing's centre).
  double outerRacewayRadius() const noexcept;
};

/// One rolling element at a state q.
struct RollingElementState {
  int row = 0;
  double azimuth = 0.0;        ///< ψ [rad] from the +y axis towards +z
  double load = 0.0;           ///< Q [N] (rollers: Σ over the slices)
  double deflection = 0.0;     ///< δ [m] (rollers: the largest slice's)
  double contact_angle = 0.0;  ///< operating α [rad]
  double max_pressure = 0.0;   ///< p₀ at the more loaded raceway [Pa]
};

struct RollingBearingState {
  Eigen::Matrix<double, 5, 1> displacement = Eigen::Matrix<double, 5, 1>::Zero();  ///< q
  Eigen::Matrix<double, 5, 1> load = Eigen::Matrix<double, 5, 1>::Zero();          ///< F(q)
  Eigen::Matrix<double, 5, 5> stiffness = Eigen::Matrix<double, 5, 5>::Zero();     ///< ∂F/∂q
  std::vector<RollingElementState> elements;
  double max_element_load = 0.0;  ///< [N]
  double max_pressure = 0.0;      ///< [Pa]
  /// ISO/TS 16281 reference rating life L10r [10⁶ revolutions of the inner ring]; 0 without C,
  /// +∞ without load.
  double rating_life = 0.0;
};

struct RollingBearingSolveResult {
  RollingBearingState state;
  std::string status = "converged";  ///< "converged" or "max_iterations"
  int iterations = 0;
  double residual = 0.0;  ///< ‖F(q) − F_given‖ / ‖F_given‖
};

class RollingBearing {
 public:
  using Vector5 = Eigen::Matrix<double, 5, 1>;
  using Matrix5 = Eigen::Matrix<double, 5, 5>;

  /// Validates (InputError naming `key`.<field>) and precomputes the contacts.
  explicit RollingBearing(RollingBearingGeometry geometry, const std::string& key = "bearing");

  const RollingBearingGeometry& geometry() const noexcept { return g_; }
  /// F(q) and, when K is not null, ∂F/∂q at q. No allocation.
  void evaluate(const Vector5& q, Vector5& F, Matrix5* K) const;
  /// Everything at q: F, K, the elements' loads, the largest pressure, L10r.
  RollingBearingState state(const Vector5& q) const;
  /// q with F(q) = load: damped Newton from a reference deflection (a free direction, e.g. the
  /// axial one of a cylindrical roller bearing, stays at 0 when unloaded).
  RollingBearingSolveResult solve(const Vector5& load) const;

  /// Hertz point-contact stiffness K_n of one ball, Q = K_n δ^{3/2} [N m^{-3/2}] (balls).
  double ballStiffness() const noexcept { return k_ball_; }
  /// Slice stiffness c_s, q = c_s δ^{10/9} [N m^{-10/9}] (rollers; ISO/TS 16281 c_l / n_s).
  double sliceStiffness() const noexcept { return k_slice_; }
  /// A reference deflection of the element contact [m]: D_w × 10⁻³, the scale of a loaded
  /// contact, for starting values and finite-difference steps.
  double referenceDeflection() const noexcept { return 1e-3 * g_.element_diameter; }
  /// Every contact's stiffness at the reference deflection, summed, per translation [N/m] and
  /// times the pitch radius² per tilt [N m/rad]: the scale of the bearing's stiffness, which
  /// damps Newton steps where the contacts have none yet (q = 0 without preload).
  Vector5 referenceStiffness() const noexcept;

 private:
  struct Contact {  // one ball, or one roller slice
    int element = 0;
    double sigma = 1.0;   // axial sense of the row's contact (±1)
    Vector5 g_r, g_a;     // radial and axial displacement of the contact point per q
    double offset = 0.0;  // slices: profile drop and clearance along the normal [m]
  };
  void addSphericalSlices(int element, double psi, double side);
  double ballLoad(const Contact& c, const Vector5& q, Vector5& F, Matrix5* K, double* alpha) const;
  double sliceLoad(const Contact& c, const Vector5& q, Vector5& F, Matrix5* K) const;
  double ratingLife(const std::vector<RollingElementState>& elements,
                    const std::vector<double>& slice_loads) const;

  RollingBearingGeometry g_;
  std::vector<Contact> contacts_;
  std::vector<double> azimuth_;
  std::vector<int> row_of_;
  double A_ = 0.0;  // distance of the groove curvature centres, r_i + r_e − D_w [m]
  double k_ball_ = 0.0, k_slice_ = 0.0;
  double pressure_ball_ = 0.0;  // p₀ = c Q^{1/3} at the more loaded raceway [Pa N^{-1/3}]
  double pressure_line_ = 0.0;  // p₀ = c √(q/w), q the slice load, w its width [Pa (N/m)^{-1/2}]
};

}  // namespace geardyn

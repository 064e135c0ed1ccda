#pragma once
/// \file
/// The API constant mesh stiffness (API 684 tutorial, 2005, as quoted by Visnadi & de Castro
/// 2021, eqs. 1–6): K′ = C L cos²β 10⁶ N/m with C = 12.057 and L the face width in mm, and its
/// 2×2 directional matrix for a lateral rotor model.

#include <Eigen/Core>

#include "geardyn/stiffness/mesh_stiffness.h"

namespace geardyn {

/// API empirical constant C of eq. 5 [N/(m·mm)] / 10⁶.
inline constexpr double kApiStiffnessConstant = 12.057;

/// K′ = 12.057 · L[mm] · cos²β · 10⁶ [N/m] (Visnadi eq. 5) for face width L [m] and helix
/// angle β [rad].
double apiMeshStiffness(double face_width, double helix_angle);

/// How the rotor is loaded (A in eq. 6): the mesh force pushes the pinion down (+1) or up (−1).
enum class ApiLoading { kDown = 1, kUp = -1 };
/// Rotation sense looking into the coupling end (B in eq. 6): clockwise 90°, counter 270°.
enum class ApiRotation { kClockwise, kCounterClockwise };

/// γ = A α + B [rad] (eq. 6) for the normal pressure angle α [rad].
double apiMeshDirection(double pressure_angle, ApiLoading loading, ApiRotation rotation);

/// [[K_xx, K_xy], [K_yx, K_yy]] = K′ [[cos²γ, sinγ cosγ], [sinγ cosγ, sin²γ]] [N/m] (eqs. 1–4).
Eigen::Matrix2d apiDirectionalStiffness(double k_prime, double gamma);

/// A mesh stiffness that does not vary over the mesh period: the API value, or any constant
/// (ISO 6336 mean mesh stiffness).
class ConstantMeshStiffness final : public MeshStiffness {
 public:
  /// \param name "api", "iso6336", ...; \param value k [N/m] > 0; \param contact_ratio [-]
  ConstantMeshStiffness(std::string name, double value, double contact_ratio);
  std::string model() const override { return name_; }
  double stiffness(double) const override { return value_; }
  double contactRatio() const override { return contact_ratio_; }

 private:
  std::string name_;
  double value_;
  double contact_ratio_;
};

}  // namespace geardyn

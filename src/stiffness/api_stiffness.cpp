#include "geardyn/stiffness/api_stiffness.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "geardyn/error.h"

namespace geardyn {

double apiMeshStiffness(double face_width, double helix_angle) {
  if (!(face_width > 0.0) || !std::isfinite(face_width)) {
    throw InputError("face_width", fmt::format("{:g}", face_width), "must be finite and > 0 [m]");
  }
  const double c = std::cos(helix_angle);
  return kApiStiffnessConstant * (face_width * 1e3) * c * c * 1e6;
}

double apiMeshDirection(double pressure_angle, ApiLoading loading, ApiRotation rotation) {
  const double a = static_cast<int>(loading);
  const double b = (rotation == ApiRotation::kClockwise ? 90.0 : 270.0) * std::numbers::pi / 180.0;
  return a * pressure_angle + b;
}

Eigen::Matrix2d apiDirectionalStiffness(double k_prime, double gamma) {
  const double c = std::cos(gamma), s = std::sin(gamma);
  Eigen::Matrix2d k;
  k << c * c, s * c, s * c, s * s;
  return k_prime * k;
}

ConstantMeshStiffness::ConstantMeshStiffness(std::string name, double value, double contact_ratio)
    : name_(std::move(name)), value_(value), contact_ratio_(contact_ratio) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw InputError(name_ + " mesh stiffness", fmt::format("{:g}", value),
                     "must be finite and > 0 [N/m]");
  }
}

}  // namespace geardyn

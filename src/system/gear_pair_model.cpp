#include "geardyn/system/gear_pair_model.h"

#include <fmt/format.h>

#include <cmath>

#include "geardyn/error.h"

namespace geardyn {

double equivalentMass(double inertia1, double base_radius1, double inertia2, double base_radius2) {
  for (const auto& [key, value] :
       {std::pair{"pinion inertia", inertia1}, std::pair{"gear inertia", inertia2},
        std::pair{"pinion base radius", base_radius1},
        std::pair{"gear base radius", base_radius2}}) {
    if (!(value > 0.0) || !std::isfinite(value)) {
      throw InputError(key, fmt::format("{:g}", value), "must be finite and > 0");
    }
  }
  return inertia1 * inertia2 /
         (inertia1 * base_radius2 * base_radius2 + inertia2 * base_radius1 * base_radius1);
}

GearPairModel::GearPairModel(GearPairModelSpec spec) : spec_(std::move(spec)) {
  const auto finite = [](const char* key, double value) {
    if (!std::isfinite(value)) throw InputError(key, fmt::format("{}", value), "must be finite");
  };
  finite("model.mass", spec_.mass);
  finite("model.damping", spec_.damping);
  finite("model.mean_force", spec_.mean_force);
  finite("model.normal_backlash", spec_.backlash);
  finite("excitation.mesh_frequency", spec_.mesh_frequency);
  if (!(spec_.mass > 0.0))
    throw InputError("model.mass", fmt::format("{:g}", spec_.mass), "must be > 0 [kg]");
  if (spec_.damping < 0.0) {
    throw InputError("model.damping", fmt::format("{:g}", spec_.damping), "must be >= 0 [N s/m]");
  }
  if (spec_.backlash < 0.0) {
    throw InputError("model.normal_backlash", fmt::format("{:g} m", 2.0 * spec_.backlash),
                     "the clearance must be >= 0 [m]");
  }
  if (spec_.mesh_frequency < 0.0) {
    throw InputError("excitation.mesh_frequency", fmt::format("{:g}", spec_.mesh_frequency),
                     "must be >= 0");
  }
  if (!spec_.stiffness)
    throw InputError("model.stiffness", "", "a mesh-stiffness model is required");
  for (const auto& f : spec_.extra_forces) {
    finite("model.extra_forces", f.amplitude);
    finite("model.extra_forces", f.angular_frequency);
    finite("model.extra_forces", f.phase);
  }
}

double GearPairModel::meshForce(double t, double x, double* dforce_dx) const {
  if (spec_.contact_elements) {
    const double y = x - error(t), phase = meshPhase(t);
    double force = 0.0, slope = 0.0;
    for (int j = 0; j < spec_.contact_elements->count(); ++j) {
      double k = 0.0, gap = 0.0;
      spec_.contact_elements->element(phase, j, k, gap);
      if (y > gap) {
        force += k * (y - gap);
        slope += k;
      }
    }
    if (dforce_dx) *dforce_dx = slope;
    return force;
  }
  const double k = stiffness(t);
  double slope = 0.0;
  const double g = contactLaw(x - error(t), dforce_dx ? &slope : nullptr);
  if (dforce_dx) *dforce_dx = k * slope;
  return k * g;
}

double GearPairModel::externalForce(double t) const {
  double f = spec_.mean_force + spec_.damping * errorRate(t);
  for (const auto& h : spec_.extra_forces)
    f += h.amplitude * std::cos(h.angular_frequency * t + h.phase);
  return f;
}

double GearPairModel::acceleration(double t, double x, double v) const {
  return (externalForce(t) - spec_.damping * v - meshForce(t, x)) / spec_.mass;
}

}  // namespace geardyn

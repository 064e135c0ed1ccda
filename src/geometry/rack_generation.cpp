#include "geardyn/geometry/rack_generation.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geardyn/geometry/involute.h"

namespace geardyn {
namespace {

constexpr double kPi = std::numbers::pi;
/// Samples of u that bracket the fillet/involute crossings. The crossing is transversal and the
/// fillet bends on the scale of ρ: a crossing in and out again within 1/500 of the rounding's
/// quarter arc would need a fillet curved on the scale of ρ/300.
constexpr int kBracketSamples = 500;

/// Half-angle from the tooth centreline (+y) toward +x [rad].
double angleOf(const Eigen::Vector2d& p) {
  return std::atan2(p.x(), p.y());
}

}  // namespace

GeneratingRack generatingRack(const GearSpec& gear) {
  GeneratingRack rack;
  const double m_n = gear.normal_module;
  const double beta = std::abs(gear.helix_angle);
  rack.cos_beta = std::cos(beta);
  const double m_t = m_n / rack.cos_beta;
  rack.normal_pressure = gear.normal_pressure_angle;
  rack.transverse_pressure = std::atan(std::tan(rack.normal_pressure) / rack.cos_beta);
  const double alpha_t = rack.transverse_pressure;
  rack.pitch_radius = 0.5 * gear.teeth * m_t;
  rack.base_radius = rack.pitch_radius * std::cos(alpha_t);
  // ISO 21771 eq. (41): s_t = m_t (π/2 + 2 x tan α_n).
  const double s_t = m_t * (0.5 * kPi + 2.0 * gear.profile_shift * std::tan(rack.normal_pressure));
  rack.half_thickness_angle = s_t / (2.0 * rack.pitch_radius) + involute(alpha_t);
  rack.rounding_radius = gear.root_fillet_coefficient * m_n;

  const double y_ref = rack.pitch_radius + gear.profile_shift * m_n;
  const double rho = rack.rounding_radius;
  // Normal section: flank x_n(y) = π m_n / 4 + (y_ref − y) tan α_n, rounding centre ρ above
  // the tip line and ρ / cos α_n right of the flank (tangent to both); E = C − ρ (cos α_n,
  // sin α_n), h_FfP = h_f* m_n − ρ (1 − sin α_n) below the reference line.
  const double y_c = y_ref - gear.dedendum_coefficient * m_n + rho;
  const double x_c_normal = 0.25 * kPi * m_n + (y_ref - y_c) * std::tan(rack.normal_pressure) +
                            rho / std::cos(rack.normal_pressure);
  rack.rounding_centre = {x_c_normal / rack.cos_beta, y_c};
  rack.flank_end = {(x_c_normal - rho * std::cos(rack.normal_pressure)) / rack.cos_beta,
                    y_c - rho * std::sin(rack.normal_pressure)};
  rack.flank_end_roll = rack.pitch_radius * std::sin(alpha_t) -
                        (rack.pitch_radius - rack.flank_end.y()) / std::sin(alpha_t);
  return rack;
}

Eigen::Vector2d rackPointInGearFrame(const GeneratingRack& rack, const Eigen::Vector2d& p,
                                     double phi) {
  const Eigen::Vector2d relative = p - Eigen::Vector2d(-rack.pitch_radius * phi, 0.0);
  const double c = std::cos(phi), s = std::sin(phi);
  return {c * relative.x() - s * relative.y(), s * relative.x() + c * relative.y()};
}

double flankEndRollParameter(const GeneratingRack& rack) {
  // (E − I) normal to the flank, whose transverse direction is (−tan α_t, 1).
  const Eigen::Vector2d& e = rack.flank_end;
  const double r = rack.pitch_radius;
  return ((e.y() - r) / std::tan(rack.transverse_pressure) - e.x()) / r;
}

Eigen::Vector2d generatedFilletPoint(const GeneratingRack& rack, double u) {
  const double r = rack.pitch_radius;
  const double rho = rack.rounding_radius;
  if (rho > 0.0) {
    // Rounding point Q(θ) and tangent dQ/dθ (transverse section of the normal-section circle).
    const double theta = kPi + rack.normal_pressure + u * (0.5 * kPi - rack.normal_pressure);
    const Eigen::Vector2d q =
        rack.rounding_centre +
        Eigen::Vector2d(rho * std::cos(theta) / rack.cos_beta, rho * std::sin(theta));
    const Eigen::Vector2d dq(-rho * std::sin(theta) / rack.cos_beta, rho * std::cos(theta));
    // Envelope (Litvin & Fuentes §6.1): the relative velocity at Q, normal to Q − I, is
    // tangent to the rounding: (Q − I) · dQ/dθ = 0 with I = (−r φ, r), linear in φ.
    const double phi = -(q.x() + (q.y() - r) * dq.y() / dq.x()) / r;
    return rackPointInGearFrame(rack, q, phi);
  }
  // Sharp corner: its path from the roll where it lies on the line of action (the flank's
  // envelope condition) to the roll where it is right above the gear centre.
  const Eigen::Vector2d& q = rack.flank_end;
  const double phi_flank = flankEndRollParameter(rack);
  const double phi_bottom = -q.x() / r;
  return rackPointInGearFrame(rack, q, phi_flank + u * (phi_bottom - phi_flank));
}

double involuteHalfAngle(const GeneratingRack& rack, double radius) {
  const double alpha_y = std::acos(std::min(1.0, rack.base_radius / radius));
  return rack.half_thickness_angle - involute(alpha_y);
}

double trueFormRadius(const GeneratingRack& rack) {
  const double rb = rack.base_radius;
  if (rack.flank_end_roll >= 0.0) return std::hypot(rb, rack.flank_end_roll);
  // g(u) = ψ_fillet − ψ_involute at the fillet point's radius, where that radius is ≥ r_b.
  // g > 0: the fillet lies outside the involute tooth; g < 0: it cuts into it.
  struct Sample {
    double u, g, radius;
    bool valid;
  };
  const auto sample = [&](double u) {
    const Eigen::Vector2d p = generatedFilletPoint(rack, u);
    const double radius = p.norm();
    if (radius < rb) return Sample{u, 0.0, radius, false};
    return Sample{u, angleOf(p) - involuteHalfAngle(rack, radius), radius, true};
  };
  // The point of [a, b] where the fillet passes the base circle, on its valid side (a valid).
  const auto base_circle_crossing = [&](Sample a, Sample b) {
    for (int k = 0; k < 200 && std::abs(b.u - a.u) > 1e-16; ++k) {
      const Sample mid = sample(0.5 * (a.u + b.u));
      (mid.valid ? a : b) = mid;
    }
    return a;
  };
  double best = rb;
  Sample previous = sample(0.0);
  for (int i = 1; i <= kBracketSamples; ++i) {
    const Sample next = sample(static_cast<double>(i) / kBracketSamples);
    Sample lo = previous, hi = next;
    previous = next;
    if (!lo.valid && !hi.valid) continue;
    if (!lo.valid) lo = base_circle_crossing(hi, lo);
    if (!hi.valid) hi = base_circle_crossing(lo, hi);
    if ((lo.g > 0.0) == (hi.g > 0.0)) continue;
    for (int k = 0; k < 200 && hi.u - lo.u > 1e-16; ++k) {
      const Sample mid = sample(0.5 * (lo.u + hi.u));
      ((mid.g > 0.0) == (lo.g > 0.0) ? lo : hi) = mid;
    }
    best = std::max(best, 0.5 * (lo.radius + hi.radius));
  }
  return best;
}

}  // namespace geardyn

#include "geardyn/geometry/tooth_profile.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "geardyn/error.h"
#include "geardyn/geometry/involute.h"

namespace geardyn {
namespace {

constexpr double kPi = std::numbers::pi;

struct MemberData {
  const GearSpec& spec;
  const GearGeometry& geometry;
};

MemberData memberData(const GearPair& pair, Member member) {
  return member == Member::kPinion ? MemberData{pair.spec().pinion, pair.pinion()}
                                   : MemberData{pair.spec().gear, pair.gear()};
}

/// Polar form of a point in the gear frame: radius and angle from +y toward +x.
struct Polar {
  double radius, angle;
};

Polar toPolar(const Eigen::Vector2d& p) {
  return {p.norm(), std::atan2(p.x(), p.y())};
}

/// Envelope of the generating rack's tip rounding in the gear frame (the trochoidal fillet).
///
/// Rack frame (transverse section, heights measured from the gear centre, as the rack stands
/// when the tooth being cut is centred on +y): reference line y = r + x m_n; the right rack
/// flank x_F(y) = π m_t / 4 + (r + x m_n − y) tan α_t (so that the tooth is s_t thick on the
/// rolling line y = r); tip line y = r + x m_n − h_f* m_n; tip rounding of radius ρ = ρ_fP* m_n
/// tangent to both, centre C. For a roll parameter φ the gear centre is at G = (−r φ, 0), the
/// gear has turned by −φ, and the instantaneous centre of rotation is I = (−r φ, r). The
/// envelope point on the rounding is where its normal passes through I (Litvin, Gear Geometry
/// and Applied Theory, ch. 6): Q = C + ρ (C − I)/|C − I|; in the gear frame P = R(φ)(Q − G).
/// φ runs from the rounding's tangent point with the flank (normal −(cos α_t, sin α_t)) to its
/// tangent point with the tip line (normal (0, −1)), which lands on the root circle.
///
/// With undercut, the end E of the straight flank (the rounding's tangent point) passes beyond
/// the interference point and its own path — a prolate trochoid — cuts the involute back; that
/// path is returned in `flank_end_path` (φ over ±1.5 angular pitches about the generating
/// position), and `undercut` says whether E generates beyond T.
struct RackCut {
  std::vector<Eigen::Vector2d> envelope;
  std::vector<Eigen::Vector2d> flank_end_path;
  bool undercut = false;
};

RackCut rackCut(const GearPair& pair, const MemberData& m, int points) {
  const double r = m.geometry.pitch_radius;
  const double m_n = m.spec.normal_module;
  const double m_t = m.geometry.transverse_module;
  const double alpha = pair.transversePressureAngle();
  const double rho = m.spec.root_fillet_coefficient * m_n;
  const double y_ref = r + m.spec.profile_shift * m_n;
  const auto flank_x = [&](double y) { return 0.25 * kPi * m_t + (y_ref - y) * std::tan(alpha); };
  const double y_c = y_ref - m.spec.dedendum_coefficient * m_n + rho;
  const Eigen::Vector2d centre(flank_x(y_c) + rho / std::cos(alpha), y_c);

  const double phi_bottom = -centre.x() / r;
  const double t = (r - centre.y()) / std::sin(alpha);
  const double phi_flank = -(centre.x() + t * std::cos(alpha)) / r;

  // A rack point p at roll parameter φ, in the gear frame.
  const auto in_gear_frame = [&](const Eigen::Vector2d& p, double phi) {
    const Eigen::Vector2d relative = p - Eigen::Vector2d(-r * phi, 0.0);
    const double c = std::cos(phi), s = std::sin(phi);
    return Eigen::Vector2d(c * relative.x() - s * relative.y(),
                           s * relative.x() + c * relative.y());
  };

  RackCut cut;
  cut.envelope.reserve(points);
  for (int i = 0; i < points; ++i) {
    const double phi = phi_bottom + (phi_flank - phi_bottom) * i / (points - 1.0);
    const Eigen::Vector2d instant(-r * phi, r);
    Eigen::Vector2d q = centre;
    if (rho > 0.0) {
      const Eigen::Vector2d away = centre - instant;
      q += rho * away / away.norm();
    }
    cut.envelope.push_back(in_gear_frame(q, phi));
  }
  // E: the rounding's tangent point with the flank. At φ_flank it lies on the line of action;
  // beyond T (negative roll distance) the tooth is undercut.
  const Eigen::Vector2d flank_end =
      centre - rho * Eigen::Vector2d(std::cos(alpha), std::sin(alpha));
  const double roll_from_t = r * std::sin(alpha) - (r - flank_end.y()) / std::sin(alpha);
  cut.undercut = roll_from_t < 0.0;
  if (cut.undercut) {
    const double span = 1.5 * 2.0 * kPi / m.spec.teeth;
    const int path_points = 4 * points;
    cut.flank_end_path.reserve(path_points);
    for (int i = 0; i < path_points; ++i) {
      const double phi = phi_flank - span + 2.0 * span * i / (path_points - 1.0);
      cut.flank_end_path.push_back(in_gear_frame(flank_end, phi));
    }
  }
  return cut;  // envelope from the root circle (φ_bottom) up to the flank end (φ_flank)
}

/// Smallest angle at `radius` over the segments of a polar polyline that span it; +inf if none.
double smallestAngleAt(const std::vector<Polar>& curve, double radius) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i + 1 < curve.size(); ++i) {
    const Polar& a = curve[i];
    const Polar& b = curve[i + 1];
    const double lo = std::min(a.radius, b.radius), hi = std::max(a.radius, b.radius);
    if (radius < lo || radius > hi) continue;
    const double w = hi > lo ? (radius - a.radius) / (b.radius - a.radius) : 0.0;
    best = std::min(best, a.angle + w * (b.angle - a.angle));
  }
  return best;
}

}  // namespace

double involuteHalfAngle(const GearPair& pair, Member member, double radius) {
  const MemberData m = memberData(pair, member);
  const double r = m.geometry.pitch_radius;
  const double s_t =
      m.geometry.transverse_module *
      (0.5 * kPi + 2.0 * m.spec.profile_shift * std::tan(m.spec.normal_pressure_angle));
  const double alpha_y = std::acos(std::min(1.0, m.geometry.base_radius / radius));
  return s_t / (2.0 * r) + involute(pair.transversePressureAngle()) - involute(alpha_y);
}

ToothProfile computeToothProfile(const GearPair& pair, Member member, int points_per_segment) {
  if (points_per_segment < 8) {
    throw InputError("points_per_segment", std::to_string(points_per_segment), "must be >= 8");
  }
  const MemberData m = memberData(pair, member);
  const double rb = m.geometry.base_radius;
  const double ra = m.geometry.tip_radius;
  const double rf = m.geometry.root_radius;
  const int teeth = m.spec.teeth;

  ToothProfile profile;
  const RackCut cut = rackCut(pair, m, 2 * points_per_segment);
  profile.fillet = cut.envelope;
  std::vector<Polar> fillet_polar, flank_end_polar;
  for (const auto& p : cut.envelope) fillet_polar.push_back(toPolar(p));
  for (const auto& p : cut.flank_end_path) flank_end_polar.push_back(toPolar(p));

  // The straight flank of the rack generates the involute down to its end, the top of the
  // fillet envelope; with undercut that point lies beyond T and the involute is generated down
  // to the base circle, where the path of the flank's end cuts it back.
  const double involute_start = cut.undercut ? rb : fillet_polar.back().radius;

  // Radii: the fillet's own, then the involute's, evenly in roll distance (dense at the base).
  std::vector<double> radii;
  for (const auto& p : fillet_polar) radii.push_back(p.radius);
  for (const auto& p : flank_end_polar) radii.push_back(p.radius);
  const double roll_start = std::sqrt(std::max(0.0, involute_start * involute_start - rb * rb));
  const double roll_tip = std::sqrt(ra * ra - rb * rb);
  for (int i = 0; i < points_per_segment; ++i) {
    const double roll = roll_start + (roll_tip - roll_start) * i / (points_per_segment - 1.0);
    radii.push_back(std::hypot(rb, roll));
  }
  radii.push_back(involute_start);
  std::sort(radii.begin(), radii.end());
  radii.erase(std::unique(radii.begin(), radii.end(),
                          [](double a, double b) { return std::abs(a - b) < 1e-15; }),
              radii.end());

  // The tooth keeps, at each radius, the smallest half-angle any cutting curve leaves.
  std::vector<Polar> flank;
  profile.form_radius = ra;
  for (double radius : radii) {
    if (radius < rf || radius > ra) continue;
    double angle =
        std::min(smallestAngleAt(fillet_polar, radius), smallestAngleAt(flank_end_polar, radius));
    const bool involute_here = radius >= involute_start * (1.0 - 1e-12);
    if (involute_here) {
      const double psi = involuteHalfAngle(pair, member, radius);
      // Where fillet and involute meet they are tangent: a round-off tie goes to the involute.
      if (psi <= angle + 1e-12) {
        profile.form_radius = std::min(profile.form_radius, radius);
        angle = psi;
      }
    }
    if (std::isfinite(angle)) flank.push_back({radius, angle});
  }

  const auto point = [](double radius, double angle) {
    return Eigen::Vector2d(radius * std::sin(angle), radius * std::cos(angle));
  };
  // Root circle from the middle of the tooth space to the fillet, then up the flank, then the
  // tip circle to the tooth centreline.
  const double space_middle = kPi / teeth;
  constexpr int kArcPoints = 12;
  const double root_end = flank.front().angle;
  for (int i = 0; i < kArcPoints; ++i) {
    profile.points.push_back(point(rf, space_middle + (root_end - space_middle) * i / kArcPoints));
  }
  for (const Polar& p : flank) profile.points.push_back(point(p.radius, p.angle));
  const double tip_angle = flank.back().angle;
  for (int i = 1; i <= kArcPoints; ++i) {
    profile.points.push_back(point(ra, tip_angle * (1.0 - static_cast<double>(i) / kArcPoints)));
  }
  return profile;
}

}  // namespace geardyn

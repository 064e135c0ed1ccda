#include "geardyn/geometry/tooth_profile.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "geardyn/error.h"
#include "geardyn/geometry/involute.h"
#include "geardyn/geometry/rack_generation.h"

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

/// What the generating rack cuts (geometry/rack_generation.h): the envelope of its tip rounding
/// (the trochoidal fillet) from the root circle up to the point E where the rounding meets the
/// straight flank, and, with undercut, the path of E itself over ±1.5 angular pitches about its
/// generating position (a prolate trochoid; it lies inside what the rounding sweeps, a check
/// on the polyline rather than a cut of its own).
struct RackCut {
  std::vector<Eigen::Vector2d> envelope;
  std::vector<Eigen::Vector2d> flank_end_path;
  bool undercut = false;
  double form_radius = 0.0;  // true form radius r_Ff [m]
};

RackCut rackCut(const GeneratingRack& rack, int teeth, int points) {
  RackCut cut;
  cut.envelope.reserve(points);
  for (int i = 0; i < points; ++i) {
    cut.envelope.push_back(generatedFilletPoint(rack, 1.0 - i / (points - 1.0)));
  }
  cut.undercut = rack.flank_end_roll < 0.0;
  cut.form_radius = trueFormRadius(rack);
  if (cut.undercut) {
    const double phi_flank = flankEndRollParameter(rack);
    const double span = 1.5 * 2.0 * kPi / teeth;
    const int path_points = 4 * points;
    cut.flank_end_path.reserve(path_points);
    for (int i = 0; i < path_points; ++i) {
      const double phi = phi_flank - span + 2.0 * span * i / (path_points - 1.0);
      cut.flank_end_path.push_back(rackPointInGearFrame(rack, rack.flank_end, phi));
    }
  }
  return cut;  // envelope from the root circle up to the flank end
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
  const RackCut cut = rackCut(generatingRack(m.spec), teeth, 2 * points_per_segment);
  profile.fillet = cut.envelope;
  std::vector<Polar> fillet_polar, flank_end_polar;
  for (const auto& p : cut.envelope) fillet_polar.push_back(toPolar(p));
  for (const auto& p : cut.flank_end_path) flank_end_polar.push_back(toPolar(p));

  // The straight flank of the rack generates the involute down to its end, the top of the
  // fillet envelope; with undercut that point lies beyond T and the fillet cuts the involute
  // back down to the true form radius r_Ff, solved exactly (rack_generation.h).
  const double involute_start = cut.form_radius;

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
  profile.form_radius = involute_start;
  for (double radius : radii) {
    if (radius < rf || radius > ra) continue;
    double angle =
        std::min(smallestAngleAt(fillet_polar, radius), smallestAngleAt(flank_end_polar, radius));
    const bool involute_here = radius >= involute_start * (1.0 - 1e-12);
    if (involute_here) {
      const double psi = involuteHalfAngle(pair, member, radius);
      // From r_Ff up the involute is the profile (the fillet's chords, tangent to it at r_Ff
      // without undercut, may stray across it by their sag).
      angle = psi;
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

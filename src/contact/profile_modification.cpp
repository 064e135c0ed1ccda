#include "geardyn/contact/profile_modification.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "geardyn/error.h"
#include "geardyn/stiffness/potential_energy_stiffness.h"

namespace geardyn {

double Relief::at(double distance) const {
  if (amount == 0.0 || length <= 0.0 || distance >= length) return 0.0;
  const double x = 1.0 - std::max(distance, 0.0) / length;
  return amount * (shape == ReliefShape::kLinear ? x : x * x);
}

void Relief::validate(const char* key) const {
  if (!std::isfinite(amount) || amount < 0.0 || !std::isfinite(length) || length < 0.0 ||
      (amount > 0.0 && length == 0.0)) {
    throw InputError(key, fmt::format("amount {:g} m, length {:g} m", amount, length),
                     "amount and length must be finite and >= 0, with a length > 0 when the "
                     "amount is");
  }
}

void ToothModification::validate(const char* key) const {
  tip.validate(key);
  root.validate(key);
  if (!std::isfinite(crowning) || crowning < 0.0 || !std::isfinite(profile_slope_error)) {
    throw InputError(
        key, fmt::format("crowning {:g} m, slope error {:g} m", crowning, profile_slope_error),
        "crowning >= 0 and a finite slope error [m]");
  }
  for (double e : pitch_errors) {
    if (!std::isfinite(e)) throw InputError(key, "pitch error", "must be finite [m]");
  }
  end_relief.validate(key);
  if (!std::isfinite(helix_slope)) {
    throw InputError(key, fmt::format("helix slope {:g} m", helix_slope), "must be finite [m]");
  }
  if (lead_error_positions.size() != lead_errors.size()) {
    throw InputError(key,
                     fmt::format("{} lead error positions, {} lead errors",
                                 lead_error_positions.size(), lead_errors.size()),
                     "one error per position");
  }
  for (std::size_t i = 0; i < lead_errors.size(); ++i) {
    if (!std::isfinite(lead_errors[i]) || !std::isfinite(lead_error_positions[i]) ||
        (i > 0 && !(lead_error_positions[i] > lead_error_positions[i - 1]))) {
      throw InputError(
          key,
          fmt::format("lead error {:g} m at z = {:g} m", lead_errors[i], lead_error_positions[i]),
          "finite errors at strictly ascending face positions [m]");
    }
  }
}

namespace {

/// Linear interpolation of a table (constant beyond its ends; 0 when empty).
double interpolate(const std::vector<double>& x, const std::vector<double>& y, double at) {
  if (x.empty()) return 0.0;
  if (at <= x.front()) return y.front();
  if (at >= x.back()) return y.back();
  const auto hi = std::upper_bound(x.begin(), x.end(), at) - x.begin();
  const double t = (at - x[hi - 1]) / (x[hi] - x[hi - 1]);
  return y[hi - 1] + t * (y[hi] - y[hi - 1]);
}

double toothLead(const ToothModification& t, double z, double b) {
  double g = t.helix_slope * z / b;
  g += t.end_relief.at(z + 0.5 * b) + t.end_relief.at(0.5 * b - z);
  return g + interpolate(t.lead_error_positions, t.lead_errors, z);
}

}  // namespace

double PairModifications::leadSeparation(double z, double face_width) const {
  if (!(face_width > 0.0)) return 0.0;
  const double zeta = 2.0 * z / face_width;
  double g = (pinion.crowning + gear.crowning) * zeta * zeta;
  g += toothLead(pinion, z, face_width) + toothLead(gear, z, face_width);
  return g - misalignment * z / face_width;
}

double PairModifications::separation(double s, double z, int pinion_tooth, int gear_tooth,
                                     double s_begin, double s_end, double face_width) const {
  double g = 0.0;
  // Pinion: tip at s_end, root at s_begin; gear: tip at s_begin, root at s_end.
  g += pinion.tip.at(s_end - s) + pinion.root.at(s - s_begin);
  g += gear.tip.at(s - s_begin) + gear.root.at(s_end - s);
  g += leadSeparation(z, face_width);
  const double span = s_end - s_begin;
  if (span > 0.0) {
    const double t = (s - s_begin) / span - 0.5;  // −½ at the pinion root, +½ at its tip
    g += pinion.profile_slope_error * t - gear.profile_slope_error * t;
  }
  const auto pitch = [](const std::vector<double>& e, int tooth) {
    if (e.empty()) return 0.0;
    const int n = static_cast<int>(e.size());
    return e[((tooth % n) + n) % n];
  };
  g += pitch(pinion.pitch_errors, pinion_tooth) + pitch(gear.pitch_errors, gear_tooth);
  return g;
}

bool PairModifications::none() const {
  const auto empty = [](const ToothModification& m) {
    return m.tip.amount == 0.0 && m.root.amount == 0.0 && m.crowning == 0.0 &&
           m.profile_slope_error == 0.0 && m.pitch_errors.empty() && m.helix_slope == 0.0 &&
           m.end_relief.amount == 0.0 && m.lead_errors.empty();
  };
  return empty(pinion) && empty(gear) && misalignment == 0.0;
}

PairModifications designedTipRelief(const PotentialEnergyMeshStiffness& stiffness,
                                    double design_load, bool long_relief, ReliefShape shape) {
  if (!(design_load > 0.0) || !std::isfinite(design_load)) {
    throw InputError("modifications.design_load", fmt::format("{:g}", design_load),
                     "must be finite and > 0 [N]");
  }
  const double s_begin = stiffness.contactStart(), s_end = stiffness.contactEnd();
  const double pb = stiffness.basePitch();
  const double two_pair = (s_end - s_begin) - pb;  // each two-pair zone: (ε_α − 1) p_b
  if (!(two_pair > 0.0)) {
    throw InputError("modifications.relief", long_relief ? "long" : "short",
                     "needs a transverse contact ratio above 1");
  }
  const double s_single = 0.5 * (s_begin + s_end);
  const double deflection =
      design_load / (stiffness.faceWidth() * stiffness.pairStiffnessPerWidth(s_single));
  Relief r{deflection, long_relief ? two_pair : 0.5 * two_pair, shape};
  PairModifications m;
  m.pinion.tip = r;
  m.gear.tip = r;
  return m;
}

}  // namespace geardyn

#include "geardyn/stiffness/potential_energy_stiffness.h"

#include <fmt/format.h>

#include <algorithm>
#include <cassert>
#include <cmath>

#include "geardyn/error.h"
#include "geardyn/stiffness/foundation_fit_note.h"

namespace geardyn {
namespace {

double hubRadius(const std::optional<double>& given, const GearSpec& spec) {
  return given ? *given : 0.5 * spec.bore_diameter;
}

}  // namespace

void PotentialEnergyOptions::validate() const {
  if (slices < 0 || slices > 100000) {
    throw InputError("slices", std::to_string(slices),
                     "must be in [0, 100000] (0: exact integral)");
  }
  if (table_points < 16 || table_points > 1000000) {
    throw InputError("table_points", std::to_string(table_points), "must be in [16, 1000000]");
  }
  for (const auto& [name, value] : {std::pair{"pinion_hub_radius", pinion_hub_radius},
                                    std::pair{"gear_hub_radius", gear_hub_radius}}) {
    if (value && !(*value > 0.0 && std::isfinite(*value))) {
      throw InputError(name, fmt::format("{:g}", *value), "must be finite and > 0 [m]");
    }
  }
}

PotentialEnergyMeshStiffness::PotentialEnergyMeshStiffness(const GearPair& pair,
                                                           const PotentialEnergyOptions& options)
    : pinion_beam_((options.validate(), pair), Member::kPinion, options.root,
                   options.foundation_arm, options.foundation,
                   hubRadius(options.pinion_hub_radius, pair.spec().pinion)),
      gear_beam_(pair, Member::kGear, options.root, options.foundation_arm, options.foundation,
                 hubRadius(options.gear_hub_radius, pair.spec().gear)) {
  const GearSpec& g1 = pair.spec().pinion;
  const GearSpec& g2 = pair.spec().gear;
  rb1_ = pair.pinion().base_radius;
  rb2_ = pair.gear().base_radius;
  line_of_action_ = pair.lineOfActionLength();
  hertz_per_width_ = hertzStiffnessPerWidth(g1.youngs_modulus, g1.poisson_ratio, g2.youngs_modulus,
                                            g2.poisson_ratio);
  s_begin_ = std::min(pair.pathOfContactStart(), pair.pathOfContactEnd());
  s_end_ = std::max(pair.pathOfContactStart(), pair.pathOfContactEnd());
  base_pitch_ = pair.basePitchTransverse();
  face_width_ = pair.effectiveFaceWidth();
  stagger_ = face_width_ * std::tan(pair.baseHelixAngle());
  scale_ = options.helical_cos2_beta_b ? std::pow(std::cos(pair.baseHelixAngle()), 2) : 1.0;
  slices_ = options.slices;
  driver_is_pinion_ = pair.spec().driver == Driver::kPinion;
  window_ = (s_end_ - s_begin_) + stagger_;
  contact_ratio_ = window_ / base_pitch_;
  pair_slots_ = static_cast<int>(std::floor(contact_ratio_)) + 1;
  // GearPair starts the path of contact no lower than each member's true form radius (the end of
  // the generated involute, undercut included), the radius the beams' involutes start from.
  assert(s_begin_ / rb1_ >= pinion_beam_.involuteStartRoll() - 1e-9);
  assert((line_of_action_ - s_end_) / rb2_ >= gear_beam_.involuteStartRoll() - 1e-9);

  // Table of k′(s) with fourth-order slopes and the exact running integral of its interpolant.
  const int n = options.table_points;
  step_ = (s_end_ - s_begin_) / (n - 1);
  values_.resize(n);
  for (int i = 0; i < n; ++i) values_[i] = pairStiffnessPerWidthExact(s_begin_ + i * step_);
  slopes_.resize(n);
  const auto& f = values_;
  const double h12 = 12.0 * step_;
  for (int i = 0; i < n; ++i) {
    if (i >= 2 && i <= n - 3) {
      slopes_[i] = (-f[i + 2] + 8 * f[i + 1] - 8 * f[i - 1] + f[i - 2]) / h12;
    } else if (i < 2) {
      slopes_[i] = i == 0 ? (-25 * f[0] + 48 * f[1] - 36 * f[2] + 16 * f[3] - 3 * f[4]) / h12
                          : (-3 * f[0] - 10 * f[1] + 18 * f[2] - 6 * f[3] + f[4]) / h12;
    } else {
      const int m = n - 1;
      slopes_[i] =
          i == m ? (25 * f[m] - 48 * f[m - 1] + 36 * f[m - 2] - 16 * f[m - 3] + 3 * f[m - 4]) / h12
                 : (3 * f[m] + 10 * f[m - 1] - 18 * f[m - 2] + 6 * f[m - 3] - f[m - 4]) / h12;
    }
  }
  cumulative_.assign(n, 0.0);
  for (int i = 0; i + 1 < n; ++i) {
    cumulative_[i + 1] = cumulative_[i] + step_ * (0.5 * (f[i] + f[i + 1]) +
                                                   step_ * (slopes_[i] - slopes_[i + 1]) / 12.0);
  }

  assessFoundationFit();

  // Where the piecewise structure changes (in progress u along the window, mod one pitch):
  // spur pairs enter and leave; helical slices (or the face's ends) enter and leave.
  std::vector<double> progress = {0.0, s_end_ - s_begin_};
  if (stagger_ > 0.0) {
    if (slices_ == 0) {
      progress.push_back(stagger_);
      progress.push_back(window_);
    } else {
      progress.clear();
      for (int i = 0; i < slices_; ++i) {
        const double enter = stagger_ - (i + 0.5) * stagger_ / slices_;
        progress.push_back(enter);
        progress.push_back(enter + (s_end_ - s_begin_));
      }
    }
  }
  for (double u : progress) breaks_.push_back(wrapPhase(u / base_pitch_));
  std::sort(breaks_.begin(), breaks_.end());
  breaks_.erase(std::unique(breaks_.begin(), breaks_.end(),
                            [](double a, double b) { return std::abs(a - b) < 1e-14; }),
                breaks_.end());
}

/// The mean mesh stiffness is k̄ = (b/p_b) ∫ k′(s) ds over the path of contact (every pair
/// crosses the whole path once per base pitch), so the relative change of ∫ k′ ds with the
/// foundation fits held at their data range is that of k̄. Both integrals use the table's grid
/// and the trapezoidal rule, whose error cancels in the ratio.
void PotentialEnergyMeshStiffness::assessFoundationFit() {
  const std::string& pinion = pinion_beam_.foundationFitExtrapolation();
  const std::string& gear = gear_beam_.foundationFitExtrapolation();
  if (pinion.empty() && gear.empty()) return;
  const int n = static_cast<int>(values_.size());
  const auto trapezoid = [n](const auto& k_at) {
    double sum = 0.0;
    for (int i = 0; i < n; ++i) sum += (i == 0 || i == n - 1 ? 0.5 : 1.0) * k_at(i);
    return sum;
  };
  // As fitted: the table already holds k′ on the grid.
  const double as_fitted = trapezoid([&](int i) { return values_[i]; });
  const ToothBeam pinion_fitted = pinion_beam_, gear_fitted = gear_beam_;
  pinion_beam_ = pinion_fitted.withFoundationFitClamped();
  gear_beam_ = gear_fitted.withFoundationFitClamped();
  const double held =
      trapezoid([&](int i) { return pairStiffnessPerWidthExact(s_begin_ + i * step_); });
  pinion_beam_ = pinion_fitted;
  gear_beam_ = gear_fitted;

  foundation_fit_effect_ = held / as_fitted - 1.0;
  foundation_fit_note_ = fmt::format("{}{}{}", pinion.empty() ? "" : "pinion: " + pinion,
                                     !pinion.empty() && !gear.empty() ? "; " : "",
                                     gear.empty() ? "" : "gear: " + gear);
  if (std::abs(foundation_fit_effect_) > kFoundationFitWarning) {
    warnings_.push_back(foundationFitWarning(foundation_fit_note_, foundation_fit_effect_));
  }
}

ToothCompliance PotentialEnergyMeshStiffness::pinionCompliance(double s) const {
  return pinion_beam_.compliance(std::max(s / rb1_, pinion_beam_.involuteStartRoll()));
}

ToothCompliance PotentialEnergyMeshStiffness::gearCompliance(double s) const {
  return gear_beam_.compliance(
      std::max((line_of_action_ - s) / rb2_, gear_beam_.involuteStartRoll()));
}

double PotentialEnergyMeshStiffness::pairStiffnessPerWidthExact(double s) const {
  if (s < s_begin_ - 1e-15 || s > s_end_ + 1e-15) return 0.0;
  // Visnadi eq. 9 per unit width: the pair is a series of both teeth and the contact.
  const double compliance =
      1.0 / hertz_per_width_ + pinionCompliance(s).total() + gearCompliance(s).total();
  return 1.0 / compliance;
}

double PotentialEnergyMeshStiffness::interpolate(double s) const {
  if (s < s_begin_ || s > s_end_) return 0.0;
  const double t = (s - s_begin_) / step_;
  const int i = std::min(static_cast<int>(t), static_cast<int>(values_.size()) - 2);
  const double x = t - i;
  const double x2 = x * x, x3 = x2 * x;
  return (2 * x3 - 3 * x2 + 1) * values_[i] + (x3 - 2 * x2 + x) * step_ * slopes_[i] +
         (-2 * x3 + 3 * x2) * values_[i + 1] + (x3 - x2) * step_ * slopes_[i + 1];
}

double PotentialEnergyMeshStiffness::pairStiffnessPerWidth(double s) const {
  return interpolate(s);
}

double PotentialEnergyMeshStiffness::runningIntegral(double u) const {
  if (u <= s_begin_) return 0.0;
  if (u >= s_end_) return cumulative_.back();
  const double t = (u - s_begin_) / step_;
  const int i = std::min(static_cast<int>(t), static_cast<int>(values_.size()) - 2);
  const double x = t - i;
  const double x2 = x * x, x3 = x2 * x, x4 = x3 * x;
  // ∫₀ˣ of the Hermite basis functions.
  const double i00 = x - x3 + 0.5 * x4, i10 = 0.5 * x2 - 2.0 * x3 / 3.0 + 0.25 * x4;
  const double i01 = x3 - 0.5 * x4, i11 = -x3 / 3.0 + 0.25 * x4;
  return cumulative_[i] + step_ * (values_[i] * i00 + step_ * slopes_[i] * i10 +
                                   values_[i + 1] * i01 + step_ * slopes_[i + 1] * i11);
}

double PotentialEnergyMeshStiffness::pairAt(double s_pair) const {
  if (stagger_ <= 0.0) return face_width_ * interpolate(s_pair);
  if (slices_ == 0) {
    // ∫₀ᵇ k′(s + z tan β_b) dz = (b / stagger) [C(s + stagger) − C(s)].
    return scale_ * face_width_ / stagger_ *
           (runningIntegral(s_pair + stagger_) - runningIntegral(s_pair));
  }
  double sum = 0.0;
  const double width = face_width_ / slices_;
  for (int i = 0; i < slices_; ++i) sum += interpolate(s_pair + (i + 0.5) * stagger_ / slices_);
  return scale_ * width * sum;
}

bool PotentialEnergyMeshStiffness::pairSection(double phase, int pair, double& s_pair) const {
  // Progress of pair j along its window: u = (φ + j) p_b, in contact for 0 <= u < window.
  const double u = (wrapPhase(phase) + pair) * base_pitch_;
  if (pair < 0 || u >= window_) return false;
  s_pair = driver_is_pinion_ ? s_begin_ - stagger_ + u : s_end_ - u;
  return true;
}

double PotentialEnergyMeshStiffness::pairStiffness(double phase, int pair) const {
  double s_pair = 0.0;
  return pairSection(phase, pair, s_pair) ? pairAt(s_pair) : 0.0;
}

double PotentialEnergyMeshStiffness::stiffness(double phase) const {
  double total = 0.0;
  for (int j = 0; j < pair_slots_; ++j) total += pairStiffness(phase, j);
  return total;
}

}  // namespace geardyn

/// The input speed profile (speed_profile.h).

#include "geardyn/system/speed_profile.h"

namespace geardyn {

double SpeedProfile::speed(double t) const {
  if (t <= ramp_start || ramp_end <= ramp_start) return t <= ramp_start ? start : end;
  if (t >= ramp_end) return end;
  return start + (end - start) * (t - ramp_start) / (ramp_end - ramp_start);
}

double SpeedProfile::acceleration(double t) const {
  if (ramp_end <= ramp_start || t <= ramp_start || t >= ramp_end) return 0.0;
  return (end - start) / (ramp_end - ramp_start);
}

double SpeedProfile::angle(double t) const {
  if (t <= ramp_start || ramp_end <= ramp_start) {
    return t <= ramp_start ? start * t : start * ramp_start + end * (t - ramp_start);
  }
  const double ramp = std::min(t, ramp_end) - ramp_start;
  const double rate = (end - start) / (ramp_end - ramp_start);
  double angle = start * ramp_start + start * ramp + 0.5 * rate * ramp * ramp;
  if (t > ramp_end) angle += end * (t - ramp_end);
  return angle;
}

}  // namespace geardyn

/// Gear whirl components, frames and keyphasor pulses.

#include "geardyn/signal/gear_whirl.h"

#include <gtest/gtest.h>

#include <cmath>

#include "geardyn/error.h"
#include "geardyn/system/lateral_rotor.h"

namespace geardyn {
namespace {

TEST(GearWhirl, ComponentsMatchTheModelsForcing) {
  const LateralRotorModel model(raoTable41Spec());
  const auto forcing = model.whirlForcing();
  const auto components = gearWhirlComponents({11.0, 16, 35, 5});
  ASSERT_EQ(components.size(), forcing.size());
  for (std::size_t i = 0; i < forcing.size(); ++i) {
    EXPECT_EQ(components[i].name, forcing[i].name);
    EXPECT_NEAR(components[i].frequency * 2 * M_PI, forcing[i].omega, 1e-9);
  }
  EXPECT_NEAR(GearWhirlSetup({11.0, 16, 35, 5}).commonPeriod(), 35.0 / 11.0, 1e-15);
  EXPECT_NEAR(GearWhirlSetup({10.0, 20, 30, 1}).commonPeriod(), 3.0 / 10.0, 1e-15);  // gcd 10
}

TEST(GearWhirl, ShaftFrameOfANegativelyTurningShaft) {
  const WhirlComponent c{"pinion_1x_bwd", -11.0, {1.0, 2.0}};
  const WhirlComponent s = inShaftFrame(c, true);
  EXPECT_EQ(s.name, "pinion_1x_fwd");
  EXPECT_EQ(s.frequency, 11.0);
  EXPECT_EQ(s.value, std::complex<double>(1.0, -2.0));
  EXPECT_EQ(inShaftFrame({"mesh_2_fwd", 352.0, 1.0}, true).name, "mesh_2_bwd");
  EXPECT_EQ(inShaftFrame(c, false).name, "pinion_1x_bwd");
  EXPECT_EQ(inShaftFrame({"static", 0.0, 1.0}, true).name, "static");
}

/// A trapezoidal once-per-revolution pulse whose rising edge is linear across 4 samples around
/// the crossing: linear interpolation then finds the crossing exactly.
std::vector<double> pulses(double fs, int n, double speed, double first) {
  std::vector<double> v(n);
  for (int i = 0; i < n; ++i) {
    const double t = i / fs;
    double phase = std::fmod((t - first) * speed, 1.0);
    if (phase < 0) phase += 1.0;
    const double since = phase / speed;  // time since the last pulse
    const double to_next = (1.0 - phase) / speed;
    const double ramp = 4.0 / fs;
    double value = 0.0;
    if (to_next < ramp / 2)
      value = 0.5 - to_next / ramp;
    else if (since < ramp / 2)
      value = 0.5 + since / ramp;
    else if (since < 0.1 / speed)
      value = 1.0;
    else if (since < 0.1 / speed + ramp)
      value = 1.0 - (since - 0.1 / speed) / ramp;
    v[i] = value;
  }
  return v;
}

TEST(Keyphasor, FindsPulsesToRoundOffAndTheSpeed) {
  const double fs = 5000.0, speed = 16.15, first = 0.0123456;
  const auto k = pulses(fs, 5000, speed, first);
  const KeyphasorPulses p = findKeyphasorPulses(k, fs, 0.0);
  ASSERT_GE(p.times.size(), 15u);
  for (std::size_t i = 0; i < p.times.size(); ++i)
    EXPECT_NEAR(p.times[i], first + i / speed, 1e-12);
  EXPECT_NEAR(p.speed, speed, 1e-9);
}

TEST(Keyphasor, RejectsMissingPulsesAndFlatChannels) {
  const double fs = 5000.0;
  auto k = pulses(fs, 5000, 16.15, 0.01);
  // Remove the 5th pulse: one revolution appears twice as long.
  const int at = static_cast<int>((0.01 + 4 / 16.15) * fs);
  for (int i = at - 10; i < at + 400; ++i) k[i] = 0.0;
  EXPECT_THROW(findKeyphasorPulses(k, fs, 0.0), InputError);
  EXPECT_THROW(findKeyphasorPulses(std::vector<double>(100, 1.0), fs, 0.0), InputError);
  auto one = pulses(fs, 100, 16.15, 0.01);  // a single pulse in 20 ms
  EXPECT_THROW(findKeyphasorPulses(one, fs, 0.0), InputError);
  k = pulses(fs, 500, 16.15, 0.01);
  k[7] = NAN;
  EXPECT_THROW(findKeyphasorPulses(k, fs, 0.0), InputError);
}

}  // namespace
}  // namespace geardyn

/// Run-up of a gear train: Newmark along a speed ramp and its derived defaults (train_runup.h).

#include "geardyn/solvers/train_runup.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geardyn/error.h"
#include "geardyn/solvers/train_modal.h"
#include "geardyn/solvers/train_response.h"
#include "geardyn/units.h"

namespace geardyn {

using units::kRpm;
namespace {
constexpr double kTwoPi = 2.0 * std::numbers::pi;
// Damping ratios below this are round-off of an undamped mode (the eigensolver's accuracy).
constexpr double kUndampedRatio = 1e-10;
// Mesh harmonics of the steady state a run-up starts from (the forced response's default).
constexpr int kStartMeshHarmonics = 10;
// Steps between progress reports and divergence checks.
constexpr long long kCheckEvery = 1000;

double carrierSpeedRatio(const GearTrainModel& model, int stage) {
  const std::string& carrier = model.spec().stages[stage].carrier;
  for (std::size_t s = 0; s < model.spec().shafts.size(); ++s) {
    if (model.spec().shafts[s].name == carrier)
      return model.bodies()[model.shaftBody(static_cast<int>(s))].speed_ratio;
  }
  return 0.0;
}
}  // namespace

void TrainRunUpOptions::validate() const {
  newmark.validate();
  ramp.validate();
  if (!(time_step >= 0.0) || !std::isfinite(time_step)) {
    throw InputError("runup.time_step", fmt::format("{:g} s", time_step),
                     "a step >= 0 s (0: derived)");
  }
  if (steps_per_mesh_period < 8) {
    throw InputError("runup.steps_per_mesh_period", std::to_string(steps_per_mesh_period),
                     "an integer >= 8");
  }
  if (!(speed_tolerance > 0.0 && speed_tolerance < 1.0)) {
    throw InputError("runup.speed_tolerance", fmt::format("{:g}", speed_tolerance),
                     "a relative tolerance in (0, 1)");
  }
}

double trainRunUpTimeStep(const GearTrainModel& model, const TrainSpeedRamp& ramp,
                          int steps_per_mesh_period) {
  double fastest = 0.0;
  for (const TrainMesh& m : model.meshes()) fastest = std::max(fastest, m.frequency_ratio);
  fastest *= ramp.maxSpeed();
  if (!(fastest > 0.0)) {
    throw InputError("runup.speed_max_rpm", "0 rpm", "a speed > 0 (no mesh frequency at rest)");
  }
  return 1.0 / (fastest * steps_per_mesh_period);
}

TrainRunUpResponse solveTrainRunUp(const GearTrainModel& model, const TrainRunUpOptions& options) {
  options.validate();
  if (model.meshes().empty()) throw InputError("meshes", "", "a train with at least one mesh");
  const int n = model.dofCount();
  for (int d : options.dofs) {
    if (d < 0 || d >= n)
      throw InputError("runup.channels", std::to_string(d), "a DOF of the train");
  }
  const double dt = options.time_step > 0.0
                        ? options.time_step
                        : trainRunUpTimeStep(model, options.ramp, options.steps_per_mesh_period);
  const long long steps = static_cast<long long>(std::ceil(options.ramp.duration / dt - 1e-9));
  TrainRunUpResponse r;
  r.time_step = dt;
  const Eigen::Index samples = steps + 1;
  const auto r_meshes = static_cast<Eigen::Index>(model.meshes().size());
  const auto channels = static_cast<Eigen::Index>(options.dofs.size());
  r.t.resize(samples);
  r.speed.resize(samples);
  r.angle.resize(samples);
  r.mesh_force.resize(samples, r_meshes);
  r.displacement.resize(samples, channels);

  TrainNewmarkStepper stepper(model, options.ramp, dt, options.newmark, options.speed_tolerance);
  Eigen::VectorXd q0 = Eigen::VectorXd::Zero(n), v0 = Eigen::VectorXd::Zero(n);
  r.start = "rest";
  if (options.start == TrainRunUpOptions::Start::kSteadyState && options.ramp.start != 0.0) {
    try {
      // q(t) = Re[X₀ + 2 Σ_h X_h e^{i h ω₀ t}] at t = 0, and its derivative.
      TrainSteadyOptions steady;
      steady.mesh_harmonics = kStartMeshHarmonics;
      const TrainSteadyState s = solveTrainSteadyState(model, options.ramp.start, steady);
      const double w0 = kTwoPi * s.base_frequency;
      q0 = s.harmonic.col(0).real();
      for (Eigen::Index h = 1; h < s.harmonic.cols(); ++h) {
        q0 += 2.0 * s.harmonic.col(h).real();
        v0 -= 2.0 * static_cast<double>(h) * w0 * s.harmonic.col(h).imag();
      }
      r.start = "steady_state";
    } catch (const InputError&) {
      // A common period too long for the balance: start from the static deflection.
    }
  }
  if (r.start == "rest" && options.start != TrainRunUpOptions::Start::kRest) {
    q0 = solveTrainStatic(model, options.ramp.start).displacement;
    r.start = "static";
  }
  stepper.reset(0.0, q0, v0);
  auto record = [&](Eigen::Index i) {
    r.t(i) = stepper.time();
    r.speed(i) = stepper.speed();
    r.angle(i) = options.ramp.angle(stepper.time());
    for (Eigen::Index m = 0; m < r_meshes; ++m)
      r.mesh_force(i, m) = stepper.meshForce(static_cast<int>(m));
    for (Eigen::Index c = 0; c < channels; ++c)
      r.displacement(i, c) = stepper.displacement()(options.dofs[c]);
  };
  record(0);
  for (long long k = 1; k <= steps; ++k) {
    stepper.step();
    record(k);
    if (k % kCheckEvery == 0) {
      if (!stepper.displacement().allFinite()) {
        r.status = "diverged";
        r.message = fmt::format("Newmark diverged at t = {:.6g} s ({:.1f} rpm)", stepper.time(),
                                stepper.speed() / kRpm);
        r.steps = k;
        r.factorisations = stepper.factorisations();
        return r;
      }
      if (options.progress) options.progress(static_cast<double>(k), static_cast<double>(steps));
    }
  }
  r.steps = steps;
  r.factorisations = stepper.factorisations();
  r.message =
      fmt::format("{} Newmark steps of {:.3g} s, {} factorisation(s)", steps, dt, r.factorisations);
  return r;
}

TrainRunUpDefaults trainRunUpDefaults(const GearTrainModel& model, double start, double end,
                                      int mesh_harmonics, int modes, double window, int speeds) {
  const double lo = std::min(std::abs(start), std::abs(end));
  const double hi = std::max(std::abs(start), std::abs(end));
  TrainRunUpDefaults d;
  d.window = window;
  if (!(d.window > 0.0)) {
    // kWindowCommonPeriods common periods (1e9 base harmonics: no limit, as for the time
    // response) and at least one input revolution, at the mean speed.
    const double mean = 0.5 * (lo + hi);
    const double base = trainBaseFrequency(model, 1, 1000000000).ratio * mean;
    double slowest = HUGE_VAL;  // the slowest mesh frequency [Hz]
    for (const TrainMesh& m : model.meshes()) slowest = std::min(slowest, m.frequency_ratio * mean);
    // A train whose meshes have no small common period: kWindowSlowestMeshPeriods instead.
    d.window = std::max(std::min(kWindowCommonPeriods / base, kWindowSlowestMeshPeriods / slowest),
                        kTwoPi / mean);
  }
  double duration = kMinRunUpWindows * d.window;
  if (hi > lo) {
    std::vector<double> grid(speeds);
    for (int i = 0; i < speeds; ++i) grid[i] = lo + (hi - lo) * i / (speeds - 1.0);
    TrainModalOptions mo;
    mo.modes = std::min(modes, model.dofCount());
    std::vector<TrainOrderLine> lines;
    for (const TrainOrderLine& l : trainOrderLines(model, mesh_harmonics)) {
      if (l.name.find("mesh") != std::string::npos) lines.push_back(l);
    }
    const TrainCampbell c = trainCampbell(model, grid, mo, lines);
    for (const TrainCriticalSpeed& cs : c.critical_speeds) {
      // The tracked mode at the nearest grid speed.
      const auto i = static_cast<std::size_t>(
          std::clamp(std::lround((cs.speed - lo) / (hi - lo) * (speeds - 1.0)), 0L,
                     static_cast<long>(speeds - 1)));
      const TrainMode& mode = c.modes[i][cs.mode];
      double mesh_energy = 0.0;
      for (double e : mode.mesh_strain_energy) mesh_energy += e;
      if (mesh_energy < kExcitedMeshEnergy) continue;
      double slope = 0.0;  // the line's frequency per unit speed [Hz per rad/s]
      for (const TrainOrderLine& l : lines) {
        if (l.name == cs.line) slope = l.slope;
      }
      // ḟ = slope (hi − lo) / T <= 4π ζ² f² / kSweepTimeConstants.
      // An undamped mode (ζ at round-off) asks for an infinite duration.
      const double zeta = mode.damping_ratio > kUndampedRatio ? mode.damping_ratio : 0.0;
      const double sweep =
          zeta > 0.0 ? kSweepTimeConstants * slope * (hi - lo) /
                           (4.0 * std::numbers::pi * zeta * zeta * cs.frequency * cs.frequency)
                     : HUGE_VAL;
      d.resonances.push_back({cs.mode, cs.line, cs.speed, cs.frequency, zeta, sweep});
      duration = std::max(duration, sweep);
    }
  }
  d.duration = duration;
  return d;
}

double trainRampInertiaTorque(const GearTrainModel& model, const TrainSpeedRamp& ramp) {
  double inertia = 0.0;  // reduced to the input [kg m²]
  for (const TrainBody& b : model.bodies()) {
    inertia += b.polar_inertia * b.speed_ratio * b.speed_ratio;
    if (b.kind == TrainBodyKind::kPlanet && b.stage >= 0) {
      // A planet's centre orbits with its carrier: m |c|² ω_c².
      const double ratio = carrierSpeedRatio(model, b.stage);
      inertia += b.mass * b.centre.squaredNorm() * ratio * ratio;
    }
  }
  return inertia * std::abs(ramp.end - ramp.start) / ramp.duration;
}

}  // namespace geardyn

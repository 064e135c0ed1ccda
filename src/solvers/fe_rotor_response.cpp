/// The FE geared rotor's time response through the gear train's Newmark stepper (see header).

#include "geardyn/solvers/fe_rotor_response.h"

#include <fmt/format.h>

#include <cmath>

#include "geardyn/error.h"

namespace geardyn {

void FeTimeOptions::validate() const {
  newmark.validate();
  if (!(time_step > 0.0) || !std::isfinite(time_step))
    throw InputError("time.time_step", fmt::format("{:g}", time_step), "a time step > 0 s");
  if (!(duration >= time_step) || !std::isfinite(duration))
    throw InputError("time.duration", fmt::format("{:g}", duration),
                     "a duration of at least one time step");
  if (!(gyro_speed_tolerance > 0.0) || !(gyro_speed_tolerance < 1.0))
    throw InputError("time.gyro_speed_tolerance", fmt::format("{:g}", gyro_speed_tolerance),
                     "a relative tolerance in (0, 1)");
  if (record_every < 1)
    throw InputError("time.record_every", std::to_string(record_every), "an integer >= 1");
}

std::string toString(FeTimeStatus status) {
  return status == FeTimeStatus::kCompleted ? "completed" : "diverged";
}

TrainNewmarkStepper feRotorStepper(const FeRotorModel& model, const FeTimeOptions& options) {
  options.validate();
  TrainStepperSetup setup;
  setup.dofs = model.trainDofs();
  setup.static_load = model.staticLoad();
  const SpeedProfile& p = model.speed();
  if (p.constant()) {
    return TrainNewmarkStepper(model.train(), p.start, options.time_step, options.newmark,
                               std::nullopt, std::move(setup));
  }
  const TrainSpeedRamp ramp{p.start, p.end, p.ramp_end - p.ramp_start, p.ramp_start};
  return TrainNewmarkStepper(model.train(), ramp, options.time_step, options.newmark,
                             options.gyro_speed_tolerance, std::nullopt, std::move(setup));
}

FeTimeResponse solveFeRotorTimeResponse(const FeRotorModel& model, const FeTimeOptions& options) {
  options.validate();
  FeTimeResponse r;
  const int n = model.dofCount();
  r.channels = options.channels;
  if (r.channels.empty()) {
    for (int i = 0; i < n; ++i) r.channels.push_back(i);
  }
  for (int c : r.channels) {
    if (c < 0 || c >= n) throw InputError("time.channels", std::to_string(c), "an active DOF");
  }
  const long long steps = std::llround(options.duration / options.time_step);
  const long long samples = steps / options.record_every + 1;
  const int nc = static_cast<int>(r.channels.size());
  r.displacement.resize(samples, nc);
  r.velocity.resize(samples, nc);
  r.acceleration.resize(samples, nc);
  r.t.reserve(samples);

  TrainNewmarkStepper stepper = feRotorStepper(model, options);
  const Eigen::VectorXd q0 =
      options.start_from_static ? stepper.staticDeflection(0.0) : Eigen::VectorXd::Zero(n);
  stepper.reset(0.0, q0, Eigen::VectorXd::Zero(n));
  long long row = 0;
  auto record = [&] {
    for (int j = 0; j < nc; ++j) {
      r.displacement(row, j) = stepper.displacement()(r.channels[j]);
      r.velocity(row, j) = stepper.velocity()(r.channels[j]);
      r.acceleration(row, j) = stepper.acceleration()(r.channels[j]);
    }
    r.t.push_back(stepper.time());
    r.speed.push_back(model.speed().speed(stepper.time()));
    r.mesh_stiffness.push_back(stepper.meshStiffness(0));
    r.mesh_force.push_back(stepper.meshForce(0));
    ++row;
  };
  record();
  for (long long s = 1; s <= steps; ++s) {
    stepper.step();
    r.steps = s;
    if (options.progress && s % 1000 == 0) options.progress(static_cast<double>(s), steps);
    if (s % options.record_every == 0) {
      if (!std::isfinite(stepper.displacement().squaredNorm())) {
        r.status = FeTimeStatus::kDiverged;
        r.message = fmt::format("non-finite response at t = {:.6g} s (step {})", stepper.time(), s);
        break;
      }
      record();
    }
  }
  r.displacement.conservativeResize(row, nc);
  r.velocity.conservativeResize(row, nc);
  r.acceleration.conservativeResize(row, nc);
  r.factorisations = stepper.factorisations();
  if (r.converged()) {
    r.message = fmt::format("{} Newmark steps of {:.3g} s, {} factorisation(s)", r.steps,
                            options.time_step, r.factorisations);
  }
  return r;
}

}  // namespace geardyn

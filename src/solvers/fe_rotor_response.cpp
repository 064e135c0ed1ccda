/// Newmark integration of the FE geared rotor with a rank-1 time-varying mesh (see header).

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

FeNewmarkStepper::FeNewmarkStepper(const FeGearedRotor& model, const FeTimeOptions& options)
    : model_(model),
      dt_(options.time_step),
      gamma_(options.newmark.gamma),
      gyro_tolerance_(options.gyro_speed_tolerance),
      nm_(options.newmark, options.time_step) {
  options.validate();
  const int n = model.dofCount();
  k_ref_ = model.meanMeshStiffness();
  A_.resize(n, n);
  Cg_.resize(n, n);
  K0_ = model.stiffness() + k_ref_ * model.meshVector() * model.meshVector().transpose();
  for (Eigen::VectorXd* x : {&q_, &v_, &a_, &z_, &rhs_, &y_, &p_, &c_, &f_}) x->setZero(n);
  factorise(model.spec().speed.speed(0.0));
}

void FeNewmarkStepper::factorise(double speed) {
  const FeGearedRotor& m = model_;
  Cg_ = m.damping() + speed * m.gyroscopic();
  A_ = K0_ + nm_.a0 * m.mass() + nm_.a1 * Cg_;  // coefficient-wise: no temporary
  lu_.compute(A_);
  z_ = lu_.solve(m.meshVector());
  s_ = m.meshVector().dot(z_);
  speed_factorised_ = speed;
  ++factorisations_;
}

void FeNewmarkStepper::force(double t, Eigen::VectorXd& f) {
  const double phase = model_.meshPhase(t);
  k_ = model_.meshStiffness(phase);
  e_ = model_.transmissionError(phase);
  f = model_.staticLoad();
  if (e_ != 0.0) f.noalias() += (k_ * e_) * model_.meshVector();
  model_.addUnbalanceForce(t, f);
}

void FeNewmarkStepper::reset(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot) {
  t_ = t;
  q_ = q;
  v_ = qdot;
  const double speed = model_.spec().speed.speed(t);
  if (speed != speed_factorised_) factorise(speed);
  force(t, f_);
  const Eigen::VectorXd& w = model_.meshVector();
  f_ -= Cg_ * v_ + model_.stiffness() * q_ + k_ * w * w.dot(q_);
  a_ = model_.mass().ldlt().solve(f_);
}

double FeNewmarkStepper::meshForce() const {
  return k_ * (model_.meshVector().dot(q_) - e_);
}

void FeNewmarkStepper::step() {
  const double t1 = t_ + dt_;
  const auto& profile = model_.spec().speed;
  if (!profile.constant()) {
    const double speed = profile.speed(t1);
    if (std::abs(speed - speed_factorised_) > gyro_tolerance_ * profile.maxSpeed()) {
      factorise(speed);
    }
  }
  force(t1, f_);
  // rhs = f + M (a0 q + a2 v + a3 a) + Cg (a1 q + a4 v + a5 a)
  p_ = nm_.a0 * q_ + nm_.a2 * v_ + nm_.a3 * a_;
  c_ = nm_.a1 * q_ + nm_.a4 * v_ + nm_.a5 * a_;
  rhs_ = f_;
  rhs_.noalias() += model_.mass() * p_;
  rhs_.noalias() += Cg_ * c_;
  y_ = lu_.solve(rhs_);
  // (A + Δk v vᵀ)⁻¹ rhs = y − z Δk (vᵀy) / (1 + Δk vᵀz)   (Sherman–Morrison)
  const double dk = k_ - k_ref_;
  const double scale = dk * model_.meshVector().dot(y_) / (1.0 + dk * s_);
  y_.noalias() -= scale * z_;
  // New acceleration and velocity; p_ is reused for the old acceleration.
  p_ = a_;
  a_ = nm_.a0 * (y_ - q_) - nm_.a2 * v_ - nm_.a3 * p_;
  v_ += dt_ * ((1.0 - gamma_) * p_ + gamma_ * a_);
  q_.swap(y_);
  t_ = t1;
}

Eigen::VectorXd feStaticDeflection(const FeGearedRotor& model, double k, double e) {
  const Eigen::VectorXd& w = model.meshVector();
  const Eigen::MatrixXd K = model.stiffness() + k * w * w.transpose();
  const Eigen::VectorXd f = model.staticLoad() + (k * e) * w;
  return K.completeOrthogonalDecomposition().solve(f);
}

FeTimeResponse solveFeRotorTimeResponse(const FeGearedRotor& model, const FeTimeOptions& options) {
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

  FeNewmarkStepper stepper(model, options);
  Eigen::VectorXd q0 = Eigen::VectorXd::Zero(n);
  if (options.start_from_static) {
    const double phase = model.meshPhase(0.0);
    q0 = feStaticDeflection(model, model.meshStiffness(phase), model.transmissionError(phase));
  }
  stepper.reset(0.0, q0, Eigen::VectorXd::Zero(n));
  long long row = 0;
  auto record = [&] {
    for (int j = 0; j < nc; ++j) {
      r.displacement(row, j) = stepper.displacement()(r.channels[j]);
      r.velocity(row, j) = stepper.velocity()(r.channels[j]);
      r.acceleration(row, j) = stepper.acceleration()(r.channels[j]);
    }
    r.t.push_back(stepper.time());
    r.speed.push_back(model.spec().speed.speed(stepper.time()));
    r.mesh_stiffness.push_back(stepper.meshStiffness());
    r.mesh_force.push_back(stepper.meshForce());
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

/// Newmark integration of a gear train with time-varying mesh stiffness (train_time.h).

#include "geardyn/solvers/train_time.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <utility>

#include "geardyn/error.h"
#include "geardyn/solvers/detail/train_time_dormand_prince.h"
#include "geardyn/solvers/detail/train_time_full_law.h"
#include "geardyn/solvers/train_modal.h"
#include "geardyn/solvers/train_response.h"
#include "geardyn/units.h"

namespace geardyn {

using units::kRpm;

/// Plain steps per DOF on new factors before the dense step switches to the precomputed
/// products (TrainNewmarkStepper: their cost is paid back after about 2n steps).
constexpr Eigen::Index kPlainSteps = 4;

void TrainTimeOptions::validate() const {
  newmark.validate();
  if (!(relative_tolerance >= 1e-14 && relative_tolerance <= 1e-2)) {
    throw InputError("time.relative_tolerance", fmt::format("{:g}", relative_tolerance),
                     "a tolerance in [1e-14, 1e-2]");
  }
  if (!(time_step >= 0.0) || !std::isfinite(time_step)) {
    throw InputError("time.time_step", fmt::format("{:g} s", time_step),
                     "a step >= 0 s (0: derived)");
  }
  if (steps_per_mesh_period < 8) {
    throw InputError("time.steps_per_mesh_period", std::to_string(steps_per_mesh_period),
                     "an integer >= 8");
  }
  if (!(duration >= 0.0) || !std::isfinite(duration)) {
    throw InputError("time.duration", fmt::format("{:g} s", duration),
                     "a duration >= 0 s (0: derived)");
  }
  if (record_periods < 1) {
    throw InputError("time.record_periods", std::to_string(record_periods), "an integer >= 1");
  }
}

void TrainSpeedRamp::validate() const {
  if (!std::isfinite(start) || !std::isfinite(end) || start * end < 0.0) {
    throw InputError("runup.speed_max_rpm", fmt::format("{:g} rpm", end / kRpm),
                     fmt::format("a speed of the same sign as runup.speed_min_rpm = {:g} rpm (the "
                                 "train does not reverse)",
                                 start / kRpm));
  }
  if (!(duration > 0.0) || !std::isfinite(duration)) {
    throw InputError("runup.duration", fmt::format("{:g} s", duration), "a duration > 0 s");
  }
  if (!(begin >= 0.0) || !std::isfinite(begin)) {
    throw InputError("speed.ramp_start", fmt::format("{:g} s", begin), "a time >= 0 s");
  }
}

double TrainSpeedRamp::speed(double t) const noexcept {
  if (t <= begin) return start;
  const double s = t - begin;
  return s >= duration ? end : start + (end - start) * (s / duration);
}

double TrainSpeedRamp::angle(double t) const noexcept {
  const double a = std::abs(start), b = std::abs(end);
  if (t <= begin) return a * t;
  const double s = t - begin;
  if (s <= duration) return a * begin + (a * s + 0.5 * (b - a) * (s * s / duration));
  return a * begin + (0.5 * (a + b) * duration + b * (s - duration));
}

TrainNewmarkStepper::TrainNewmarkStepper(const GearTrainModel& model, double input_speed,
                                         double time_step, NewmarkParameters newmark,
                                         std::optional<bool> sparse, TrainStepperSetup setup)
    : model_(model),
      speed_(input_speed),
      dt_(time_step),
      gamma_(newmark.gamma),
      nm_(newmark, time_step),
      force_(std::move(setup.force)) {
  newmark.validate();
  const int r = static_cast<int>(model.meshes().size());
  V_.resize(model.dofCount(), r);
  for (int m = 0; m < r; ++m) V_.col(m) = model.meshVector(m);
  F0_ = model.staticLoad();
  if (!setup.dofs.empty()) restrict(setup.dofs), dofs_ = setup.dofs;
  external_ = static_cast<bool>(force_) || !model.excitations().empty();
  if (!model.excitations().empty()) excitation_.setZero(model.dofCount());
  const int n = static_cast<int>(V_.rows());
  if (setup.static_load.size() > 0) {
    if (setup.static_load.size() != n) {
      throw std::invalid_argument(fmt::format(
          "TrainStepperSetup::static_load: {} entries for {} DOFs", setup.static_load.size(), n));
    }
    F0_ = setup.static_load;
  }
  sparse_ = sparse.value_or(n >= kSparseTrainDofs);
  if (sparse_) {
    // Entries below 1e-14 of the largest are round-off of cancelling sums, not couplings.
    Msp_ = M().sparseView(1.0, 1e-14 * M().cwiseAbs().maxCoeff());
  }
  speed_dependent_ = G().cwiseAbs().maxCoeff() > 0.0 || Kc().cwiseAbs().maxCoeff() > 0.0;
  Cg_.resize(n, n);
  K0_.resize(n, n);
  A_.resize(n, n);
  Z_.resize(n, r);
  S_.resize(r, r);
  lu_ = Eigen::PartialPivLU<Eigen::MatrixXd>(n);
  q_ = v_ = a_ = f_ = fx_ = rhs_ = y_ = g0_ = Eigen::VectorXd::Zero(n);
  if (!sparse_) PQ_.resize(n, 2 * n), pc_.setZero(2 * n);
  factorise(speed_);
  small_ = Eigen::PartialPivLU<Eigen::MatrixXd>(r);
  small_matrix_ = Eigen::MatrixXd::Zero(r, r);
  w_ = w_solved_ = dk_ = ke_ = k_ = e_ = Eigen::VectorXd::Zero(r);
}

TrainNewmarkStepper::TrainNewmarkStepper(const GearTrainModel& model, const TrainSpeedRamp& ramp,
                                         double time_step, NewmarkParameters newmark,
                                         double speed_tolerance, std::optional<bool> sparse,
                                         TrainStepperSetup setup)
    : TrainNewmarkStepper(model, (ramp.validate(), ramp.start), time_step, newmark, sparse,
                          std::move(setup)) {
  if (!(speed_tolerance > 0.0 && speed_tolerance < 1.0)) {
    throw InputError("runup.speed_tolerance", fmt::format("{:g}", speed_tolerance),
                     "a relative tolerance in (0, 1)");
  }
  ramp_ = ramp;
  tolerance_ = speed_tolerance;
}

void TrainNewmarkStepper::restrict(const std::vector<int>& dofs) {
  const int n = static_cast<int>(dofs.size());
  for (int i : dofs) {
    if (i < 0 || i >= model_.dofCount()) {
      throw std::invalid_argument(
          fmt::format("TrainStepperSetup::dofs: DOF {} of a train of {}", i, model_.dofCount()));
    }
  }
  auto sub = [&](const Eigen::MatrixXd& A, Eigen::MatrixXd& out) {
    out.resize(n, n);
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) out(i, j) = A(dofs[i], dofs[j]);
  };
  sub(model_.mass(), Mr_), sub(model_.stiffness(), Kr_), sub(model_.damping(), Cr_);
  sub(model_.gyroscopic(), Gr_), sub(model_.centripetal(), Kcr_);
  sub(model_.meanMeshStiffness(), Kmeshr_);
  restricted_ = true;
  const Eigen::MatrixXd V = V_;
  const Eigen::VectorXd F0 = F0_;
  V_.resize(n, V.cols());
  F0_.resize(n);
  for (int i = 0; i < n; ++i) V_.row(i) = V.row(dofs[i]), F0_(i) = F0(dofs[i]);
}

void TrainNewmarkStepper::factorise(double speed) {
  // The expressions of GearTrainModel::dampingAt and meanStiffnessAt, written into the
  // preallocated matrices (coefficient-wise: no temporaries).
  Cg_ = C() + speed * G();
  K0_ = K() + Kmesh() + speed * speed * Kc();
  A_ = K0_ + nm_.a0 * M() + nm_.a1 * Cg_;
  if (sparse_) {
    Cgsp_ = Cg_.sparseView(1.0, 1e-14 * std::max(Cg_.cwiseAbs().maxCoeff(), 1e-300));
    const Eigen::SparseMatrix<double> Asp = A_.sparseView(1.0, 1e-14 * A_.cwiseAbs().maxCoeff());
    if (!slu_.factorize(Asp)) {
      throw InputError("gearbox", "",
                       "a train whose Newmark matrix can be factorised: " + slu_.message());
    }
    for (Eigen::Index c = 0; c < V_.cols(); ++c) {
      slu_.solve(V_.col(c), y_);
      Z_.col(c) = y_;
    }
  } else {
    lu_.compute(A_);
    for (Eigen::Index c = 0; c < V_.cols(); ++c) {
      rhs_ = V_.col(c);
      y_ = lu_.solve(rhs_);
      Z_.col(c) = y_;
    }
  }
  S_.noalias() = V_.transpose() * Z_;  // W = Vᵀ A⁻¹ V; the step's matrix is I + D W
  speed_factorised_ = speed;
  ++factorisations_;
  products_ = false;
  steps_on_factors_ = 0;
}

void TrainNewmarkStepper::precomputeProducts() {
  // The step's solve as products: A⁻¹ b = A⁻¹F₀ + Z ke + [A⁻¹M  A⁻¹(C + ΩG₁)] [p; c].
  const Eigen::Index n = A_.rows();
  PQ_.leftCols(n) = lu_.solve(M());
  PQ_.rightCols(n) = lu_.solve(Cg_);
  rhs_ = F0_;
  g0_ = lu_.solve(rhs_);
  products_ = true;
}

void TrainNewmarkStepper::meshState(double t) {
  const auto& meshes = model_.meshes();
  const double speed = ramp_ ? ramp_->speed(t) : speed_;
  const double angle = ramp_ ? ramp_->angle(t) : 0.0;
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    const double phi =
        ramp_ ? meshes[m].frequency_ratio * angle + meshes[m].phase : meshes[m].phaseAt(t, speed_);
    k_(m) = meshes[m].stiffness->stiffness(phi);
    dk_(m) = k_(m) - meshes[m].mean_stiffness;
    const TransmissionError& e = meshes[m].transmission_error;
    e_(m) = e.value(phi);
    // k e + c ė, ė = de/dφ f_m.
    ke_(m) = k_(m) * e_(m) +
             meshes[m].damping * e.derivative(phi) * meshes[m].frequency_ratio * std::abs(speed);
  }
}

void TrainNewmarkStepper::externalForce(double t) {
  fx_.setZero();
  if (force_) force_(t, fx_);
  if (excitation_.size() == 0) return;
  // The input's rotation α = ∫|Ω| dt, |Ω| and d|Ω|/dt (train_excitation.h).
  double angle = std::abs(speed_) * t, rate = 0.0;
  if (ramp_) {
    angle = ramp_->angle(t);
    const double s = t - ramp_->begin;
    if (s > 0.0 && s < ramp_->duration)
      rate = (std::abs(ramp_->end) - std::abs(ramp_->start)) / ramp_->duration;
  }
  excitation_.setZero();
  addExcitationForce(model_.excitations(), angle, ramp_ ? ramp_->speed(t) : speed_, rate, k_.data(),
                     excitation_);
  if (dofs_.empty()) {
    fx_ += excitation_;
  } else {
    for (std::size_t i = 0; i < dofs_.size(); ++i) fx_(i) += excitation_(dofs_[i]);
  }
}

void TrainNewmarkStepper::reset(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot) {
  t_ = t;
  q_ = q;
  v_ = qdot;
  if (ramp_) {
    speed_ = ramp_->speed(t);
    if (speed_dependent_ && speed_ != speed_factorised_) factorise(speed_);
  }
  meshState(t);
  // M a = F − C v − K(t) q.
  f_ = F0_ + V_ * ke_ - Cg_ * v_ - K0_ * q_ - V_ * (dk_.asDiagonal() * (V_.transpose() * q_));
  if (external_) {
    externalForce(t);
    f_ += fx_;
  }
  a_ = M().llt().solve(f_);
}

Eigen::VectorXd TrainNewmarkStepper::staticDeflection(double t) {
  meshState(t);
  const double speed = ramp_ ? ramp_->speed(t) : speed_;
  // K + Ω² K_Ω + Σ k_m(t) v_m v_mᵀ.
  Eigen::MatrixXd Kt = K() + Kmesh() + speed * speed * Kc();
  Kt.noalias() += V_ * (dk_.asDiagonal() * V_.transpose());
  // The constant loads and the meshes' k e (no dashpot force at rest; the time-dependent force
  // is an excitation, not a load the rotor rests under).
  const Eigen::VectorXd f = F0_ + V_ * k_.cwiseProduct(e_);
  return Kt.completeOrthogonalDecomposition().solve(f);
}

void TrainNewmarkStepper::step() {
  const double t1 = t_ + dt_;
  if (ramp_) {
    speed_ = ramp_->speed(t1);
    if (speed_dependent_ && std::abs(speed_ - speed_factorised_) > tolerance_ * ramp_->maxSpeed())
      factorise(speed_);
  }
  meshState(t1);
  if (external_) externalForce(t1);
  if (sparse_) {
    rhs_.noalias() = F0_;
    rhs_.noalias() += V_ * ke_;
    if (external_) rhs_ += fx_;
    y_ = nm_.a0 * q_ + nm_.a2 * v_ + nm_.a3 * a_;
    rhs_.noalias() += Msp_ * y_;
    y_ = nm_.a1 * q_ + nm_.a4 * v_ + nm_.a5 * a_;
    rhs_.noalias() += Cgsp_ * y_;
    slu_.solve(rhs_, y_);
  } else if (!products_ && ++steps_on_factors_ <= kPlainSteps * q_.size()) {
    // The first 4n steps on new factors: two products and two triangular solves (4n²), while
    // the products below (2n³ in triangular solves, ~100 plain steps of the 60-DOF rotor)
    // would not yet have paid for themselves (a run-up refactorises every ~100 steps).
    rhs_.noalias() = F0_;
    rhs_.noalias() += V_ * ke_;
    if (external_) rhs_ += fx_;
    y_ = nm_.a0 * q_ + nm_.a2 * v_ + nm_.a3 * a_;
    rhs_.noalias() += M() * y_;
    y_ = nm_.a1 * q_ + nm_.a4 * v_ + nm_.a5 * a_;
    rhs_.noalias() += Cg_ * y_;
    y_ = lu_.solve(rhs_);
  } else {
    // One product with the precomputed [A⁻¹M  A⁻¹(C + ΩG₁)] (2n²) instead of two products and
    // two triangular solves.
    if (!products_) precomputeProducts();
    const Eigen::Index n = q_.size();
    pc_.head(n) = nm_.a0 * q_ + nm_.a2 * v_ + nm_.a3 * a_;
    pc_.tail(n) = nm_.a1 * q_ + nm_.a4 * v_ + nm_.a5 * a_;
    y_ = g0_;
    y_.noalias() += PQ_ * pc_;
    y_.noalias() += Z_ * ke_;
    if (external_) {
      rhs_ = lu_.solve(fx_);
      y_ += rhs_;
    }
  }
  if (dk_.size() == 1) {
    // One mesh: Woodbury is Sherman–Morrison, (A + d v vᵀ)⁻¹ b = y − z d (vᵀy) / (1 + d vᵀz).
    const double d = dk_(0);
    y_.noalias() -= (d * V_.col(0).dot(y_) / (1.0 + d * S_(0, 0))) * Z_.col(0);
  } else if (dk_.size() > 1) {
    // Woodbury: (A + V D Vᵀ)⁻¹ b = y − Z (I + D W)⁻¹ D Vᵀ y.
    w_.noalias() = V_.transpose() * y_;
    w_.array() *= dk_.array();
    small_matrix_.noalias() = dk_.asDiagonal() * S_;
    small_matrix_.diagonal().array() += 1.0;
    small_.compute(small_matrix_);
    // Into another vector: solving in place would permute w_ in place, which allocates a mask.
    w_solved_ = small_.solve(w_);
    y_.noalias() -= Z_ * w_solved_;
  }
  // y_ is q_{n+1}.
  rhs_ = nm_.a0 * (y_ - q_) - nm_.a2 * v_ - nm_.a3 * a_;  // a_{n+1}
  v_ += dt_ * ((1.0 - gamma_) * a_ + gamma_ * rhs_);
  a_ = rhs_;
  q_ = y_;
  t_ = t1;
}

double TrainNewmarkStepper::meshForce(int mesh) const {
  // k(φ) g(vᵀq − e(φ)) at the phase of the last step (TrainMesh::force at constant speed).
  const TrainMesh& m = model_.meshes()[mesh];
  return k_(mesh) * m.contactDeflection(V_.col(mesh).dot(q_) - e_(mesh));
}

TrainTimePlan planTrainTimeResponse(const GearTrainModel& model, double input_speed,
                                    const TrainTimeOptions& options) {
  options.validate();
  if (model.meshes().empty() && model.excitations().empty()) {
    throw InputError("meshes", "(none)",
                     "a train that something drives: at least one mesh, unbalance, runout or "
                     "bearing excitation");
  }
  if (!(std::abs(input_speed) > 0.0)) {
    throw InputError("operating_point.speed_rpm", "0", "a speed != 0 for a time response");
  }
  // The fastest forcing [Hz per rad/s of input speed]: a mesh frequency, or (a train without
  // meshes, e.g. a rotor with an unbalance) the fastest excitation order |ν| Ω / 2π; the
  // default step resolves its period by steps_per_mesh_period.
  double fastest = 0.0;
  for (const TrainMesh& m : model.meshes()) fastest = std::max(fastest, m.frequency_ratio);
  if (model.meshes().empty()) {
    for (const TrainExcitationTerm& e : model.excitations())
      fastest = std::max(fastest, std::abs(e.ratio) / (2.0 * std::numbers::pi));
  }
  fastest *= std::abs(input_speed);
  TrainTimePlan plan;
  // The common period of all meshes (1e9 base harmonics: no limit for the time domain).
  plan.period = 1.0 / (trainBaseFrequency(model, 1, 1000000000).ratio * std::abs(input_speed));
  const double dt =
      options.time_step > 0 ? options.time_step : 1.0 / (fastest * options.steps_per_mesh_period);
  plan.steps_per_period = static_cast<long long>(std::ceil(plan.period / dt - 1e-9));
  plan.time_step = plan.period / static_cast<double>(plan.steps_per_period);  // whole steps
  plan.duration = options.duration;
  if (plan.duration == 0.0) {
    plan.transient = trainTransient(model, input_speed);
    if (!std::isfinite(plan.transient->decay_time)) {
      plan.duration = HUGE_VAL;
      plan.steps = std::numeric_limits<long long>::max();
      return plan;  // solveTrainTimeResponse refuses it; the caller may name the keys first
    }
    plan.duration = plan.transient->decay_time + options.record_periods * plan.period;
  }
  const double periods =
      std::max<double>(options.record_periods, std::ceil(plan.duration / plan.period));
  plan.steps = periods * static_cast<double>(plan.steps_per_period) > 9e18
                   ? std::numeric_limits<long long>::max()
                   : static_cast<long long>(periods) * plan.steps_per_period;
  return plan;
}

TrainTimeResponse solveTrainTimeResponse(const GearTrainModel& model, double input_speed,
                                         const TrainTimeOptions& options,
                                         const ProgressCallback& progress) {
  return solveTrainTimeResponse(model, input_speed, options,
                                planTrainTimeResponse(model, input_speed, options), progress);
}

TrainTimeResponse solveTrainTimeResponse(const GearTrainModel& model, double input_speed,
                                         const TrainTimeOptions& options, const TrainTimePlan& plan,
                                         const ProgressCallback& progress) {
  const std::optional<TrainTransient>& transient = plan.transient;
  if (transient && !std::isfinite(transient->decay_time)) {
    const auto excited = std::find_if(transient->undamped.begin(), transient->undamped.end(),
                                      [](const TrainUndampedMode& m) { return m.excited; });
    throw InputError("time.duration", "0 (derived)",
                     fmt::format("a duration > 0 s: the mode at {:.4g} Hz has no damping and the "
                                 "forcing excites it, so its transient never decays (damp it, or "
                                 "give time.duration)",
                                 excited->frequency));
  }
  const double dt = plan.time_step;
  const long long per_period = plan.steps_per_period;
  const long long steps = plan.steps;
  if (steps > kMaxTrainTimeSteps) {
    const std::string given =
        transient
            ? fmt::format(
                  "0 (derived: {:.4g} s for the mode at {:.4g} Hz with damping "
                  "ratio {:.3g} to decay)",
                  plan.duration, transient->slowest_frequency, transient->slowest_damping_ratio)
            : fmt::format("{:g} s", plan.duration);
    throw InputError(
        "time.duration", given,
        fmt::format("fewer than {:.0e} steps of {:.3g} s (this run needs {:.3g}); {}",
                    static_cast<double>(kMaxTrainTimeSteps), dt, static_cast<double>(steps),
                    transient ? "damp that mode or give a shorter time.duration"
                              : "shorten it or coarsen time.steps_per_mesh_period"));
  }
  if (options.method == TrainTimeMethod::kDormandPrince) {
    return detail::solveTrainTimeDormandPrince(model, input_speed, options, plan, progress);
  }
  // A rolling bearing's full law: the nonlinear Newmark on the same plan.
  if (detail::hasFullBearingLaw(model)) {
    return detail::solveTrainTimeFullLaw(model, input_speed, options, plan, progress);
  }
  TrainNewmarkStepper stepper(model, input_speed, dt, options.newmark);
  const int n = model.dofCount();
  Eigen::VectorXd q0 = Eigen::VectorXd::Zero(n);
  if (options.start_from_static) q0 = solveTrainStatic(model, input_speed).displacement;
  stepper.reset(0.0, q0, Eigen::VectorXd::Zero(n));

  TrainTimeResponse r;
  r.time_step = dt;
  r.transient = transient;
  const long long recorded = options.record_periods * per_period;
  const long long first = steps - recorded;
  detail::sizeTrainTimeRecord(r, recorded, n, static_cast<int>(model.meshes().size()),
                              options.record_rates);
  for (long long k = 1; k <= steps; ++k) {
    stepper.step();
    if (k % per_period == 0 && progress)
      progress(static_cast<double>(k), static_cast<double>(steps));
    if (k % per_period == 0 && !stepper.displacement().allFinite()) {
      r.status = "diverged";
      r.message = fmt::format("Newmark diverged at t = {:.6g} s", stepper.time());
      r.steps = k;
      return r;
    }
    if (k > first) detail::recordTrainTimeSample(r, k - first - 1, stepper, options.record_rates);
  }
  r.steps = steps;
  return r;
}

}  // namespace geardyn

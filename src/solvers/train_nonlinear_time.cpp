/// Newmark with Newton on the mesh deflections for gear trains with contact loss and backlash
/// (train_nonlinear_time.h).

#include "geardyn/solvers/train_nonlinear_time.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "geardyn/error.h"
#include "geardyn/solvers/train_response.h"

namespace geardyn {

void TrainNonlinearTimeOptions::validate() const {
  newmark.validate();
  if (steps_per_mesh_period < 8) {
    throw InputError("nonlinear.steps_per_mesh_period", std::to_string(steps_per_mesh_period),
                     "an integer >= 8");
  }
  if (min_periods < 1 || max_periods < min_periods) {
    throw InputError("nonlinear.max_periods", std::to_string(max_periods),
                     fmt::format("an integer >= min_periods = {} >= 1", min_periods));
  }
  // The finest step: below ~2^-19 of a mesh period the acceleration update a₀(q' − q) − a₂v − a
  // loses the digits the steady-state test needs (round-off ~ ε |q| a₀; measured: 2^-21 of a
  // mesh period stalls the test at 1e-7 where 2^-19 reaches 1e-10).
  const int finest =
      kMaxFinestStepsLog2 -
      static_cast<int>(std::floor(std::log2(static_cast<double>(steps_per_mesh_period))));
  const int most = std::max(0, std::min(kMaxEventRefinement, finest));
  const auto check = [&](const char* key, int value) {
    if (value < 0 || value > most) {
      throw InputError(key, std::to_string(value),
                       fmt::format("an integer in [0, {}] (steps_per_mesh_period {} x "
                                   "2^refinement <= 2^{})",
                                   most, steps_per_mesh_period, kMaxFinestStepsLog2));
    }
  };
  check("nonlinear.newmark_event_refinement", event_refinement);
  check("nonlinear.newmark_contact_refinement", contact_refinement);
  if (!(steady_tolerance > 0.0) || !(newton_tolerance > 0.0) || max_newton_iterations < 1) {
    throw InputError("nonlinear.steady_tolerance", fmt::format("{:g}", steady_tolerance),
                     "tolerances > 0 and max_newton_iterations >= 1");
  }
}

double TrainNonlinearTimeResponse::meshPeakToPeak(int mesh) const {
  return mesh_deflection.col(mesh).maxCoeff() - mesh_deflection.col(mesh).minCoeff();
}

double TrainNonlinearTimeResponse::bearingRadialPeakToPeak(int bearing) const {
  const Eigen::VectorXd radius = bearing_displacement.middleCols(2 * bearing, 2).rowwise().norm();
  return radius.maxCoeff() - radius.minCoeff();
}

TrainNonlinearNewmark::TrainNonlinearNewmark(const GearTrainModel& model, double input_speed,
                                             double time_step, NewmarkParameters newmark,
                                             int event_refinement, int contact_refinement)
    : model_(model),
      speed_(input_speed),
      gamma_(newmark.gamma),
      jump_levels_(event_refinement),
      contact_levels_(contact_refinement) {
  newmark.validate();
  refuseExcitations(model, "the nonlinear time response");
  for (auto [key, levels] :
       {std::pair{"nonlinear.newmark_event_refinement", event_refinement},
        std::pair{"nonlinear.newmark_contact_refinement", contact_refinement}}) {
    if (levels < 0 || levels > TrainNonlinearTimeOptions::kMaxEventRefinement) {
      throw InputError(
          key, std::to_string(levels),
          fmt::format("an integer in [0, {}]", TrainNonlinearTimeOptions::kMaxEventRefinement));
    }
  }
  // The force can jump only where a k(φ) jumps or tooth pairs engage: elsewhere no level for it
  // (every level holds an n × n factorisation).
  bool jumps = false;
  for (const TrainMesh& mesh : model.meshes()) {
    breaks_.push_back(mesh.stiffness->discontinuities());
    jumps = jumps || mesh.toothPairs() || !breaks_.back().empty();
  }
  if (!jumps) jump_levels_ = 0;
  const int finest = std::max(jump_levels_, contact_levels_);
  const int n = model.dofCount();
  meshes_ = static_cast<int>(model.meshes().size());
  const int bearings = static_cast<int>(model.clearanceBearings().size());
  int r = meshes_;
  laws_ = trainBearingLaws(model);
  for (const TrainBearingLaw& law : laws_) {
    bearing_first_.push_back(r);
    r += law.width();
  }
  Cg_ = model.dampingAt(speed_);
  K0_ = model.meanStiffnessAt(speed_);
  V_ = model.nonlinearVectors();  // [V, bearing columns]: δ, then (u_y, u_z) per bearing
  levels_.resize(finest + 1);
  for (int l = 0; l <= finest; ++l) {
    Level& level = levels_[l];
    level.dt = std::ldexp(time_step, -l);
    level.nm = NewmarkCoefficients(newmark, level.dt);
    level.lu.compute(K0_ + level.nm.a0 * model.mass() + level.nm.a1 * Cg_);
    level.Z = level.lu.solve(V_);
    level.W = V_.transpose() * level.Z;
  }
  small_ = Eigen::PartialPivLU<Eigen::MatrixXd>(r);
  J_.resize(r, r);
  slope_ = Eigen::MatrixXd::Zero(r, r);
  q_ = v_ = a_ = rhs_ = y_ = Eigen::VectorXd::Zero(n);
  delta_ = f_ = res_ = dashpot_ = free_ = step_ = Eigen::VectorXd::Zero(r);
  k_ = e_ = Eigen::VectorXd::Zero(meshes_);
  tooth_pairs_.resize(meshes_);
  events_.assign(2 * meshes_ + bearings, 0);
  saved_.resize(finest);
  for (Saved& s : saved_) {
    s.q = s.v = s.a = q_;
    s.delta = delta_;
    s.events = events_;
  }
  meshState(0.0);  // sizes the tooth-pair tables once: steps refill them without allocating
}

void TrainNonlinearNewmark::meshState(double t) {
  const auto& meshes = model_.meshes();
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    const TrainMesh& mesh = meshes[m];
    const double phi = mesh.phaseAt(t, speed_);
    k_(m) = mesh.stiffness->stiffness(phi);
    e_(m) = mesh.transmission_error.value(phi);
    if (mesh.toothPairs()) tooth_pairs_[m].tabulate(*mesh.contact.tooth_pairs, &phi, 1);
    // c ė, ė = de/dφ f_m.
    dashpot_(m) = mesh.damping * mesh.transmission_error.derivative(phi) * mesh.frequency_ratio *
                  std::abs(speed_);
  }
}

void TrainNonlinearNewmark::nonlinearForces(const Eigen::VectorXd& delta, Eigen::VectorXd& f,
                                            Eigen::MatrixXd* slope) const {
  const auto& meshes = model_.meshes();
  for (int m = 0; m < meshes_; ++m) {
    const double y = delta(m) - e_(m);
    double s = 1.0, force = 0.0;
    if (tooth_pairs_[m].elementCount() > 0) {
      force = tooth_pairs_[m].force(0, y, &s);  // Σ_j k_j max(0, y − g_j)
    } else {
      force = k_(m) * meshes[m].contactDeflection(y, &s);
      s *= k_(m);
    }
    f(m) = force - meshes[m].mean_stiffness * delta(m);
    if (slope) (*slope)(m, m) = s - meshes[m].mean_stiffness;
  }
  // Clearance bearings: f̃ = f(u) − k u with its coupled w × w Jacobian (bearing_clearance.h).
  for (std::size_t b = 0; b < laws_.size(); ++b) {
    const int c = bearing_first_[b], w = laws_[b].width();
    TrainBearingLaw::Matrix J(w, w);
    f.segment(c, w) = laws_[b].correctionForce(TrainBearingLaw::Vector(delta.segment(c, w)),
                                               slope ? &J : nullptr);
    if (slope) slope->block(c, c, w, w) = J;
  }
}

double TrainNonlinearNewmark::meshForce(int mesh) const {
  const double y = delta_(mesh) - e_(mesh);
  if (tooth_pairs_[mesh].elementCount() > 0) return tooth_pairs_[mesh].force(0, y, nullptr);
  return k_(mesh) * model_.meshes()[mesh].contactDeflection(y);
}

void TrainNonlinearNewmark::eventState(std::vector<long long>& out) const {
  const auto& meshes = model_.meshes();
  for (int m = 0; m < meshes_; ++m) {
    const TrainMesh& mesh = meshes[m];
    const double y = delta_(m) - e_(m);
    long long contact = 0, segment = 0;
    if (const ToothPairTable& table = tooth_pairs_[m]; table.elementCount() > 0) {
      // Bit j % 64: the contact set {j: k_j > 0, y > g_j} and the engaged set {j: k_j > 0} (a
      // pair on the path of contact).
      for (int j = 0; j < table.elementCount(); ++j) {
        if (!(table.stiffness(0, j) > 0.0)) continue;
        const long long bit = 1LL << (j % 64);
        segment |= bit;
        if (y > table.gap(0, j)) contact |= bit;
      }
    } else {
      if (mesh.nonlinear()) {
        double s = 0.0;
        mesh.contactDeflection(y, &s);
        contact = s == 0.0 ? 0 : (y > 0.0 ? 1 : -1);  // free play, loaded or back flank
      }
      // The stiffness segment: jumps of k(φ) passed since φ = 0 (none for a continuous k).
      if (const std::vector<double>& breaks = breaks_[m]; !breaks.empty()) {
        const double phi = mesh.phaseAt(t_, speed_), whole = std::floor(phi);
        segment = static_cast<long long>(whole) * static_cast<long long>(breaks.size()) +
                  (std::upper_bound(breaks.begin(), breaks.end(), phi - whole) - breaks.begin());
      }
    }
    out[2 * m] = contact;
    out[2 * m + 1] = segment;
  }
  for (std::size_t b = 0; b < laws_.size(); ++b) {
    const TrainBearingLaw::Vector u = delta_.segment(bearing_first_[b], laws_[b].width());
    out[2 * meshes_ + b] = laws_[b].touching(u);
  }
}

int TrainNonlinearNewmark::refinementBetween(const std::vector<long long>& before,
                                             const std::vector<long long>& after) const {
  bool contact = false, jump = false;
  for (int m = 0; m < meshes_; ++m) {
    const long long c0 = before[2 * m], c1 = after[2 * m];
    const long long s0 = before[2 * m + 1], s1 = after[2 * m + 1];
    contact = contact || c0 != c1;
    // A tooth pair engaging or released while in contact makes the force jump; a plain mesh's
    // k(φ) jumps where its segment changes.
    jump = jump || (tooth_pairs_[m].elementCount() > 0 ? ((s0 ^ s1) & (c0 | c1)) != 0 : s0 != s1);
  }
  for (std::size_t i = 2 * meshes_; i < before.size(); ++i)
    contact = contact || before[i] != after[i];
  return std::max(jump ? jump_levels_ : 0, contact ? contact_levels_ : 0);
}

void TrainNonlinearNewmark::reset(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot) {
  t_ = t;
  q_ = q;
  v_ = qdot;
  delta_ = V_.transpose() * q_;
  meshState(t);
  nonlinearForces(delta_, f_, nullptr);
  a_ = model_.mass().llt().solve(model_.staticLoad() + V_ * (dashpot_ - f_) - Cg_ * v_ - K0_ * q_);
  eventState(events_);
}

bool TrainNonlinearNewmark::step(double newton_tolerance, int max_iterations) {
  return advance(0, newton_tolerance, max_iterations);
}

bool TrainNonlinearNewmark::advance(int level, double newton_tolerance, int max_iterations) {
  if (level + 1 == static_cast<int>(levels_.size())) {
    return trial(levels_[level], newton_tolerance, max_iterations);
  }
  Saved& saved = saved_[level];  // same sizes: copies without allocating
  saved.t = t_;
  saved.q = q_;
  saved.v = v_;
  saved.a = a_;
  saved.delta = delta_;
  saved.events = events_;
  const bool converged = trial(levels_[level], newton_tolerance, max_iterations);
  // Keep the step unless an event inside it (or Newton's failure) asks for finer ones.
  const int depth =
      converged ? refinementBetween(saved.events, events_) : static_cast<int>(levels_.size()) - 1;
  if (level >= depth) return converged;
  t_ = saved.t;
  q_ = saved.q;
  v_ = saved.v;
  a_ = saved.a;
  delta_ = saved.delta;
  events_ = saved.events;
  ++refined_;
  const bool first = advance(level + 1, newton_tolerance, max_iterations);
  const bool second = advance(level + 1, newton_tolerance, max_iterations);
  return first && second;
}

bool TrainNonlinearNewmark::trial(const Level& level, double newton_tolerance, int max_iterations) {
  const NewmarkCoefficients& nm = level.nm;
  const double t1 = t_ + level.dt;
  meshState(t1);
  rhs_.noalias() = model_.staticLoad();
  rhs_.noalias() += V_ * dashpot_;
  y_ = nm.a0 * q_ + nm.a2 * v_ + nm.a3 * a_;
  rhs_.noalias() += model_.mass() * y_;
  y_ = nm.a1 * q_ + nm.a4 * v_ + nm.a5 * a_;
  rhs_.noalias() += Cg_ * y_;
  y_ = level.lu.solve(rhs_);
  // Newton on δ − Vᵀy + W f̃(t1, δ) = 0 from the last step's deflections (and bearing u).
  free_.noalias() = V_.transpose() * y_;
  bool converged = false;
  for (int it = 0; it < max_iterations && !converged; ++it) {
    nonlinearForces(delta_, f_, &slope_);
    res_ = delta_ - free_;
    res_.noalias() += level.W * f_;
    J_.noalias() = level.W * slope_;
    J_.diagonal().array() += 1.0;
    small_.compute(J_);
    step_ = small_.solve(res_);
    // A piecewise-linear law can make full steps cycle between contact states: damp late ones.
    delta_ -= (it < 20 ? 1.0 : 0.5) * step_;
    const double scale = std::max(delta_.cwiseAbs().maxCoeff(), 1e-300);
    converged = step_.cwiseAbs().maxCoeff() <= newton_tolerance * scale;
  }
  nonlinearForces(delta_, f_, nullptr);
  y_.noalias() -= level.Z * f_;                        // q_{n+1}
  rhs_ = nm.a0 * (y_ - q_) - nm.a2 * v_ - nm.a3 * a_;  // a_{n+1}
  v_ += level.dt * ((1.0 - gamma_) * a_ + gamma_ * rhs_);
  a_ = rhs_;
  q_.swap(y_);
  t_ = t1;
  if (levels_.size() > 1) eventState(events_);
  return converged;
}

TrainNonlinearTimeResponse solveTrainNonlinearTime(const GearTrainModel& model, double input_speed,
                                                   const TrainNonlinearTimeOptions& options,
                                                   const Eigen::VectorXd& q0,
                                                   const Eigen::VectorXd& v0) {
  options.validate();
  if (model.meshes().empty()) throw InputError("meshes", "", "a train with at least one mesh");
  if (!(std::abs(input_speed) > 0.0)) {
    throw InputError("operating_point.speed_rpm", "0", "a speed != 0 for a time response");
  }
  const TrainBaseFrequency base = trainBaseFrequency(model, 1, 1000000000);
  int largest = 1;
  for (int p : base.mesh_multiple) largest = std::max(largest, p);
  const long long per_period = static_cast<long long>(largest) * options.steps_per_mesh_period;
  TrainNonlinearTimeResponse r;
  r.period = 1.0 / (base.ratio * std::abs(input_speed));
  const double dt = r.period / static_cast<double>(per_period);
  TrainNonlinearNewmark stepper(model, input_speed, dt, options.newmark, options.event_refinement,
                                options.contact_refinement);
  const int n = model.dofCount();
  const int meshes = static_cast<int>(model.meshes().size());
  int coordinates = meshes;
  for (const TrainClearanceBearing& b : model.clearanceBearings())
    coordinates += static_cast<int>(b.jacobian.rows());
  const Eigen::VectorXd q = q0.size() == n ? q0 : solveTrainStatic(model, input_speed).displacement;
  stepper.reset(0.0, q, v0.size() == n ? v0 : Eigen::VectorXd::Zero(n));
  Eigen::MatrixXd previous(per_period, coordinates), current(per_period, coordinates);
  r.t.resize(per_period);
  r.displacement.resize(per_period, n);
  for (int period = 1; period <= options.max_periods; ++period) {
    for (long long k = 0; k < per_period; ++k) {
      if (!stepper.step(options.newton_tolerance, options.max_newton_iterations)) {
        r.status = "newton_failure";
        r.message =
            fmt::format("Newton on the mesh deflections failed at t = {:.6g} s", stepper.time());
      }
      current.row(k) = stepper.coordinates().transpose();
      r.t(k) = stepper.time();
      r.displacement.row(k) = stepper.displacement().transpose();
    }
    r.periods = period;
    r.steps += per_period;
    r.refined_steps = stepper.refinedSteps();
    if (!current.allFinite()) {
      r.status = "diverged";
      r.message = fmt::format("diverged at t = {:.6g} s", stepper.time());
      return r;
    }
    if (r.status == "newton_failure") return r;
    // Relative to the meshes' largest |δ|, and to each clearance bearing's own largest |u| or
    // its clearance when larger (a journal floating at the centre has |u| ~ round-off).
    r.last_change = period > 1 ? 0.0 : HUGE_VAL;
    // Per group against its own scale: the meshes' δ; a bearing's translations (floor: its
    // clearance); a full-DOF bearing's tilts (floor: the translation scale over d_m/2, the tilt
    // that moves an element as far).
    const auto change = [&](int first, int count, double floor) {
      const double scale = std::max(current.middleCols(first, count).cwiseAbs().maxCoeff(), floor);
      r.last_change =
          std::max(r.last_change,
                   (current - previous).middleCols(first, count).cwiseAbs().maxCoeff() / scale);
      return scale;
    };
    if (period > 1) {
      change(0, meshes, 1e-300);
      for (int b = 0, c = meshes; b < static_cast<int>(model.clearanceBearings().size()); ++b) {
        const TrainClearanceBearing& bearing = model.clearanceBearings()[b];
        const int w = static_cast<int>(bearing.jacobian.rows());
        const double translation = change(c, std::min(w, 3), bearing.clearance);
        if (w > 3) {
          change(c + 3, w - 3, translation / (0.5 * bearing.rolling->geometry().pitch_diameter));
        }
        c += w;
      }
    }
    std::swap(previous, current);
    if (period >= options.min_periods && r.last_change <= options.steady_tolerance) break;
  }
  r.mesh_deflection = previous.leftCols(meshes);  // the last period (swapped)
  r.bearing_displacement.resize(per_period,
                                2 * static_cast<Eigen::Index>(model.clearanceBearings().size()));
  for (int b = 0, c = meshes; b < static_cast<int>(model.clearanceBearings().size()); ++b) {
    r.bearing_displacement.middleCols(2 * b, 2) = previous.middleCols(c, 2);  // (u_y, u_z)
    c += static_cast<int>(model.clearanceBearings()[b].jacobian.rows());
  }
  r.mesh_force.resize(per_period, meshes);
  for (long long k = 0; k < per_period; ++k) {
    for (int m = 0; m < meshes; ++m) {
      const TrainMesh& mesh = model.meshes()[m];
      const double phi = mesh.phaseAt(r.t(k), input_speed);
      r.mesh_force(k, m) =
          mesh.nonlinearForce(phi, r.mesh_deflection(k, m) - mesh.transmission_error.value(phi));
    }
  }
  if (r.last_change > options.steady_tolerance) {
    r.status = "max_periods";
    r.message = fmt::format("not periodic after {} common periods (last change {:.2g})", r.periods,
                            r.last_change);
  }
  return r;
}

}  // namespace geardyn

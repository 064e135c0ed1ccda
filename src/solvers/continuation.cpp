/// Pseudo-arclength continuation in frequency with confirmed folds (continuation.h).

#include "geardyn/solvers/continuation.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "geardyn/error.h"

namespace geardyn {

std::string toString(BifurcationType type) {
  switch (type) {
    case BifurcationType::kFold:
      return "fold";
    case BifurcationType::kBranchPoint:
      return "branch_point";
    case BifurcationType::kPeriodDoubling:
      return "period_doubling";
    case BifurcationType::kNeimarkSacker:
      return "neimark_sacker";
  }
  return "unknown";
}

void ContinuationOptions::validate() const {
  // Values are echoed in the unit of the user's keys (display_unit).
  const auto shown = [&](double omega) {
    return fmt::format("{:g} {}", omega / display_scale, display_unit);
  };
  if (!(start > 0.0) || !std::isfinite(start))
    throw InputError("sweep.start", shown(start), "must be finite and > 0");
  if (!(stop > 0.0) || !std::isfinite(stop))
    throw InputError("sweep.stop", shown(stop), "must be finite and > 0");
  if (start == stop) throw InputError("sweep.stop", shown(stop), "must differ from sweep.start");
  if (!(min_step > 0.0)) throw InputError("sweep.min_step", shown(min_step), "must be > 0");
  if (!(max_step >= min_step))
    throw InputError("sweep.max_step", shown(max_step),
                     "must be >= sweep.min_step = " + shown(min_step));
  if (!(initial_step >= min_step && initial_step <= max_step)) {
    throw InputError("sweep.initial_step", shown(initial_step),
                     fmt::format("must lie in [sweep.min_step, sweep.max_step] = [{}, {}]",
                                 shown(min_step), shown(max_step)));
  }
  if (!(fold_tolerance >= 0.0) || !std::isfinite(fold_tolerance))
    throw InputError("sweep.fold_tolerance", shown(fold_tolerance), "must be finite and >= 0");
}

void solveAtFixedFrequency(ContinuationProblem& problem, HarmonicBalancePoint& point,
                           double tolerance, int max_iterations) {
  Eigen::VectorXd r, trial = point.q;
  Eigen::MatrixXd J;
  problem.residual(point.q, point.omega, r, &J, nullptr);
  double norm = problem.residualNorm(point.q, r, point.omega);
  for (point.iterations = 0; point.iterations < max_iterations; ++point.iterations) {
    if (norm <= tolerance) break;
    const Eigen::VectorXd step = problem.factorJacobian(J).solve(-r);
    if (!step.allFinite()) break;
    double alpha = 1.0;
    for (int back = 0; back < 6; ++back) {
      trial = point.q + alpha * step;
      problem.residual(trial, point.omega, r, &J, nullptr);
      const double trial_norm = problem.residualNorm(trial, r, point.omega);
      if (trial_norm < norm || back == 5) {
        norm = trial_norm;
        break;
      }
      alpha *= 0.5;
    }
    point.q = trial;
  }
  point.residual = norm;
  point.converged = norm <= tolerance;
}

void deriveContinuationSteps(ContinuationOptions& o, double natural_frequency, double damping_ratio,
                             int harmonics) {
  const double range = std::abs(o.stop - o.start);
  const double low = std::min(o.start, o.stop), high = std::max(o.start, o.stop);
  const double zeta = std::clamp(damping_ratio, 1e-3, 0.5);
  // The highest-order superharmonic resonance j ω = ω_n inside the range (its half-power
  // width 2 ζ ω_n / j is the narrowest feature to resolve); the primary when none is.
  int order = 1;
  if (natural_frequency > 0.0) {
    for (int j = 1; j <= std::max(harmonics, 1); ++j) {
      const double at = natural_frequency / j;
      if (at >= low && at <= high) order = j;
    }
  }
  double largest = range / 50.0;
  if (natural_frequency > 0.0) largest = std::min(largest, zeta * natural_frequency / order);
  const bool derive_max = o.max_step == 0.0, derive_min = o.min_step == 0.0,
             derive_initial = o.initial_step == 0.0;
  if (derive_max) o.max_step = o.min_step > 0.0 ? std::max(largest, o.min_step) : largest;
  if (derive_min) o.min_step = std::min(1e-6 * largest, o.max_step);
  if (derive_initial) o.initial_step = std::clamp(0.2 * largest, o.min_step, o.max_step);
}

namespace {

/// The fold bookkeeping: a sign change of dω/ds is a candidate; it becomes a fold when the
/// branch has gone back in ω by more than the tolerance, and is dropped if the tangent turns
/// again first (a zigzag of the piecewise-smooth discretised curve).
class FoldTracker {
 public:
  FoldTracker(double direction, double tolerance) : sign_(direction), tolerance_(tolerance) {}
  /// After point `index` at ω with tangent ω-component `t_omega`; returns true when a fold is
  /// confirmed (its index in *fold).
  bool update(std::size_t index, double omega, double t_omega, std::size_t* fold) {
    if (t_omega * sign_ < 0.0) {
      sign_ = -sign_;
      if (pending_) {
        pending_ = false;  // turned back before going anywhere: not a fold
      } else {
        pending_ = true;
        // The turning point lies between the last point and this one: the more extreme.
        turn_index_ = (omega - last_omega_) * sign_ > 0.0 ? index - 1 : index;
        turn_omega_ = (omega - last_omega_) * sign_ > 0.0 ? last_omega_ : omega;
      }
    } else if (pending_ && (omega - turn_omega_) * sign_ < 0.0) {
      turn_index_ = index, turn_omega_ = omega;  // still going the old way: a later extreme
    }
    last_omega_ = omega;
    if (pending_ && (omega - turn_omega_) * sign_ >= tolerance_) {
      pending_ = false;
      *fold = turn_index_;
      return true;
    }
    return false;
  }
  void start(double omega) { last_omega_ = omega; }

 private:
  double sign_, tolerance_;
  bool pending_ = false;
  std::size_t turn_index_ = 0;
  double turn_omega_ = 0.0, last_omega_ = 0.0;
};

/// Stability changes that are not folds, typed by the critical multiplier of the unstable side.
/// A change within a few points or 2 `tolerance` of ω of a fold is the fold's (the sampled
/// contact makes the exponent cross zero a little off the turning point).
void classifyStabilityChanges(ContinuationResult& out, double tolerance) {
  std::vector<Bifurcation> all;
  for (std::size_t f : out.folds) {
    all.push_back({BifurcationType::kFold, f, out.points[f].solution.omega});
  }
  for (std::size_t i = 1; i < out.points.size(); ++i) {
    const auto& a = out.points[i - 1].solution;
    const auto& b = out.points[i].solution;
    if (a.stable == b.stable) continue;
    const bool near_fold = std::any_of(out.folds.begin(), out.folds.end(), [&](std::size_t f) {
      return (f + 3 >= i && f <= i + 2) ||
             std::abs(out.points[f].solution.omega - b.omega) <= 2.0 * tolerance;
    });
    if (near_fold) continue;
    const std::complex<double> mu = a.stable ? b.critical_multiplier : a.critical_multiplier;
    BifurcationType type = BifurcationType::kNeimarkSacker;
    if (std::abs(mu.imag()) <= 1e-6 * std::abs(mu)) {  // Hill: exp(λT) rounds off the real axis
      type = mu.real() < 0.0 ? BifurcationType::kPeriodDoubling : BifurcationType::kBranchPoint;
    }
    all.push_back({type, i, b.omega});
  }
  std::sort(all.begin(), all.end(), [](const auto& x, const auto& y) { return x.index < y.index; });
  out.bifurcations = std::move(all);
}

}  // namespace

namespace {

/// Pseudo-arclength continuation of problem's solutions in ω (continueInFrequency), its state
/// and steps. The unknowns are scaled: q by its size at the start, ω by the larger end of the
/// range.
class ArclengthContinuation {
 public:
  ArclengthContinuation(ContinuationProblem& problem, const ContinuationOptions& options)
      : problem_(problem),
        options_(options),
        n_(problem.size()),
        direction_(options.stop > options.start ? 1.0 : -1.0),
        omega_ref_(std::max(options.start, options.stop)),
        range_(std::abs(options.stop - options.start)),
        fold_tolerance_(options.fold_tolerance > 0.0 ? options.fold_tolerance : 1e-3 * range_),
        folds_(direction_, fold_tolerance_),
        A_(n_ + 1, n_ + 1),
        lu_(n_ + 1),
        unit_(Eigen::VectorXd::Zero(n_ + 1)),
        // The corrector at the predicted ω (problem.frequencyChangeIsCostly(): see
        // correctAtPredictedFrequency).
        hold_frequency_(problem.frequencyChangeIsCostly()),
        q_(n_),
        rhs_(n_ + 1),
        dy_(n_ + 1),
        predicted_(n_ + 1),
        y_(n_ + 1),
        z_(n_ + 1) {
    unit_[n_] = 1.0;
  }

  ContinuationResult run();

 private:
  /// [∂R/∂q q_scale, ∂R/∂ω ω_ref; rowᵀ] factorised into lu_.
  void factorise(const Eigen::VectorXd& row) {
    A_.topLeftCorner(n_, n_) = Jq_ * q_scale_;
    A_.topRightCorner(n_, 1) = Jw_ * omega_ref_;
    A_.bottomRows(1) = row.transpose();
    lu_.compute(A_);
  }
  /// The tangent of the factorised matrix (its last row the previous tangent: same orientation).
  Eigen::VectorXd tangentOfFactors() {
    Eigen::VectorXd t = lu_.solve(unit_);
    return Eigen::VectorXd(t / t.norm());
  }
  Eigen::VectorXd tangentFrom(const Eigen::VectorXd& previous) {
    factorise(previous);
    return tangentOfFactors();
  }
  void classify(HarmonicBalancePoint& p, bool samples_current) {
    if (options_.stability) problem_.classify(p, options_.stability_method, samples_current);
  }
  bool start();
  bool correctAtPredictedFrequency(int& iterations, double& norm);
  Eigen::VectorXd tangentAtHeldFrequency();
  bool correctPseudoArclength(int& iterations, double& norm);
  /// Takes the corrected point y_; true when the sweep has reached options.stop.
  bool accept(bool held, int iterations, double norm);
  ContinuationResult finish(std::string message) {
    out_.message = std::move(message);
    classifyStabilityChanges(out_, fold_tolerance_);
    return std::move(out_);
  }

  ContinuationProblem& problem_;
  const ContinuationOptions& options_;
  const int n_;
  const double direction_, omega_ref_, range_, fold_tolerance_;
  FoldTracker folds_;
  ContinuationResult out_;
  double q_scale_ = 1.0;
  Eigen::MatrixXd A_;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
  Eigen::VectorXd unit_;
  const bool hold_frequency_;
  const Eigen::PartialPivLU<Eigen::MatrixXd>* lu_q_ = nullptr;  // the problem's (factorJacobian)
  Eigen::VectorXd r_, Jw_;
  Eigen::MatrixXd Jq_;
  Eigen::VectorXd q_, rhs_, dy_, predicted_, y_, z_, t_;
  double step_ = 0.0, min_step_ = 0.0, max_step_ = 0.0;
  int branch_ = 0;
  int cuts_ = 0;  // since the last accepted point
  double arclength_ = 0.0;
};

/// The first point at options.start and the first tangent; false (out_.message set) when the
/// start does not converge.
bool ArclengthContinuation::start() {
  HarmonicBalancePoint first;
  first.omega = options_.start;
  first.q = options_.initial_guess.size() == n_ ? options_.initial_guess
                                                : problem_.startingGuess(first.omega);
  problem_.solve(first);
  if (!first.converged) {
    out_.message =
        fmt::format("no solution at the start frequency (residual {:.2g})", first.residual);
    return false;
  }
  q_scale_ = std::max(first.q.norm(), 1e-300);
  classify(first, false);
  out_.points.push_back({first, 0, 0.0});
  Eigen::VectorXd seed = Eigen::VectorXd::Zero(n_ + 1);
  seed[n_] = direction_;
  problem_.residual(first.q, first.omega, r_, &Jq_, &Jw_);
  t_ = tangentFrom(seed);
  if (t_[n_] * direction_ < 0) t_ = -t_;
  step_ = options_.initial_step / omega_ref_;
  min_step_ = options_.min_step / omega_ref_, max_step_ = options_.max_step / omega_ref_;
  z_ << first.q / q_scale_, first.omega / omega_ref_;
  folds_.start(first.omega);
  return true;
}

// The corrector at the predicted ω (problem.frequencyChangeIsCostly(): a locally
// parametrised corrector, Rheinboldt & Burkardt 1983, with ω as the parameter): Newton on q
// alone at ω held, so one residual at a new ω a point. The Jacobian of the first iteration is
// held while the residual falls at least by half a step (chord Newton), else refreshed. The
// point is taken only if it lies within a tenth of the step of the prediction: at fixed ω a
// corrector can land on another branch (near a fold, where ∂R/∂q turns singular), which the
// arclength constraint prevents; then (or if it fails) the pseudo-arclength corrector runs.
// On the planetary sweep of bench/train_nonlinear_bench.cpp 97 % of the points are held.
bool ArclengthContinuation::correctAtPredictedFrequency(int& iterations, double& norm) {
  const double omega = predicted_[n_] * omega_ref_;
  if (!(omega > 0.0)) return false;
  q_ = predicted_.head(n_) * q_scale_;
  problem_.residual(q_, omega, r_, &Jq_, &Jw_);
  norm = problem_.residualNorm(q_, r_, omega);
  lu_q_ = &problem_.factorJacobian(Jq_);
  for (iterations = 0; iterations < 10 && norm > 1e-10; ++iterations) {
    q_ -= lu_q_->solve(r_);
    const double previous = norm;
    problem_.residual(q_, omega, r_, nullptr, nullptr);
    norm = problem_.residualNorm(q_, r_, omega);
    if (!std::isfinite(norm)) return false;
    if (norm > 1e-10 && norm > 0.5 * previous) {
      problem_.residual(q_, omega, r_, &Jq_, &Jw_);
      lu_q_ = &problem_.factorJacobian(Jq_);
    }
  }
  if (norm > 1e-10) return false;
  y_ << q_ / q_scale_, predicted_[n_];
  return (y_ - predicted_).norm() <= 0.1 * step_;
}

// Its tangent: [∂R/∂q q_scale, ∂R/∂ω ω_ref] t = 0 with t_ω = 1, from the held factors.
Eigen::VectorXd ArclengthContinuation::tangentAtHeldFrequency() {
  Eigen::VectorXd tangent(n_ + 1);
  tangent << lu_q_->solve(Jw_) * (-omega_ref_ / q_scale_), 1.0;
  tangent.normalize();
  return Eigen::VectorXd(tangent.dot(t_) < 0.0 ? -tangent : tangent);
}

/// Newton on [R(y); tᵀ(y − predicted)] = 0 from the prediction.
bool ArclengthContinuation::correctPseudoArclength(int& iterations, double& norm) {
  for (iterations = 0; iterations < 25; ++iterations) {
    q_ = y_.head(n_) * q_scale_;
    const double omega = y_[n_] * omega_ref_;
    if (!(omega > 0.0)) break;
    problem_.residual(q_, omega, r_, &Jq_, &Jw_);
    norm = problem_.residualNorm(q_, r_, omega);
    const double constraint = t_.dot(y_ - predicted_);
    if (norm <= 1e-10 && std::abs(constraint) <= 1e-12) return true;
    factorise(t_);
    rhs_ << -r_, -constraint;
    dy_ = lu_.solve(rhs_);
    if (!dy_.allFinite()) break;
    y_ += dy_;
  }
  return false;
}

bool ArclengthContinuation::accept(bool held, int iterations, double norm) {
  HarmonicBalancePoint point;
  point.q = y_.head(n_) * q_scale_;
  point.omega = y_[n_] * omega_ref_;
  point.converged = true;
  point.iterations = iterations;
  point.residual = norm;
  // The tangent from the corrector's last factorisation [J(y_k); tᵀ], y_k one converging
  // Newton step from the point (saves an LU a point): an error of the order of that step in
  // a predictor direction, and folds are confirmed by the points themselves. (The AFT samples are
  // the converged point's: the sampled-monodromy stability reuses them.)
  const Eigen::VectorXd t_new = held             ? tangentAtHeldFrequency()
                                : iterations > 0 ? tangentOfFactors()
                                                 : tangentFrom(t_);
  arclength_ += step_;
  classify(point, true);
  out_.points.push_back({point, branch_, arclength_, cuts_});
  cuts_ = 0;
  std::size_t fold = 0;
  if (folds_.update(out_.points.size() - 1, point.omega, t_new[n_], &fold)) {
    ++branch_;
    out_.folds.push_back(fold);
    for (std::size_t i = fold + 1; i < out_.points.size(); ++i) out_.points[i].branch = branch_;
  }
  if (options_.progress) {
    options_.progress(std::clamp(std::abs(point.omega - options_.start), 0.0, range_), range_);
  }
  t_ = t_new;
  z_ = y_;
  if (iterations <= 4) step_ = std::min(step_ * 1.5, max_step_);
  if (iterations >= 10) step_ = std::max(step_ * 0.5, min_step_);
  return (point.omega - options_.stop) * direction_ >= 0.0;
}

ContinuationResult ArclengthContinuation::run() {
  if (!start()) return std::move(out_);
  while (static_cast<int>(out_.points.size()) < options_.max_points) {
    predicted_ = z_ + step_ * t_;
    y_ = predicted_;
    int iterations = 0;
    double norm = 0.0;
    const bool held = hold_frequency_ && correctAtPredictedFrequency(iterations, norm);
    bool converged = held;
    if (!held) {
      y_ = predicted_;
      converged = correctPseudoArclength(iterations, norm);
    }
    if (!converged) {
      ++out_.failures;
      ++cuts_;
      step_ *= 0.5;
      if (step_ < min_step_) {
        return finish(
            fmt::format("continuation stopped at {:.6g} {}: the corrector failed with the "
                        "minimum step (residual {:.2g})",
                        z_[n_] * omega_ref_ / options_.display_scale, options_.display_unit, norm));
      }
      continue;
    }
    if (accept(held, iterations, norm)) {
      out_.completed = true;
      return finish(fmt::format("{} points, {} folds, {} step cuts", out_.points.size(),
                                out_.folds.size(), out_.failures));
    }
  }
  // Where it stopped, so that a sweep stuck on a tall branch (a lightly damped resonance with
  // contact loss) says so.
  const double reached = z_[n_] * omega_ref_;
  return finish(fmt::format(
      "stopped after the maximum of {} points at {:.6g} {}, {:.0f} % of the way from {:.6g} to "
      "{:.6g} {}",
      options_.max_points, reached / options_.display_scale, options_.display_unit,
      100.0 * std::clamp(std::abs(reached - options_.start), 0.0, range_) / range_,
      options_.start / options_.display_scale, options_.stop / options_.display_scale,
      options_.display_unit));
}

}  // namespace

ContinuationResult continueInFrequency(ContinuationProblem& problem,
                                       const ContinuationOptions& options) {
  options.validate();
  return ArclengthContinuation(problem, options).run();
}

std::vector<HarmonicBalancePoint> solutionsAtFrequency(
    ContinuationProblem& problem, const std::vector<const ContinuationResult*>& sweeps,
    double omega) {
  std::vector<HarmonicBalancePoint> found;
  for (const ContinuationResult* sweep : sweeps) {
    for (std::size_t i = 1; i < sweep->points.size(); ++i) {
      const auto& a = sweep->points[i - 1].solution;
      const auto& b = sweep->points[i].solution;
      if ((a.omega - omega) * (b.omega - omega) > 0.0 || a.omega == b.omega) continue;
      HarmonicBalancePoint p;
      p.omega = omega;
      p.q = a.q + (omega - a.omega) / (b.omega - a.omega) * (b.q - a.q);
      problem.solve(p);
      if (!p.converged) continue;
      const bool seen = std::any_of(found.begin(), found.end(), [&](const auto& f) {
        return (f.q - p.q).norm() <= 1e-6 * p.q.norm();
      });
      if (!seen) found.push_back(p);
    }
  }
  return found;
}

}  // namespace geardyn

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
    const Eigen::VectorXd step = J.partialPivLu().solve(-r);
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

ContinuationResult continueInFrequency(ContinuationProblem& problem,
                                       const ContinuationOptions& options) {
  options.validate();
  ContinuationResult out;
  const int n = problem.size();
  const double direction = options.stop > options.start ? 1.0 : -1.0;
  const double omega_ref = std::max(options.start, options.stop);
  const double range = std::abs(options.stop - options.start);

  HarmonicBalancePoint first;
  first.omega = options.start;
  first.q = problem.startingGuess(first.omega);
  problem.solve(first);
  if (!first.converged) {
    out.message =
        fmt::format("no solution at the start frequency (residual {:.2g})", first.residual);
    return out;
  }
  // Scaling: q by its size at the start, ω by the larger end of the range.
  const double q_scale = std::max(first.q.norm(), 1e-300);
  Eigen::MatrixXd A(n + 1, n + 1);
  Eigen::PartialPivLU<Eigen::MatrixXd> lu(n + 1);
  Eigen::VectorXd unit = Eigen::VectorXd::Zero(n + 1);
  unit[n] = 1.0;
  // [∂R/∂q q_scale, ∂R/∂ω ω_ref; rowᵀ] factorised into `lu`.
  const auto factorise = [&](const Eigen::MatrixXd& Jq, const Eigen::VectorXd& Jw,
                             const Eigen::VectorXd& row) {
    A.topLeftCorner(n, n) = Jq * q_scale;
    A.topRightCorner(n, 1) = Jw * omega_ref;
    A.bottomRows(1) = row.transpose();
    lu.compute(A);
  };
  // The tangent of the factorised matrix (its last row the previous tangent: same orientation).
  const auto tangentOfFactors = [&]() {
    Eigen::VectorXd t = lu.solve(unit);
    return Eigen::VectorXd(t / t.norm());
  };
  const auto tangentFrom = [&](const Eigen::MatrixXd& Jq, const Eigen::VectorXd& Jw,
                               const Eigen::VectorXd& previous) {
    factorise(Jq, Jw, previous);
    return tangentOfFactors();
  };
  const auto classify = [&](HarmonicBalancePoint& p, bool samples_current) {
    if (options.stability) problem.classify(p, options.stability_method, samples_current);
  };
  classify(first, false);
  out.points.push_back({first, 0, 0.0});
  Eigen::VectorXd seed = Eigen::VectorXd::Zero(n + 1);
  seed[n] = direction;
  Eigen::VectorXd r, Jw;
  Eigen::MatrixXd Jq;
  problem.residual(first.q, first.omega, r, &Jq, &Jw);
  Eigen::VectorXd t = tangentFrom(Jq, Jw, seed);
  if (t[n] * direction < 0) t = -t;

  double step = options.initial_step / omega_ref;
  const double min_step = options.min_step / omega_ref, max_step = options.max_step / omega_ref;
  Eigen::VectorXd z(n + 1);
  z << first.q / q_scale, first.omega / omega_ref;
  int branch = 0;
  double arclength = 0.0;
  const double fold_tolerance =
      options.fold_tolerance > 0.0 ? options.fold_tolerance : 1e-3 * range;
  FoldTracker folds(direction, fold_tolerance);
  folds.start(first.omega);

  Eigen::VectorXd q(n), rhs(n + 1), dy(n + 1), predicted(n + 1), y(n + 1);
  // The corrector at the predicted ω (problem.frequencyChangeIsCostly(): a locally
  // parametrised corrector, Rheinboldt & Burkardt 1983, with ω as the parameter): Newton on q
  // alone at ω held, so one residual at a new ω a point. The Jacobian of the first iteration is
  // held while the residual falls at least by half a step (chord Newton), else refreshed. The
  // point is taken only if it lies within a tenth of the step of the prediction: at fixed ω a
  // corrector can land on another branch (near a fold, where ∂R/∂q turns singular), which the
  // arclength constraint prevents; then (or if it fails) the pseudo-arclength corrector runs.
  // On the planetary sweep of bench/train_nonlinear_bench.cpp 97 % of the points are held.
  const bool hold_frequency = problem.frequencyChangeIsCostly();
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_q(hold_frequency ? n : 0);
  const auto correctAtPredictedFrequency = [&](int& iterations, double& norm) {
    const double omega = predicted[n] * omega_ref;
    if (!(omega > 0.0)) return false;
    q = predicted.head(n) * q_scale;
    problem.residual(q, omega, r, &Jq, &Jw);
    norm = problem.residualNorm(q, r, omega);
    lu_q.compute(Jq);
    for (iterations = 0; iterations < 10 && norm > 1e-10; ++iterations) {
      q -= lu_q.solve(r);
      const double previous = norm;
      problem.residual(q, omega, r, nullptr, nullptr);
      norm = problem.residualNorm(q, r, omega);
      if (!std::isfinite(norm)) return false;
      if (norm > 1e-10 && norm > 0.5 * previous) {
        problem.residual(q, omega, r, &Jq, &Jw);
        lu_q.compute(Jq);
      }
    }
    if (norm > 1e-10) return false;
    y << q / q_scale, predicted[n];
    return (y - predicted).norm() <= 0.1 * step;
  };
  // Its tangent: [∂R/∂q q_scale, ∂R/∂ω ω_ref] t = 0 with t_ω = 1, from the held factors.
  const auto tangentAtHeldFrequency = [&]() {
    Eigen::VectorXd tangent(n + 1);
    tangent << lu_q.solve(Jw) * (-omega_ref / q_scale), 1.0;
    tangent.normalize();
    return Eigen::VectorXd(tangent.dot(t) < 0.0 ? -tangent : tangent);
  };
  int cuts = 0;  // since the last accepted point
  while (static_cast<int>(out.points.size()) < options.max_points) {
    predicted = z + step * t;
    y = predicted;
    bool converged = false;
    int iterations = 0;
    double norm = 0.0;
    const bool held = hold_frequency && correctAtPredictedFrequency(iterations, norm);
    if (held) converged = true;
    if (!held) y = predicted, iterations = 0;
    for (; !held && iterations < 25; ++iterations) {
      q = y.head(n) * q_scale;
      const double omega = y[n] * omega_ref;
      if (!(omega > 0.0)) break;
      problem.residual(q, omega, r, &Jq, &Jw);
      norm = problem.residualNorm(q, r, omega);
      const double constraint = t.dot(y - predicted);
      if (norm <= 1e-10 && std::abs(constraint) <= 1e-12) {
        converged = true;
        break;
      }
      factorise(Jq, Jw, t);
      rhs << -r, -constraint;
      dy = lu.solve(rhs);
      if (!dy.allFinite()) break;
      y += dy;
    }
    if (!converged) {
      ++out.failures;
      ++cuts;
      step *= 0.5;
      if (step < min_step) {
        out.message = fmt::format(
            "continuation stopped at {:.6g} {}: the corrector failed with the "
            "minimum step (residual {:.2g})",
            z[n] * omega_ref / options.display_scale, options.display_unit, norm);
        classifyStabilityChanges(out, fold_tolerance);
        return out;
      }
      continue;
    }
    HarmonicBalancePoint point;
    point.q = y.head(n) * q_scale;
    point.omega = y[n] * omega_ref;
    point.converged = true;
    point.iterations = iterations;
    point.residual = norm;
    // The tangent from the corrector's last factorisation [J(y_k); tᵀ], y_k one converging
    // Newton step from the point (saves an LU a point): an error of the order of that step in
    // a predictor direction, and folds are confirmed by the points themselves. (The AFT samples are
    // the converged point's: the sampled-monodromy stability reuses them.)
    const Eigen::VectorXd t_new = held             ? tangentAtHeldFrequency()
                                  : iterations > 0 ? tangentOfFactors()
                                                   : tangentFrom(Jq, Jw, t);
    arclength += step;
    classify(point, true);
    out.points.push_back({point, branch, arclength, cuts});
    cuts = 0;
    std::size_t fold = 0;
    if (folds.update(out.points.size() - 1, point.omega, t_new[n], &fold)) {
      ++branch;
      out.folds.push_back(fold);
      for (std::size_t i = fold + 1; i < out.points.size(); ++i) out.points[i].branch = branch;
    }
    if (options.progress) {
      options.progress(std::clamp(std::abs(point.omega - options.start), 0.0, range), range);
    }
    t = t_new;
    z = y;
    if (iterations <= 4) step = std::min(step * 1.5, max_step);
    if (iterations >= 10) step = std::max(step * 0.5, min_step);
    if ((point.omega - options.stop) * direction >= 0.0) {
      out.completed = true;
      out.message = fmt::format("{} points, {} folds, {} step cuts", out.points.size(),
                                out.folds.size(), out.failures);
      classifyStabilityChanges(out, fold_tolerance);
      return out;
    }
  }
  out.message = fmt::format("stopped after the maximum of {} points", options.max_points);
  classifyStabilityChanges(out, fold_tolerance);
  return out;
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

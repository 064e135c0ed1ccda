#pragma once
/// \file
/// The Newmark family (Newmark 1959) for a single-degree-of-freedom oscillator with a
/// time-varying, piecewise-linear restoring force:
///
///   m x″ + c x′ + k(t) g(x − e(t)) = f(t),
///
/// one class parameterised by (β, γ) with named presets (MFEM-style: the integrator never
/// touches the physics beyond this small interface). Each step solves the implicit equilibrium
/// at t_{n+1} by Newton's method safeguarded by bisection (the residual is monotone in x because
/// k > 0 and g′ >= 0), so piecewise-linear contact laws (contact loss, backlash) converge in a
/// few iterations — exactly, once the branch of g is found.

#include <algorithm>
#include <cmath>
#include <string>

namespace geardyn {

/// β, γ of the Newmark family.
struct NewmarkParameters {
  double beta = 0.25;
  double gamma = 0.5;
  /// Average (constant) acceleration, trapezoidal rule: unconditionally stable, 2nd order.
  static NewmarkParameters averageAcceleration() { return {0.25, 0.5}; }
  /// Linear acceleration: 2nd order, conditionally stable (h < 0.55 T_natural).
  static NewmarkParameters linearAcceleration() { return {1.0 / 6.0, 0.5}; }
  /// Throws InputError unless 0 < β <= 1/2 and 1/2 <= γ <= 1.
  void validate() const;
};

/// The coefficients of Newmark's scheme in effective-stiffness form for a step h [s] (Bathe,
/// Finite Element Procedures, 2014, Table 9.3): A = K + a₀M + a₁C;
/// a_{n+1} = a₀(x_{n+1} − x_n) − a₂v_n − a₃a_n, v_{n+1} = v_n + h((1 − γ)a_n + γa_{n+1}), and
/// the right-hand side M(a₀x + a₂v + a₃a) + C(a₁x + a₄v + a₅a).
struct NewmarkCoefficients {
  double a0 = 0, a1 = 0, a2 = 0, a3 = 0, a4 = 0, a5 = 0;
  NewmarkCoefficients() = default;
  NewmarkCoefficients(const NewmarkParameters& p, double h)
      : a0(1.0 / (p.beta * h * h)),
        a1(p.gamma / (p.beta * h)),
        a2(1.0 / (p.beta * h)),
        a3(0.5 / p.beta - 1.0),
        a4(p.gamma / p.beta - 1.0),
        a5(0.5 * h * (p.gamma / p.beta - 2.0)) {}
};

/// What a step of the Newmark scheme needs from a model (GearPairModel satisfies it):
///   double mass() const; double damping() const;
///   double stiffness(double t) const; double error(double t) const;
///   double externalForce(double t) const;
///   double contactLaw(double y, double* slope) const;
///   bool hasContactElements() const; double meshForce(double t, double x, double* slope) const
///   (with contact elements the spring is meshForce, evaluated per Newton iteration).
struct NewmarkState {
  double x = 0.0, v = 0.0, a = 0.0;  ///< displacement, velocity, acceleration
};

struct NewmarkStepReport {
  int iterations = 0;
  bool converged = true;
};

template <typename Model>
class NewmarkStepper {
 public:
  /// \param tolerance Newton stops when |Δx| <= tolerance (absolute, in the units of x).
  NewmarkStepper(const Model& model, NewmarkParameters parameters, double tolerance,
                 int max_iterations = 60)
      : model_(model), p_(parameters), tolerance_(tolerance), max_iterations_(max_iterations) {
    p_.validate();
  }

  /// The acceleration consistent with (x, v) at t (to start the scheme).
  double initialAcceleration(double t, double x, double v) const {
    const double spring =
        model_.hasContactElements()
            ? model_.meshForce(t, x, nullptr)
            : model_.stiffness(t) * model_.contactLaw(x - model_.error(t), nullptr);
    return (model_.externalForce(t) - model_.damping() * v - spring) / model_.mass();
  }

  /// Advances the state from t to t + h.
  NewmarkStepReport step(double t, double h, NewmarkState& s) const {
    const double t1 = t + h;
    const double m = model_.mass(), c = model_.damping();
    const double k = model_.stiffness(t1), e = model_.error(t1), f = model_.externalForce(t1);
    const bool elements = model_.hasContactElements();
    const double bh2 = p_.beta * h * h;
    // x_{n+1} = x* + β h² a_{n+1},  v_{n+1} = v* + γ h a_{n+1}
    const double x_star = s.x + h * s.v + h * h * (0.5 - p_.beta) * s.a;
    const double v_star = s.v + h * (1.0 - p_.gamma) * s.a;
    const double inertia = m / bh2 + c * p_.gamma * h / bh2;  // d(m a + c v)/dx
    // Residual of the equilibrium at t_{n+1}; *scale gets the size of its terms, so that a
    // residual at round-off level (an exact Newton step on a linear piece of g) ends the loop.
    const auto residual = [&](double x, double* slope, double* scale) {
      const double a = (x - x_star) / bh2;
      const double v = v_star + p_.gamma * h * a;
      const double spring =
          elements ? model_.meshForce(t1, x, slope) : k * model_.contactLaw(x - e, slope);
      *scale = std::abs(m * a) + std::abs(c * v) + std::abs(spring) + std::abs(f);
      return m * a + c * v + spring - f;
    };

    NewmarkStepReport report;
    double x = s.x + h * s.v + 0.5 * h * h * s.a;  // explicit predictor
    // Bracket [lo, hi] of the root with the residuals there (R increases with x). A Newton step
    // that leaves the bracket (cycling between branches of g) is replaced by the Illinois
    // variant of regula falsi, which converges superlinearly on piecewise-linear residuals.
    double lo = -HUGE_VAL, hi = HUGE_VAL, r_lo = 0.0, r_hi = 0.0;
    int side = 0;  // which end moved last (Illinois: halve the other end's residual)
    double slope = 0.0, scale = 0.0;
    double r = residual(x, &slope, &scale);
    report.converged = false;
    for (report.iterations = 1; report.iterations <= max_iterations_; ++report.iterations) {
      if (r < 0.0) {
        if (side == -1) r_hi *= 0.5;
        lo = x, r_lo = r, side = -1;
      } else if (r > 0.0) {
        if (side == 1) r_lo *= 0.5;
        hi = x, r_hi = r, side = 1;
      }
      // With contact elements the residual's slope is already dF/dx.
      double next = x - r / (inertia + (elements ? slope : k * slope));
      if (std::isfinite(lo) && std::isfinite(hi) && !(next > lo && next < hi)) {
        next = lo - r_lo * (hi - lo) / (r_hi - r_lo);
      }
      const double dx = next - x;
      x = next;
      r = residual(x, &slope, &scale);
      if (std::abs(r) <= 1e-13 * scale || std::abs(dx) <= tolerance_) {
        report.converged = true;
        break;
      }
    }
    const double a = (x - x_star) / bh2;
    s.v = v_star + p_.gamma * h * a;
    s.x = x;
    s.a = a;
    return report;
  }

 private:
  const Model& model_;
  NewmarkParameters p_;
  double tolerance_;
  int max_iterations_;
};

}  // namespace geardyn

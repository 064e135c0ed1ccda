#pragma once
/// \file
/// Natural frequencies of a uniform Timoshenko beam (shear deformation and rotary inertia) with
/// clamped or free ends, from the exact solution of its two equations (Timoshenko 1921; the
/// frequency equation as in Han, Benaroya & Wei 1999, J. Sound Vib. 225(5) 935-988, sec. 6):
///   κGA (w'' − ψ') + ρAω² w = 0,   EI ψ'' + κGA (w' − ψ) + ρIω² ψ = 0.
/// With w, ψ ∝ e^{sx} the characteristic equation is, for S = s²,
///   κGA·EI S² + (κGA ρIω² + ρAω² EI) S + ρAω² (ρIω² − κGA) = 0,
/// whose roots below the second spectrum's cut-off ω_c = √(κGA/ρI) are S₁ = α² > 0 and
/// S₂ = −β² < 0; the solution is spanned by (w, ψ) = (cosh αx, r sinh αx), (sinh αx, r cosh αx),
/// (cos βx, q sin βx), (sin βx, −q cos βx) with r = (κGA α² + ρAω²)/(κGA α) and
/// q = (ρAω² − κGA β²)/(κGA β) (from the first equation). A clamped end holds w = ψ = 0, a free
/// end has no moment and no shear force, ψ' = 0 and w' − ψ = 0. The frequencies are the zeros
/// of the 4 × 4 determinant of the two ends' conditions, bracketed by a scan and bisected.

#include <Eigen/Dense>
#include <cmath>
#include <numbers>
#include <vector>

namespace geardyn::testing {

struct TimoshenkoBeam {
  double length = 1.0;          ///< L [m]
  double E = 210e9, G = 0.0;    ///< [Pa]
  double kappa = 5.0 / 6.0;     ///< shear coefficient κ [-]
  double rho = 7850.0;          ///< [kg/m³]
  double area = 0.0;            ///< A [m²]
  double inertia = 0.0;         ///< second moment I [m⁴]
  double rotary_inertia = 1.0;  ///< factor on ρI (0: no rotary inertia, Euler–Bernoulli's limit)
};

enum class BeamEnd { clamped, free };

/// The boundary-condition determinant at ω [rad/s].
inline double timoshenkoDeterminant(const TimoshenkoBeam& b, BeamEnd left, BeamEnd right,
                                    double w) {
  const double kga = b.kappa * b.G * b.area, ei = b.E * b.inertia;
  const double ra = b.rho * b.area * w * w, ri = b.rotary_inertia * b.rho * b.inertia * w * w;
  const double c2 = kga * ei, c1 = kga * ri + ra * ei, c0 = ra * (ri - kga);
  const double disc = std::sqrt(c1 * c1 - 4.0 * c2 * c0);
  const double alpha = std::sqrt((-c1 + disc) / (2.0 * c2));
  const double beta = std::sqrt((c1 + disc) / (2.0 * c2));
  const double r = (kga * alpha * alpha + ra) / (kga * alpha);
  const double q = (ra - kga * beta * beta) / (kga * beta);
  // Rows: the two conditions at each end; columns: the four solutions (w, ψ, w', ψ' at x).
  auto rows = [&](double x, BeamEnd end) {
    const double ch = std::cosh(alpha * x), sh = std::sinh(alpha * x);
    const double c = std::cos(beta * x), s = std::sin(beta * x);
    Eigen::Matrix<double, 4, 4> state;                // w, ψ, w', ψ' of each solution
    state << ch, sh, c, s,                            //
        r * sh, r * ch, q * s, -q * c,                //
        alpha * sh, alpha * ch, -beta * s, beta * c,  //
        r * alpha * ch, r * alpha * sh, q * beta * c, q * beta * s;
    Eigen::Matrix<double, 2, 4> bc;
    if (end == BeamEnd::clamped) {
      bc << state.row(0), state.row(1);
    } else {
      bc << state.row(3), state.row(2) - state.row(1);
    }
    return bc;
  };
  Eigen::Matrix4d D;
  D << rows(0.0, left), rows(b.length, right);
  // Scale each column by its largest entry: cosh αL grows fast and the determinant's sign is
  // what the bisection needs.
  for (int j = 0; j < 4; ++j) D.col(j) /= D.col(j).cwiseAbs().maxCoeff();
  return D.determinant();
}

/// The lowest `count` flexural frequencies [Hz], scanning from `start_hz` in steps of `step_hz`.
inline std::vector<double> timoshenkoFrequenciesHz(const TimoshenkoBeam& b, BeamEnd left,
                                                   BeamEnd right, int count, double start_hz,
                                                   double step_hz) {
  std::vector<double> hz;
  const double two_pi = 2.0 * std::numbers::pi;
  double f0 = start_hz, d0 = timoshenkoDeterminant(b, left, right, two_pi * f0);
  while (static_cast<int>(hz.size()) < count && f0 < 1e3 * (start_hz + step_hz) * count) {
    const double f1 = f0 + step_hz, d1 = timoshenkoDeterminant(b, left, right, two_pi * f1);
    if ((d0 < 0.0) != (d1 < 0.0)) {
      double lo = f0, hi = f1, dlo = d0;
      for (int i = 0; i < 200 && hi - lo > 1e-13 * hi; ++i) {
        const double mid = 0.5 * (lo + hi),
                     dm = timoshenkoDeterminant(b, left, right, two_pi * mid);
        if ((dm < 0.0) == (dlo < 0.0)) {
          lo = mid;
          dlo = dm;
        } else {
          hi = mid;
        }
      }
      hz.push_back(0.5 * (lo + hi));
    }
    f0 = f1;
    d0 = d1;
  }
  return hz;
}

}  // namespace geardyn::testing

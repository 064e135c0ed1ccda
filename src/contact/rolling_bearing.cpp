/// Rolling-element bearing from its geometry (rolling_bearing.h): the contacts, the
/// load–deflection relation and its tangent stiffness, and the solve for a given load.

#include "geardyn/contact/rolling_bearing.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "geardyn/contact/hertz_point_contact.h"

namespace geardyn {
namespace {

constexpr double kPi = std::numbers::pi;

/// ISO/TS 16281:2008 eq. (42)–(44): the logarithmic roller profile drop at x from the roller's
/// middle [m]. For L_we > 2.5 D_we the drop is 0 in the middle and logarithmic over 1.25 D_we at
/// each end; the open transcription we compared with (github.com/minzhun/ISO16281,
/// RollerBearing.py) has 2|x| − L − 2.5D in that branch, corrected here to 2|x| − (L − 2.5D),
/// which is 0 where the flat part ends and reaches the edge at |x| = L/2.
double logarithmicDrop(const RollingBearingGeometry& g, double x) {
  const double D = g.element_diameter, L = g.roller_length;
  const double tapered = g.type == RollingBearingType::kTaperedRoller;
  auto log_drop = [](double c, double u) { return c * std::log(1.0 / (1.0 - u * u)); };
  if (tapered) return log_drop(0.00045 * D, 2.0 * x / L);
  if (L <= 2.5 * D) return log_drop(0.00035 * D, 2.0 * x / L);
  const double flat = 0.5 * (L - 2.5 * D);
  if (std::abs(x) <= flat) return 0.0;
  return log_drop(0.0005 * D, (2.0 * std::abs(x) - (L - 2.5 * D)) / (2.5 * D));
}

double profileDrop(const RollingBearingGeometry& g, double x) {
  switch (g.profile) {
    case RollerProfile::kStraight:
      return 0.0;
    case RollerProfile::kCrowned:
      return g.crown_drop * (2.0 * x / g.roller_length) * (2.0 * x / g.roller_length);
    case RollerProfile::kLogarithmic:
      return logarithmicDrop(g, x);
  }
  return 0.0;
}

/// The displacement along the bearing axis and radially at azimuth ψ of the inner ring's point
/// at axial position x_p and radius r_p, per q = (u_y, u_z, u_x, θ_y, θ_z): u + θ × p with
/// p = (x_p, r_p cos ψ, r_p sin ψ) gives u_x + r_p (θ_y sin ψ − θ_z cos ψ) axially and
/// (u_y + θ_z x_p) cos ψ + (u_z − θ_y x_p) sin ψ radially (Lim & Singh 1990, eq. 5).
void pointGradients(double psi, double x_p, double r_p, RollingBearing::Vector5& g_r,
                    RollingBearing::Vector5& g_a) {
  const double c = std::cos(psi), s = std::sin(psi);
  g_r << c, s, 0.0, -x_p * s, x_p * c;
  g_a << 0.0, 0.0, 1.0, r_p * s, -r_p * c;
}

}  // namespace

RollingBearing::RollingBearing(RollingBearingGeometry geometry, const std::string& key)
    : g_(std::move(geometry)) {
  g_.validate(key);
  const double D = g_.element_diameter, dm = g_.pitch_diameter, alpha = g_.contact_angle;
  const double gamma = D * std::cos(alpha) / dm;
  const double e_star = contactModulus(g_.youngs_modulus, g_.poisson_ratio,
                                       g_.element_youngs_modulus, g_.element_poisson_ratio);
  if (g_.ball()) {
    // Harris & Kotzalas (2006) vol. 1 eq. (2.27)–(2.30): curvature sums in the rolling plane
    // 2/(D(1 ∓ γ)) and across the groove 2/D − 1/r; Johnson's A, B are half of them.
    A_ = g_.inner_groove_radius + g_.outer_groove_radius - D;
    const HertzPointContact inner = hertzPointContact(
        1.0 / (D * (1.0 - gamma)), 1.0 / D - 0.5 / g_.inner_groove_radius, e_star);
    const HertzPointContact outer = hertzPointContact(
        1.0 / (D * (1.0 + gamma)), 1.0 / D - 0.5 / g_.outer_groove_radius, e_star);
    // Both contacts carry Q: δ = (c_i + c_e) Q^{2/3}, so K_n = (c_i + c_e)^{-3/2}.
    k_ball_ = std::pow(inner.deflection + outer.deflection, -1.5);
    pressure_ball_ = std::max(inner.pressure, outer.pressure);
  } else {
    // ISO/TS 16281 eq. (37): c_l = 35948 L_we^{8/9} [N mm^{-10/9}] for steel (E 210 GPa,
    // ν 0.3), scaled with E*; in SI 35948·10⁶ L^{8/9}; c_s = c_l / n_s per slice.
    const double steel = contactModulus(2.1e11, 0.3, 2.1e11, 0.3);
    k_slice_ = 35948e6 * (e_star / steel) * std::pow(g_.roller_length, 8.0 / 9.0) / g_.slices;
    // Line contact (Johnson eq. 4.45): p₀ = √(w E* Σρ / π), w the load per length, Σρ of
    // the inner contact 2/(D(1 − γ)) (the larger).
    pressure_line_ = std::sqrt(e_star * 2.0 / (D * (1.0 - gamma)) / kPi);
  }
  const int rows = g_.rows();
  for (int row = 0; row < rows; ++row) {
    // Pairs: rows at ∓ s/2; back to back the row at +s/2 presses towards −x (its load line
    // meets the axis outside the pair), face to face towards +x.
    const double x_row = rows == 1 ? 0.0 : (row == 0 ? -0.5 : 0.5) * g_.row_spacing;
    double sigma = 1.0;
    if (g_.arrangement == BearingArrangement::kBackToBack) sigma = row == 0 ? 1.0 : -1.0;
    if (g_.arrangement == BearingArrangement::kFaceToFace) sigma = row == 0 ? -1.0 : 1.0;
    if (g_.reversed) sigma = -sigma;
    for (int j = 0; j < g_.elements; ++j) {
      const int element = static_cast<int>(azimuth_.size());
      const double psi = 2.0 * kPi * j / g_.elements;
      azimuth_.push_back(psi);
      row_of_.push_back(row);
      if (g_.ball()) {
        // The inner groove's curvature centre: radius d_m/2 + (r_i − D/2) cos α₀ (ISO/TS
        // 16281 eq. 16, Lim & Singh 1990 eq. 7).
        Contact c{element, sigma, {}, {}, 0.0};
        pointGradients(psi, x_row, 0.5 * dm + (g_.inner_groove_radius - 0.5 * D) * std::cos(alpha),
                       c.g_r, c.g_a);
        contacts_.push_back(c);
        continue;
      }
      if (g_.type == RollingBearingType::kSphericalRoller) {
        addSphericalSlices(element, psi, row == 0 ? -1.0 : 1.0);
        continue;
      }
      // Roller slices along the roller axis t = (cos α, −σ sin α) (axial, radial), normal
      // n = (σ sin α, cos α): the normal approach of slice k is n · (u + θ × p_k).
      for (int k = 0; k < g_.slices; ++k) {
        const double s = (k - 0.5 * g_.slices + 0.5) * g_.roller_length / g_.slices;
        Vector5 g_r, g_a;
        pointGradients(psi, x_row + s * std::cos(alpha), 0.5 * dm - sigma * s * std::sin(alpha),
                       g_r, g_a);
        Contact c{element, sigma, g_r * std::cos(alpha) + g_a * sigma * std::sin(alpha),
                  Vector5::Zero(), 0.0};
        c.offset = -0.5 * g_.clearance * std::cos(alpha) - 2.0 * profileDrop(g_, s);
        contacts_.push_back(c);
      }
    }
  }
}

void RollingBearing::addSphericalSlices(int element, double psi, double side) {
  // Spherical roller bearing (Harris & Kotzalas 2006, vol. 1 §7.2): the outer raceway is the
  // sphere of radius R_e about the bearing's centre, the roller of row `side` (−1: at −x, +1:
  // at +x) touches it along the meridian arc φ ∈ α₀ ± L/(2 R_e). Slice k touches at
  // p_k = R_e (side sin φ_k, cos φ_k) (axial, radial) with the normal n_k = p_k / R_e, so its
  // approach is n_k · (u + θ × p_k) = n_k · u: θ × p_k ⊥ p_k, no tilt stiffness. The rows'
  // contact lines meet at the centre (an X pair): row −x takes the shaft's load towards −x.
  const double R = g_.outerRacewayRadius();
  for (int k = 0; k < g_.slices; ++k) {
    const double s = (k - 0.5 * g_.slices + 0.5) * g_.roller_length / g_.slices;
    const double phi = g_.contact_angle + s / R;
    Vector5 g_r, g_a;
    pointGradients(psi, side * R * std::sin(phi), R * std::cos(phi), g_r, g_a);
    Contact c{element, side, g_r * std::cos(phi) + g_a * side * std::sin(phi), Vector5::Zero(),
              0.0};
    c.offset = -0.5 * g_.clearance * std::cos(g_.contact_angle) - 2.0 * profileDrop(g_, s);
    contacts_.push_back(c);
  }
}

double RollingBearing::ballLoad(const Contact& c, const Vector5& q, Vector5& F, Matrix5* K,
                                double* alpha) const {
  // The inner groove centre relative to the outer one: radially A cos α₀ − s_r/2 + g_r·q,
  // axially (in the row's sense σ) A sin α₀ + σ g_a·q; δ = its length − A (Harris & Kotzalas
  // eq. 7.6–7.8; ISO/TS 16281 eq. 12), the contact angle its direction.
  const double ar = A_ * std::cos(g_.contact_angle) - 0.5 * g_.clearance + c.g_r.dot(q);
  const double aa = A_ * std::sin(g_.contact_angle) + c.sigma * c.g_a.dot(q);
  if (alpha) *alpha = std::atan2(aa, ar);
  // An angular-contact row has one shoulder: no contact once the centres pass each other.
  if (g_.type == RollingBearingType::kAngularContactBall && aa <= 0.0) return 0.0;
  const double length = std::hypot(ar, aa);
  const double delta = length - A_;
  if (!(delta > 0.0)) return 0.0;
  const double root = std::sqrt(delta);
  const double Q = k_ball_ * delta * root;
  const double co = ar / length, si = aa / length;
  // ∂δ/∂q = n, ∂²δ/∂q² = t tᵀ / |A| (the contact angle turning with the load).
  const Vector5 n = co * c.g_r + si * c.sigma * c.g_a;
  F += Q * n;
  if (K) {
    const Vector5 t = -si * c.g_r + co * c.sigma * c.g_a;
    K->noalias() += (1.5 * k_ball_ * root) * n * n.transpose();
    K->noalias() += (Q / length) * t * t.transpose();
  }
  return Q;
}

double RollingBearing::sliceLoad(const Contact& c, const Vector5& q, Vector5& F, Matrix5* K) const {
  const double delta = c.g_r.dot(q) + c.offset;
  if (!(delta > 0.0)) return 0.0;
  const double ninth = std::cbrt(std::cbrt(delta));  // δ^{1/9}
  const double Q = k_slice_ * delta * ninth;         // c_s δ^{10/9} (ISO/TS 16281 eq. 40)
  F += Q * c.g_r;
  if (K) K->noalias() += (10.0 / 9.0 * k_slice_ * ninth) * c.g_r * c.g_r.transpose();
  return Q;
}

void RollingBearing::evaluate(const Vector5& q, Vector5& F, Matrix5* K) const {
  F.setZero();
  if (K) K->setZero();
  if (g_.ball()) {
    for (const Contact& c : contacts_) ballLoad(c, q, F, K, nullptr);
  } else {
    for (const Contact& c : contacts_) sliceLoad(c, q, F, K);
  }
}

RollingBearingState RollingBearing::state(const Vector5& q) const {
  RollingBearingState s;
  s.displacement = q;
  s.elements.resize(azimuth_.size());
  for (std::size_t j = 0; j < azimuth_.size(); ++j) {
    s.elements[j].row = row_of_[j];
    s.elements[j].azimuth = azimuth_[j];
    s.elements[j].contact_angle = g_.contact_angle;
  }
  std::vector<double> slice_loads;
  Vector5 F = Vector5::Zero();
  Matrix5 K = Matrix5::Zero();
  const double width = g_.ball() ? 0.0 : g_.roller_length / g_.slices;
  for (std::size_t i = 0; i < contacts_.size(); ++i) {
    const Contact& c = contacts_[i];
    RollingElementState& e = s.elements[c.element];
    if (g_.ball()) {
      e.load = ballLoad(c, q, F, &K, &e.contact_angle);
      e.deflection = std::pow(e.load / k_ball_, 2.0 / 3.0);
      e.max_pressure = pressure_ball_ * std::cbrt(e.load);
    } else {
      const double load = sliceLoad(c, q, F, &K);
      slice_loads.push_back(load);
      e.load += load;
      e.deflection = std::max(e.deflection, std::max(0.0, c.g_r.dot(q) + c.offset));
      e.max_pressure = std::max(e.max_pressure, pressure_line_ * std::sqrt(load / width));
    }
  }
  s.load = F;
  s.stiffness = K;
  for (const RollingElementState& e : s.elements) {
    s.max_element_load = std::max(s.max_element_load, e.load);
    s.max_pressure = std::max(s.max_pressure, e.max_pressure);
  }
  s.rating_life = ratingLife(s.elements, slice_loads);
  return s;
}

RollingBearing::Vector5 RollingBearing::referenceStiffness() const noexcept {
  const double R = 0.5 * g_.pitch_diameter, dref = referenceDeflection();
  const double count = static_cast<double>(contacts_.size());
  const double k =
      g_.ball() ? count * k_ball_ * std::sqrt(dref) : count * k_slice_ * std::cbrt(std::cbrt(dref));
  Vector5 D;
  D << k, k, k, k * R * R, k * R * R;
  return D;
}

RollingBearingSolveResult RollingBearing::solve(const Vector5& load) const {
  // Damped Newton (Levenberg–Marquardt): (K + μ D) Δq = F_given − F(q), D the stiffness of
  // every element at the reference deflection spread over the DOFs (moments over the pitch
  // radius²), μ ÷ 10 on a step that does not raise the scaled residual, × 10 otherwise. The
  // contacts have no stiffness at q = 0 without preload, where a plain Newton step is undefined.
  const double R = 0.5 * g_.pitch_diameter;
  Vector5 weight;  // residual scaling: forces [N], moments / R [N]
  weight << 1.0, 1.0, 1.0, 1.0 / R, 1.0 / R;
  const Vector5 D = referenceStiffness();
  const double scale = std::max(load.cwiseProduct(weight).norm(), 1e-300);
  RollingBearingSolveResult out;
  Vector5 q = Vector5::Zero(), F;
  Matrix5 K;
  evaluate(q, F, &K);
  double norm = (load - F).cwiseProduct(weight).norm();
  double mu = 1.0;
  constexpr double kTolerance = 1e-12;  // relative residual: round-off of the contact sums
  int it = 0;
  for (; it < 200 && norm > kTolerance * scale; ++it) {
    Matrix5 J = K;
    J.diagonal() += mu * D;
    const Vector5 step = J.ldlt().solve(load - F);
    const Vector5 trial = q + step;
    Vector5 F_trial;
    Matrix5 K_trial;
    evaluate(trial, F_trial, &K_trial);
    const double trial_norm = (load - F_trial).cwiseProduct(weight).norm();
    // A step that does not raise the residual is taken: inside the clearance F stays 0 and the
    // residual with it, and the steps must grow (μ ÷ 10) until they close the gap.
    if (trial_norm <= norm) {
      q = trial, F = F_trial, K = K_trial, norm = trial_norm;
      mu = std::max(mu / 10.0, 1e-14);
    } else {
      mu *= 10.0;
      if (mu > 1e20) break;
    }
  }
  out.iterations = it;
  out.residual = norm / scale;
  out.status = norm <= kTolerance * scale || load.isZero(0.0) ? "converged" : "max_iterations";
  out.state = state(q);
  return out;
}

}  // namespace geardyn

/// Timoshenko shaft element: matrices integrated from the shape functions by Gauss quadrature,
/// so that mass, stiffness and gyroscopic matrices share one set of fields and one sign
/// convention (Nelson 1980 writes them in closed form for axes y/z with another rotation sign;
/// integrating avoids transcribing sign patterns).

#include "geardyn/models/timoshenko_shaft_element.h"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <numbers>

#include "geardyn/error.h"

namespace geardyn {
namespace {

using Row = Eigen::Matrix<double, 1, 2 * kNodeDofs>;

/// Global column of DOF `dof` of element node `node` (0 or 1).
constexpr int col(int node, int dof) {
  return node * kNodeDofs + dof;
}

/// The interpolated fields at ξ = x/L ∈ [0, 1] and their x-derivatives.
struct Fields {
  Row ux, uy, uz, rx, ry, rz;        // values
  Row dux, drx, dry, drz, duy, duz;  // d/dx
};

/// Friedman & Kosmatka (1993) interpolation for one bending plane: displacement v and slope
/// rotation θ (θ ≈ dv/dx) from [v₁, θ₁, v₂, θ₂]; exact for the static Timoshenko beam.
struct PlaneShape {
  std::array<double, 4> v, theta, dv, dtheta;
};

PlaneShape planeShape(double xi, double L, double phi) {
  const double s = 1.0 / (1.0 + phi), x2 = xi * xi, x3 = x2 * xi;
  PlaneShape p;
  p.v = {s * (2 * x3 - 3 * x2 - phi * xi + 1 + phi),
         s * L * (x3 - (2 + phi / 2) * x2 + (1 + phi / 2) * xi), -s * (2 * x3 - 3 * x2 - phi * xi),
         s * L * (x3 - (1 - phi / 2) * x2 - (phi / 2) * xi)};
  p.theta = {6 * s / L * (x2 - xi), s * (3 * x2 - (4 + phi) * xi + 1 + phi), -6 * s / L * (x2 - xi),
             s * (3 * x2 - (2 - phi) * xi)};
  p.dv = {s * (6 * x2 - 6 * xi - phi) / L, s * (3 * x2 - (4 + phi) * xi + 1 + phi / 2),
          -s * (6 * x2 - 6 * xi - phi) / L, s * (3 * x2 - (2 - phi) * xi - phi / 2)};
  p.dtheta = {6 * s / (L * L) * (2 * xi - 1), s * (6 * xi - (4 + phi)) / L,
              -6 * s / (L * L) * (2 * xi - 1), s * (6 * xi - (2 - phi)) / L};
  return p;
}

Fields fieldsAt(double xi, double L, double phi) {
  Fields f;
  for (Row* r :
       {&f.ux, &f.uy, &f.uz, &f.rx, &f.ry, &f.rz, &f.dux, &f.drx, &f.dry, &f.drz, &f.duy, &f.duz})
    r->setZero();
  // Axial displacement and twist: linear.
  for (int n = 0; n < 2; ++n) {
    const double N = n == 0 ? 1.0 - xi : xi, dN = (n == 0 ? -1.0 : 1.0) / L;
    f.ux(col(n, kUx)) = N;
    f.dux(col(n, kUx)) = dN;
    f.rx(col(n, kRx)) = N;
    f.drx(col(n, kRx)) = dN;
  }
  const PlaneShape p = planeShape(xi, L, phi);
  // Plane x–y: u_y with slope rotation θ_z (du_y/dx ≈ θ_z).
  // Plane x–z: u_z with slope rotation β = −θ_y (du_z/dx ≈ −θ_y), so θ_y DOFs enter with a
  // minus sign in u_z, and θ_y(x) = −β(x).
  const std::array<int, 4> y_cols{col(0, kUy), col(0, kRz), col(1, kUy), col(1, kRz)};
  const std::array<int, 4> z_cols{col(0, kUz), col(0, kRy), col(1, kUz), col(1, kRy)};
  const std::array<double, 4> z_sign{1.0, -1.0, 1.0, -1.0};
  for (int i = 0; i < 4; ++i) {
    f.uy(y_cols[i]) = p.v[i];
    f.duy(y_cols[i]) = p.dv[i];
    f.rz(y_cols[i]) = p.theta[i];
    f.drz(y_cols[i]) = p.dtheta[i];
    f.uz(z_cols[i]) = z_sign[i] * p.v[i];
    f.duz(z_cols[i]) = z_sign[i] * p.dv[i];
    f.ry(z_cols[i]) = -z_sign[i] * p.theta[i];
    f.dry(z_cols[i]) = -z_sign[i] * p.dtheta[i];
  }
  return f;
}

/// Five-point Gauss–Legendre rule on [0, 1]: exact to degree 9 (the integrands are ≤ 6).
constexpr std::array<double, 5> kGaussX{0.0469100770306680, 0.2307653449471585, 0.5,
                                        0.7692346550528415, 0.9530899229693320};
constexpr std::array<double, 5> kGaussW{0.1184634425280945, 0.2393143352496832, 0.2844444444444444,
                                        0.2393143352496832, 0.1184634425280945};

template <typename Integrand>
ElementMatrix integrate(const ShaftSegment& s, Integrand integrand) {
  ElementMatrix m = ElementMatrix::Zero();
  const double L = s.length, phi = s.shearParameter();
  for (std::size_t g = 0; g < kGaussX.size(); ++g) {
    m += (kGaussW[g] * L) * integrand(fieldsAt(kGaussX[g], L, phi));
  }
  return m;
}

}  // namespace

double ShaftSegment::area() const {
  return std::numbers::pi / 4.0 *
         (outer_diameter * outer_diameter - inner_diameter * inner_diameter);
}

double ShaftSegment::secondMomentOfArea() const {
  return std::numbers::pi / 64.0 * (std::pow(outer_diameter, 4) - std::pow(inner_diameter, 4));
}

double ShaftSegment::shearCoefficient() const {
  const double nu = youngs_modulus / (2.0 * shear_modulus) - 1.0;
  const double m = inner_diameter / outer_diameter, m2 = m * m, q = (1 + m2) * (1 + m2);
  return 6.0 * (1.0 + nu) * q / ((7.0 + 6.0 * nu) * q + (20.0 + 12.0 * nu) * m2);
}

double ShaftSegment::shearParameter() const {
  return 12.0 * youngs_modulus * secondMomentOfArea() /
         (shearCoefficient() * shear_modulus * area() * length * length);
}

void ShaftSegment::validate(const std::string& key) const {
  auto require = [&](bool ok, const std::string& name, double value, const char* allowed) {
    if (!ok || !std::isfinite(value))
      throw InputError(key + "." + name, fmt::format("{:g}", value), allowed);
  };
  require(length > 0, "length", length, "a length > 0 m");
  require(outer_diameter > 0, "outer_diameter", outer_diameter, "a diameter > 0 m");
  require(inner_diameter >= 0 && inner_diameter < outer_diameter, "inner_diameter", inner_diameter,
          "0 <= inner diameter < outer diameter");
  require(youngs_modulus > 0, "youngs_modulus", youngs_modulus, "a modulus > 0 Pa");
  require(shear_modulus > 0, "shear_modulus", shear_modulus, "a modulus > 0 Pa");
  require(density > 0, "density", density, "a density > 0 kg/m^3");
  const double nu = youngs_modulus / (2.0 * shear_modulus) - 1.0;
  require(nu > -1.0 && nu < 0.5, "shear_modulus", shear_modulus,
          "a shear modulus giving a Poisson ratio E/(2G) - 1 in (-1, 0.5)");
}

ElementMatrix shaftElementStiffness(const ShaftSegment& s) {
  const double EA = s.youngs_modulus * s.area(), GJ = s.shear_modulus * s.polarMomentOfArea();
  const double EI = s.youngs_modulus * s.secondMomentOfArea();
  const double kGA = s.shearCoefficient() * s.shear_modulus * s.area();
  return integrate(s, [&](const Fields& f) -> ElementMatrix {
    const Row gy = f.duy - f.rz;  // shear strain in x–y: du_y/dx − θ_z
    const Row gz = f.duz + f.ry;  // shear strain in x–z: du_z/dx + θ_y
    return EA * f.dux.transpose() * f.dux + GJ * f.drx.transpose() * f.drx +
           EI * (f.dry.transpose() * f.dry + f.drz.transpose() * f.drz) +
           kGA * (gy.transpose() * gy + gz.transpose() * gz);
  });
}

ElementMatrix shaftElementMass(const ShaftSegment& s) {
  const double rA = s.density * s.area(), rI = s.density * s.secondMomentOfArea();
  const double rJ = s.density * s.polarMomentOfArea();
  return integrate(s, [&](const Fields& f) -> ElementMatrix {
    return rA * (f.ux.transpose() * f.ux + f.uy.transpose() * f.uy + f.uz.transpose() * f.uz) +
           rJ * f.rx.transpose() * f.rx + rI * (f.ry.transpose() * f.ry + f.rz.transpose() * f.rz);
  });
}

ElementMatrix shaftElementGyroscopic(const ShaftSegment& s) {
  // Spin kinetic energy per unit length ½ ρJ (Ω − θ̇_z θ_y)² (small tilts, spin about +x)
  // gives the Lagrange term ρJ Ω (N_θyᵀ N_θz − N_θzᵀ N_θy) q̇.
  const double rJ = s.density * s.polarMomentOfArea();
  return integrate(s, [&](const Fields& f) -> ElementMatrix {
    return rJ * (f.ry.transpose() * f.rz - f.rz.transpose() * f.ry);
  });
}

}  // namespace geardyn

#include "geardyn/solvers/rotor_response.h"

#include <Eigen/Dense>

namespace geardyn {

using Complex = std::complex<double>;

std::vector<RotorWhirlResponse> solveRotorFrequencyResponse(const LateralRotorModel& model) {
  const Eigen::Matrix2cd k = model.stiffness2().cast<Complex>();
  const Eigen::Matrix2cd m = model.mass2().cast<Complex>();
  const Eigen::Matrix2cd c = model.damping2().cast<Complex>();
  std::vector<RotorWhirlResponse> out;
  for (const WhirlForcing& f : model.whirlForcing()) {
    const double w = f.omega;
    const Eigen::Matrix2cd a = k - w * w * m + Complex(0.0, w) * c;
    out.push_back({f.name, w, a.partialPivLu().solve(f.force)});
  }
  return out;
}

std::vector<Eigen::Vector4d> superposeWhirlResponse(const std::vector<RotorWhirlResponse>& parts,
                                                    const std::vector<double>& times) {
  std::vector<Eigen::Vector4d> out(times.size(), Eigen::Vector4d::Zero());
  for (std::size_t i = 0; i < times.size(); ++i) {
    Complex z1 = 0.0, z2 = 0.0;
    for (const auto& p : parts) {
      const Complex e = std::polar(1.0, p.omega * times[i]);
      z1 += p.response(0) * e;
      z2 += p.response(1) * e;
    }
    out[i] = Eigen::Vector4d(z1.real(), z1.imag(), z2.real(), z2.imag());
  }
  return out;
}

}  // namespace geardyn

/// Element forces at one harmonic of a train's steady state (train_element_orders.h).

#include "geardyn/solvers/train_element_orders.h"

#include <complex>
#include <stdexcept>

namespace geardyn {

double elementForceHarmonic(const TrainElement& element, const TrainSteadyState& state, int h) {
  if (h < 1 || h > state.harmonics) {
    throw std::out_of_range("elementForceHarmonic: harmonic " + std::to_string(h) + " outside 1.." +
                            std::to_string(state.harmonics));
  }
  Eigen::VectorXcd x(static_cast<Eigen::Index>(element.dofs.size()));
  for (std::size_t i = 0; i < element.dofs.size(); ++i) {
    x(static_cast<Eigen::Index>(i)) = state.harmonic(element.dofs[i], h);
  }
  const Eigen::VectorXcd force =
      2.0 * (element.local_stiffness * element.jacobian).cast<std::complex<double>>() * x;
  double sum = 0.0;
  for (Eigen::Index r = 0; r < force.size(); ++r) {
    const bool moment = static_cast<std::size_t>(r) < element.moment_rows.size() &&
                        element.moment_rows[static_cast<std::size_t>(r)];
    if (!moment) sum += std::norm(force(r));
  }
  return std::sqrt(sum);
}

}  // namespace geardyn

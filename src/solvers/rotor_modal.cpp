/// Modal analysis and Campbell diagram of the FE geared rotor.

#include "geardyn/solvers/rotor_modal.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "geardyn/error.h"
#include "geardyn/solvers/detail/damped_modes.h"
#include "geardyn/solvers/detail/mode_tracking.h"
#include "geardyn/solvers/detail/whirl_shares.h"

namespace geardyn {
namespace {

constexpr double kTwoPi = 6.283185307179586;

void classify(const FeGearedRotor& model, RotorMode& mode) {
  const Eigen::VectorXd& md = model.mass().diagonal();
  detail::WhirlShares shares;
  const int n = model.dofCount();
  for (int i = 0; i < n; ++i) {
    const double e = md(i) * std::norm(mode.shape(i));
    switch (model.typeOf(i)) {
      case kUx:
        shares.axial += e;
        break;
      case kRx:
        shares.torsional += e;
        break;
      default:
        shares.lateral += e;
    }
    if (model.typeOf(i) != kUy) continue;
    const int iz = model.dofIndex(model.shaftOf(i), model.nodeOf(i), kUz);
    shares.addWhirl(md(i), mode.shape(i), mode.shape(iz), model.spinRatio(model.shaftOf(i)));
  }
  shares.describe(mode);
}

}  // namespace

void ModalOptions::validate() const {
  if (modes < 1) throw InputError("modal.modes", std::to_string(modes), "an integer >= 1");
  if (!(mesh_stiffness >= 0.0) || !std::isfinite(mesh_stiffness))
    throw InputError("modal.mesh_stiffness", fmt::format("{:g}", mesh_stiffness),
                     "a stiffness >= 0 N/m (0: the mean)");
  if (!(max_damping_ratio > 0.0 && max_damping_ratio <= 1.0))
    throw InputError("modal.max_damping_ratio", fmt::format("{:g}", max_damping_ratio),
                     "a damping ratio in (0, 1]");
  if (!(rigid_frequency >= 0.0))
    throw InputError("modal.rigid_frequency", fmt::format("{:g}", rigid_frequency), ">= 0 Hz");
}

std::vector<RotorMode> modalAnalysis(const FeGearedRotor& model, double pinion_speed,
                                     const ModalOptions& options) {
  options.validate();
  const double k = options.mesh_stiffness > 0 ? options.mesh_stiffness : model.meanMeshStiffness();
  const Eigen::VectorXd& v = model.meshVector();
  const Eigen::MatrixXd K = model.stiffness() + k * v * v.transpose();
  const Eigen::MatrixXd D = model.damping() + pinion_speed * model.gyroscopic();
  std::vector<RotorMode> modes;
  for (detail::DampedMode& found : detail::dampedModes(model.mass(), D, K)) {
    const std::complex<double> lambda = found.eigenvalue;
    if (std::abs(lambda) / kTwoPi < options.rigid_frequency) continue;
    if (-lambda.real() / std::abs(lambda) > options.max_damping_ratio) continue;
    RotorMode mode;
    mode.eigenvalue = lambda;
    mode.frequency = lambda.imag() / kTwoPi;
    mode.damping_ratio = -lambda.real() / std::abs(lambda);
    mode.shape = std::move(found.shape);
    classify(model, mode);
    modes.push_back(std::move(mode));
  }
  std::sort(modes.begin(), modes.end(),
            [](const RotorMode& a, const RotorMode& b) { return a.frequency < b.frequency; });
  if (static_cast<int>(modes.size()) > options.modes) modes.resize(options.modes);
  return modes;
}

std::vector<OrderLine> standardOrderLines(const FeGearedRotor& model) {
  return {{"1x pinion", 1.0},
          {"1x gear", std::abs(model.spinRatio(1))},
          {"mesh", static_cast<double>(model.spec().pinion_teeth)}};
}

CampbellDiagram campbellDiagram(const FeGearedRotor& model, const std::vector<double>& speeds,
                                const ModalOptions& options, const std::vector<OrderLine>& lines) {
  options.validate();
  if (speeds.size() < 2) throw InputError("campbell.speeds", "", "at least two speeds");
  for (std::size_t i = 1; i < speeds.size(); ++i) {
    if (!(speeds[i] > speeds[i - 1]))
      throw InputError("campbell.speeds", fmt::format("{:g}", speeds[i]), "ascending speeds");
  }
  CampbellDiagram d;
  d.speeds = speeds;
  d.lines = lines;
  ModalOptions candidates = options;
  candidates.modes = 2 * options.modes;
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    std::vector<RotorMode> found = modalAnalysis(model, speeds[i], candidates);
    if (i == 0) {
      if (static_cast<int>(found.size()) > options.modes) found.resize(options.modes);
      d.modes.push_back(std::move(found));
      continue;
    }
    std::vector<RotorMode> tracked = detail::trackByMac(d.modes.back(), found);
    d.modes.push_back(std::move(tracked));
  }
  for (const OrderLine& line : lines) {
    detail::findCrossings(
        d.speeds, d.modes, line.order / kTwoPi,
        [&](std::size_t j, std::size_t i, double speed, double f, double s) {
          d.critical_speeds.push_back({static_cast<int>(j), line.name, speed, f,
                                       (s < 0.5 ? d.modes[i - 1][j] : d.modes[i][j]).whirl});
        });
  }
  std::sort(d.critical_speeds.begin(), d.critical_speeds.end(),
            [](const CriticalSpeed& a, const CriticalSpeed& b) { return a.speed < b.speed; });
  return d;
}

}  // namespace geardyn

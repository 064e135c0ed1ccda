/// Modal analysis and Campbell diagram of a gear train (train_modal.h).

#include "geardyn/solvers/train_modal.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include "geardyn/error.h"
#include "geardyn/solvers/detail/damped_modes.h"
#include "geardyn/solvers/detail/mode_tracking.h"
#include "geardyn/system/detail/train_building.h"

namespace geardyn {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

/// Energy fractions and the planetary mode type (Lin & Parker 1999: rotational modes move the
/// central members without translating them, translational modes without rotating them,
/// planet modes not at all).
void describe(const GearTrainModel& model, TrainMode& mode) {
  // Kinetic energy per DOF, Re(x̄_i (M x)_i) (M is not diagonal with beam elements); a body's
  // rotation is its θ_x, everything else (translations, tilts) counts as translation.
  const Eigen::VectorXcd Mx = model.mass().cast<std::complex<double>>() * mode.shape;
  const Eigen::VectorXd kinetic = (mode.shape.conjugate().array() * Mx.array()).real();
  const int per = model.dofsPerBody();
  const auto& bodies = model.bodies();
  std::vector<double> rot(bodies.size(), 0.0), trans(bodies.size(), 0.0);
  double total = 0.0;
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const int r = model.rotationDof(static_cast<int>(b));
    for (int d = bodies[b].first_dof; d < bodies[b].first_dof + per; ++d) {
      (d == r ? rot[b] : trans[b]) += kinetic(d);
    }
    total += rot[b] + trans[b];
  }
  double translational = 0.0;
  mode.body_kinetic_energy.resize(bodies.size());
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    mode.body_kinetic_energy[b] = (rot[b] + trans[b]) / total;
    translational += trans[b] / total;
  }
  mode.translational_fraction = translational;

  // Strain energy of the real part of the shape (for real modes, the mode itself).
  const Eigen::VectorXd x = mode.shape.real();
  const Eigen::VectorXd y = mode.shape.imag();
  auto energy = [&](const std::vector<int>& dofs, const Eigen::MatrixXd& k) {
    Eigen::VectorXd a(dofs.size()), b(dofs.size());
    for (std::size_t i = 0; i < dofs.size(); ++i) a(i) = x(dofs[i]), b(i) = y(dofs[i]);
    return 0.5 * (a.dot(k * a) + b.dot(k * b));
  };
  double strain = 0.0;
  mode.mesh_strain_energy.clear();
  for (const TrainMesh& m : model.meshes()) {
    const Eigen::Map<const Eigen::VectorXd> v(m.gradient.data(), m.gradient.size());
    mode.mesh_strain_energy.push_back(energy(m.dofs, m.mean_stiffness * v * v.transpose()));
    strain += mode.mesh_strain_energy.back();
  }
  mode.element_strain_energy.clear();
  for (const TrainElement& e : model.elements()) {
    mode.element_strain_energy.push_back(energy(e.dofs, e.stiffness));
    strain += mode.element_strain_energy.back();
  }
  for (double& e : mode.mesh_strain_energy) e = strain > 0 ? e / strain : 0.0;
  for (double& e : mode.element_strain_energy) e = strain > 0 ? e / strain : 0.0;

  mode.stage_type.clear();
  const auto& spec = model.spec();
  for (std::size_t s = 0; s < spec.stages.size(); ++s) {
    const auto& st = spec.stages[s];
    const std::string key = "planetary." + st.name;
    double central_rot = 0.0, central_trans = 0.0;
    for (const std::string& name :
         {st.carrier, spec.gears[detail::gearIndexOf(spec, st.sun, key)].shaft,
          spec.gears[detail::gearIndexOf(spec, st.ring, key)].shaft}) {
      const int b = model.bodyIndex(name);
      central_rot += rot[b] / total;
      central_trans += trans[b] / total;
    }
    // Thresholds: the exact structure gives round-off (~1e-20 of the energy); 1e-8 leaves
    // room for the near-degenerate mixing of a solver without being fooled by real coupling.
    constexpr double kZero = 1e-8;
    double planets = 0.0;
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      if (bodies[b].kind == TrainBodyKind::kPlanet && bodies[b].stage == static_cast<int>(s))
        planets += (rot[b] + trans[b]) / total;
    }
    if (central_rot + central_trans + planets < kZero) {
      mode.stage_type.push_back("outside");  // a mode of the rest of the train
    } else if (central_rot + central_trans < kZero) {
      mode.stage_type.push_back("planet");
    } else if (per == 1 || central_trans < kZero) {
      mode.stage_type.push_back("rotational");
    } else if (central_rot < kZero) {
      mode.stage_type.push_back("translational");
    } else {
      mode.stage_type.push_back("mixed");
    }
  }
}

}  // namespace

void TrainModalOptions::validate() const {
  if (modes < 0) throw InputError("modal.modes", std::to_string(modes), "an integer >= 0");
  if (!std::isfinite(rigid_frequency)) {
    throw InputError("modal.rigid_frequency", fmt::format("{:g} Hz", rigid_frequency),
                     "a finite frequency (< 0: derived)");
  }
}

std::vector<TrainMode> trainModes(const GearTrainModel& model, double input_speed,
                                  const TrainModalOptions& options) {
  options.validate();
  const Eigen::MatrixXd K = model.meanStiffnessAt(input_speed);
  const Eigen::MatrixXd D = model.dampingAt(input_speed);
  const Eigen::MatrixXd& M = model.mass();
  std::vector<TrainMode> modes;
  const bool undamped = D.cwiseAbs().maxCoeff() == 0.0;
  if (undamped) {
    // Undamped, no Coriolis: the symmetric problem gives exact real modes (multiplicities to
    // round-off) and keeps the rigid-body modes.
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(
        0.5 * (K + K.transpose()), M);
    if (solver.info() != Eigen::Success) {
      throw std::runtime_error("modal analysis: the eigenvalue solver did not converge");
    }
    for (Eigen::Index j = 0; j < K.rows(); ++j) {
      TrainMode mode;
      const double w2 = solver.eigenvalues()(j);
      const double w = std::sqrt(std::max(w2, 0.0));
      mode.eigenvalue = {0.0, w};
      mode.frequency = w / kTwoPi;
      mode.shape = solver.eigenvectors().col(j).cast<std::complex<double>>();
      Eigen::Index largest = 0;
      mode.shape.cwiseAbs().maxCoeff(&largest);
      mode.shape /= mode.shape(largest);
      modes.push_back(std::move(mode));
    }
  } else {
    for (detail::DampedMode& found : detail::dampedModes(M, D, K)) {
      TrainMode mode;
      mode.eigenvalue = found.eigenvalue;
      mode.frequency = found.eigenvalue.imag() / kTwoPi;
      mode.damping_ratio = -found.eigenvalue.real() / std::abs(found.eigenvalue);
      mode.shape = std::move(found.shape);
      modes.push_back(std::move(mode));
    }
  }
  std::sort(modes.begin(), modes.end(),
            [](const TrainMode& a, const TrainMode& b) { return a.frequency < b.frequency; });
  const double highest = modes.empty() ? 0.0 : modes.back().frequency;
  const double rigid = options.rigid_frequency >= 0 ? options.rigid_frequency : 1e-6 * highest;
  std::vector<TrainMode> kept;
  for (TrainMode& mode : modes) {
    const bool is_rigid = std::abs(mode.eigenvalue) / kTwoPi < rigid;
    if (is_rigid) {
      // The damped eigensolver returns a rigid-body pair at λ ≈ 0 with either sign of Im λ:
      // only the symmetric path reports them, deterministically.
      if (!options.keep_rigid || !undamped) continue;
      mode.frequency = 0.0;
    }
    kept.push_back(std::move(mode));
  }
  for (std::size_t i = 0; i < kept.size(); ++i) {
    int count = 0;
    for (const TrainMode& other : kept) {
      if (std::abs(other.frequency - kept[i].frequency) <=
          1e-6 * std::max(kept[i].frequency, rigid)) {
        ++count;
      }
    }
    kept[i].multiplicity = count;
  }
  if (options.modes > 0 && static_cast<int>(kept.size()) > options.modes) {
    kept.resize(options.modes);
  }
  for (TrainMode& mode : kept) describe(model, mode);
  return kept;
}

std::vector<TrainOrderLine> trainOrderLines(const GearTrainModel& model, int mesh_harmonics) {
  std::vector<TrainOrderLine> lines;
  auto add = [&](std::string name, double slope) {
    if (!(slope > 0.0)) return;
    for (const auto& l : lines) {
      if (std::abs(l.slope - slope) <= 1e-9 * slope) return;
    }
    lines.push_back({std::move(name), slope});
  };
  for (const TrainBody& b : model.bodies()) {
    if (b.kind == TrainBodyKind::kPlanet && b.planet > 0) continue;
    add(fmt::format("1x {}", b.kind == TrainBodyKind::kPlanet
                                 ? model.spec().stages[b.stage].name + " planets"
                                 : b.name),
        std::abs(b.speed_ratio) / kTwoPi);
  }
  for (int h = 1; h <= mesh_harmonics; ++h) {
    for (const TrainMesh& m : model.meshes()) {
      const std::string name = m.stage >= 0 ? model.spec().stages[m.stage].name : m.name;
      add(h == 1 ? "mesh " + name : fmt::format("{}x mesh {}", h, name), h * m.frequency_ratio);
    }
  }
  return lines;
}

TrainCampbell trainCampbell(const GearTrainModel& model, const std::vector<double>& speeds,
                            const TrainModalOptions& options,
                            const std::vector<TrainOrderLine>& lines) {
  if (speeds.size() < 2) throw InputError("campbell.speeds", "", "at least two speeds");
  for (std::size_t i = 1; i < speeds.size(); ++i) {
    if (!(speeds[i] > speeds[i - 1])) {
      throw InputError("campbell.speeds", fmt::format("{:g} rad/s", speeds[i]), "ascending speeds");
    }
  }
  TrainCampbell d;
  d.speeds = speeds;
  d.lines = lines;
  TrainModalOptions candidates = options;
  candidates.keep_rigid = false;
  const int wanted = options.modes > 0 ? options.modes : model.dofCount();
  candidates.modes = std::min(2 * wanted, model.dofCount());
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    std::vector<TrainMode> found = trainModes(model, speeds[i], candidates);
    if (i == 0) {
      if (static_cast<int>(found.size()) > wanted) found.resize(wanted);
      d.modes.push_back(std::move(found));
    } else {
      d.modes.push_back(detail::trackByMac(d.modes.back(), found));
    }
  }
  for (const TrainOrderLine& line : lines) {
    detail::findCrossings(d.speeds, d.modes, line.slope,
                          [&](std::size_t j, std::size_t, double speed, double f, double) {
                            d.critical_speeds.push_back({static_cast<int>(j), line.name, speed, f});
                          });
  }
  std::sort(
      d.critical_speeds.begin(), d.critical_speeds.end(),
      [](const TrainCriticalSpeed& a, const TrainCriticalSpeed& b) { return a.speed < b.speed; });
  return d;
}

}  // namespace geardyn

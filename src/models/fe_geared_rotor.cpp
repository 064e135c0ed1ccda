/// Assembly of the finite-element two-shaft geared rotor (Visnadi 2021 eq. 10).

#include "geardyn/models/fe_geared_rotor.h"

#include <fmt/format.h>

#include <cmath>

#include "geardyn/error.h"
#include "geardyn/stiffness/mesh_stiffness_summary.h"

namespace geardyn {
namespace {

constexpr double kTwoPi = 6.283185307179586;
constexpr const char* kDofNames[kNodeDofs] = {"ux", "uy", "uz", "rx", "ry", "rz"};

void requireNode(int node, const FeShaftSpec& shaft, const std::string& key) {
  if (node < 0 || node >= shaft.nodeCount()) {
    throw InputError(
        key, std::to_string(node),
        fmt::format("a node index in [0, {}] of {}", shaft.nodeCount() - 1, shaft.name));
  }
}

void requireFiniteNonNegative(double value, const std::string& key, bool allow_negative = false) {
  if (!std::isfinite(value) || (!allow_negative && value < 0.0)) {
    throw InputError(key, fmt::format("{:g}", value),
                     allow_negative ? "a finite number" : "a finite number >= 0");
  }
}

/// The full-DOF matrices the constructor assembles before keeping the active DOFs.
struct FullMatrices {
  Eigen::MatrixXd M, K, C, G, Ks;  ///< mass, supports' stiffness, damping, gyroscopic, shafts'
  Eigen::VectorXd F;               ///< constant loads
};

/// One shaft's Timoshenko elements (stiffness, mass, gyroscopic at `spin` × the pinion speed) and
/// the consistent load of their weight ρ A g along −z; `offset` is its first full DOF.
void addShaftElements(const FeShaftSpec& shaft, int offset, double spin, double gravity,
                      FullMatrices& m) {
  for (std::size_t e = 0; e < shaft.elements.size(); ++e) {
    const int first = offset + static_cast<int>(e) * kNodeDofs;
    const ShaftSegment& seg = shaft.elements[e];
    const ElementMatrix ke = shaftElementStiffness(seg), me = shaftElementMass(seg);
    m.Ks.block<2 * kNodeDofs, 2 * kNodeDofs>(first, first) += ke;
    m.M.block<2 * kNodeDofs, 2 * kNodeDofs>(first, first) += me;
    m.G.block<2 * kNodeDofs, 2 * kNodeDofs>(first, first) += spin * shaftElementGyroscopic(seg);
    const double w = seg.density * seg.area() * seg.length * gravity;
    m.F(first + kUz) -= w / 2;
    m.F(first + kNodeDofs + kUz) -= w / 2;
    m.F(first + kRy) += w * seg.length / 12;  // −z load: end moments ∓ wL/12 about y
    m.F(first + kNodeDofs + kRy) -= w * seg.length / 12;
  }
}

/// One shaft's rigid disks: mass and inertia, gyroscopic coupling, weight.
void addDisks(const FeShaftSpec& shaft, int offset, double spin, double gravity, FullMatrices& m) {
  for (std::size_t i = 0; i < shaft.disks.size(); ++i) {
    const FeDisk& d = shaft.disks[i];
    const std::string key = fmt::format("{}.disks[{}]", shaft.name, i);
    requireNode(d.node, shaft, key + ".node");
    requireFiniteNonNegative(d.mass, key + ".mass");
    requireFiniteNonNegative(d.polar_inertia, key + ".polar_inertia");
    requireFiniteNonNegative(d.diametral_inertia, key + ".diametral_inertia");
    const int n = offset + d.node * kNodeDofs;
    for (int t : {kUx, kUy, kUz}) m.M(n + t, n + t) += d.mass;
    m.M(n + kRx, n + kRx) += d.polar_inertia;
    m.M(n + kRy, n + kRy) += d.diametral_inertia;
    m.M(n + kRz, n + kRz) += d.diametral_inertia;
    m.G(n + kRy, n + kRz) += spin * d.polar_inertia;
    m.G(n + kRz, n + kRy) -= spin * d.polar_inertia;
    m.F(n + kUz) -= d.mass * gravity;
  }
}

/// One shaft's bearings to ground: translational (with the y-z cross terms), tilt and torsion
/// springs and dampers.
void addBearings(const FeShaftSpec& shaft, int offset, FullMatrices& m) {
  for (std::size_t i = 0; i < shaft.bearings.size(); ++i) {
    const FeBearing& b = shaft.bearings[i];
    const std::string key = fmt::format("{}.bearings[{}]", shaft.name, i);
    requireNode(b.node, shaft, key + ".node");
    for (double k :
         {b.kxx, b.kyy, b.kzz, b.cxx, b.cyy, b.czz, b.k_tilt, b.c_tilt, b.k_torsion, b.c_torsion})
      requireFiniteNonNegative(k, key);
    for (double k : {b.kyz, b.kzy, b.cyz, b.czy}) requireFiniteNonNegative(k, key, true);
    const int n = offset + b.node * kNodeDofs;
    Eigen::MatrixXd &K = m.K, &C = m.C;
    K(n + kUx, n + kUx) += b.kxx;
    K(n + kUy, n + kUy) += b.kyy;
    K(n + kUz, n + kUz) += b.kzz;
    K(n + kUy, n + kUz) += b.kyz;
    K(n + kUz, n + kUy) += b.kzy;
    C(n + kUx, n + kUx) += b.cxx;
    C(n + kUy, n + kUy) += b.cyy;
    C(n + kUz, n + kUz) += b.czz;
    C(n + kUy, n + kUz) += b.cyz;
    C(n + kUz, n + kUy) += b.czy;
    K(n + kRy, n + kRy) += b.k_tilt;
    K(n + kRz, n + kRz) += b.k_tilt;
    C(n + kRy, n + kRy) += b.c_tilt;
    C(n + kRz, n + kRz) += b.c_tilt;
    K(n + kRx, n + kRx) += b.k_torsion;
    C(n + kRx, n + kRx) += b.c_torsion;
  }
}

}  // namespace

double SpeedProfile::speed(double t) const {
  if (t <= ramp_start || ramp_end <= ramp_start) return t <= ramp_start ? start : end;
  if (t >= ramp_end) return end;
  return start + (end - start) * (t - ramp_start) / (ramp_end - ramp_start);
}

double SpeedProfile::acceleration(double t) const {
  if (ramp_end <= ramp_start || t <= ramp_start || t >= ramp_end) return 0.0;
  return (end - start) / (ramp_end - ramp_start);
}

double SpeedProfile::angle(double t) const {
  if (t <= ramp_start || ramp_end <= ramp_start) {
    return t <= ramp_start ? start * t : start * ramp_start + end * (t - ramp_start);
  }
  const double ramp = std::min(t, ramp_end) - ramp_start;
  const double rate = (end - start) / (ramp_end - ramp_start);
  double angle = start * ramp_start + start * ramp + 0.5 * rate * ramp * ramp;
  if (t > ramp_end) angle += end * (t - ramp_end);
  return angle;
}

double SpeedProfile::maxSpeed() const {
  return std::max(std::abs(start), std::abs(end));
}

FeGearedRotor::FeGearedRotor(FeGearedRotorSpec spec) : spec_(std::move(spec)) {
  if (!spec_.mesh_stiffness) throw InputError("mesh.stiffness", "", "a mesh-stiffness model");
  if (spec_.pinion_teeth < 1 || spec_.gear_teeth < 1) {
    throw InputError("pinion.teeth", std::to_string(spec_.pinion_teeth), "tooth counts >= 1");
  }
  const MeshCouplingGeometry& g = spec_.mesh;
  if (!(g.pinion_base_radius > 0.0) || !(g.gear_base_radius > 0.0)) {
    throw InputError("mesh.base_radius", fmt::format("{:g}", g.pinion_base_radius),
                     "base radii > 0 m");
  }
  for (auto [value, key] :
       {std::pair{spec_.mesh_damping, "mesh.damping"},
        std::pair{spec_.mass_proportional, "damping.mass_proportional"},
        std::pair{spec_.stiffness_proportional, "damping.stiffness_proportional"},
        std::pair{spec_.gravity, "load.gravity"}}) {
    requireFiniteNonNegative(value, key);
  }
  requireFiniteNonNegative(spec_.drive_torque, "load.torque", true);

  // --- DOF numbering: shaft 0 nodes, then shaft 1 nodes; six DOFs each, axial removed unless
  // the model keeps it.
  int full = 0;
  for (int s = 0; s < 2; ++s) {
    const FeShaftSpec& shaft = spec_.shafts[s];
    if (shaft.elements.empty()) {
      throw InputError(shaft.name + ".element_lengths", "[]", "at least one shaft element");
    }
    for (std::size_t e = 0; e < shaft.elements.size(); ++e) {
      shaft.elements[e].validate(fmt::format("{}.element[{}]", shaft.name, e));
    }
    requireNode(shaft.gear_node, shaft, shaft.name + ".gear_node");
    node_offset_[s] = full;
    for (int n = 0; n < shaft.nodeCount(); ++n) {
      for (int d = 0; d < kNodeDofs; ++d, ++full) {
        if (d == kUx && !spec_.axial) {
          full_to_active_.push_back(-1);
          continue;
        }
        full_to_active_.push_back(static_cast<int>(active_.size()));
        active_.push_back(full);
        dof_shaft_.push_back(s);
        dof_node_.push_back(n);
        dof_type_.push_back(d);
      }
    }
  }
  requireNode(spec_.drive_node, spec_.shafts[0], "load.drive_node");
  requireNode(spec_.load_node, spec_.shafts[1], "load.load_node");

  // --- Assemble on the full DOF set, then keep the active rows and columns.
  FullMatrices m{Eigen::MatrixXd::Zero(full, full), Eigen::MatrixXd::Zero(full, full),
                 Eigen::MatrixXd::Zero(full, full), Eigen::MatrixXd::Zero(full, full),
                 Eigen::MatrixXd::Zero(full, full), Eigen::VectorXd::Zero(full)};
  auto at = [&](int s, int node, int dof) { return node_offset_[s] + node * kNodeDofs + dof; };
  for (int s = 0; s < 2; ++s) {
    const FeShaftSpec& shaft = spec_.shafts[s];
    addShaftElements(shaft, node_offset_[s], spinRatio(s), spec_.gravity, m);
    addDisks(shaft, node_offset_[s], spinRatio(s), spec_.gravity, m);
    addBearings(shaft, node_offset_[s], m);
    for (std::size_t i = 0; i < shaft.unbalances.size(); ++i) {
      const FeUnbalance& u = shaft.unbalances[i];
      const std::string key = fmt::format("{}.unbalance[{}]", shaft.name, i);
      requireNode(u.node, shaft, key + ".node");
      requireFiniteNonNegative(u.amount, key + ".amount");
      requireFiniteNonNegative(u.phase, key + ".phase", true);
      const int n = at(s, u.node, 0);
      unbalance_dofs_.push_back({n + kUy, n + kUz, s, u.amount, u.phase});
    }
  }
  if (spec_.axial) {
    for (int s = 0; s < 2; ++s) {
      double axial = 0.0;
      for (const FeBearing& b : spec_.shafts[s].bearings) axial += b.kxx;
      if (!(axial > 0.0)) {
        throw InputError(spec_.shafts[s].name + ".bearings.k_axial", "0",
                         "an axial stiffness > 0 on at least one bearing when model.axial = true "
                         "(otherwise the shaft floats axially)");
      }
    }
  }
  // Torques: T on the pinion shaft about +x, T r_bg/r_bp on the gear shaft about +x (the
  // gear turns about −x; the mesh force's moment on it is −T r_bg/r_bp).
  m.F(at(0, spec_.drive_node, kRx)) += spec_.drive_torque;
  m.F(at(1, spec_.load_node, kRx)) +=
      spec_.drive_torque * g.gear_base_radius / g.pinion_base_radius;

  // Mesh coupling between the gear nodes.
  const MeshVector vm = meshDeflectionGradient(g);
  Eigen::VectorXd v_full = Eigen::VectorXd::Zero(full);
  v_full.segment<kNodeDofs>(at(0, spec_.shafts[0].gear_node, 0)) = vm.head<kNodeDofs>();
  v_full.segment<kNodeDofs>(at(1, spec_.shafts[1].gear_node, 0)) = vm.tail<kNodeDofs>();
  m.C += spec_.mesh_damping * v_full * v_full.transpose();

  m.K += m.Ks;
  m.C += spec_.mass_proportional * m.M + spec_.stiffness_proportional * m.Ks;
  const int n = dofCount();
  M_.resize(n, n);
  K_.resize(n, n);
  C_.resize(n, n);
  G_.resize(n, n);
  v_.resize(n);
  F0_.resize(n);
  for (int i = 0; i < n; ++i) {
    v_(i) = v_full(active_[i]);
    F0_(i) = m.F(active_[i]);
    for (int j = 0; j < n; ++j) {
      M_(i, j) = m.M(active_[i], active_[j]);
      K_(i, j) = m.K(active_[i], active_[j]);
      C_(i, j) = m.C(active_[i], active_[j]);
      G_(i, j) = m.G(active_[i], active_[j]);
    }
  }
  for (auto& u : unbalance_dofs_) {
    u.y = full_to_active_[u.y];
    u.z = full_to_active_[u.z];
  }
  k_mean_ = summarizeMeshStiffness(*spec_.mesh_stiffness, 0).mean;
  if (!(k_mean_ > 0.0) || !std::isfinite(k_mean_)) {
    throw InputError("mesh.stiffness", fmt::format("{:g} N/m mean", k_mean_),
                     "a mesh stiffness with a positive mean");
  }
}

int FeGearedRotor::dofIndex(int shaft, int node, int dof) const {
  if (shaft < 0 || shaft > 1 || node < 0 || node >= spec_.shafts[shaft].nodeCount() || dof < 0 ||
      dof >= kNodeDofs)
    return -1;
  return full_to_active_[node_offset_[shaft] + node * kNodeDofs + dof];
}

std::string FeGearedRotor::dofName(int index) const {
  return fmt::format("{}.{}.{}", spec_.shafts[dof_shaft_[index]].name, dof_node_[index],
                     kDofNames[dof_type_[index]]);
}

double FeGearedRotor::meshPhase(double t) const {
  return spec_.speed.angle(t) * spec_.pinion_teeth / kTwoPi;
}

double FeGearedRotor::spinRatio(int shaft) const {
  return shaft == 0
             ? 1.0
             : -static_cast<double>(spec_.pinion_teeth) / static_cast<double>(spec_.gear_teeth);
}

double FeGearedRotor::nominalMeshForce() const {
  return spec_.drive_torque /
         (spec_.mesh.pinion_base_radius * std::cos(spec_.mesh.base_helix_angle));
}

void FeGearedRotor::addUnbalanceForce(double t, Eigen::Ref<Eigen::VectorXd> f) const {
  if (unbalance_dofs_.empty()) return;
  const double theta = spec_.speed.angle(t), omega = spec_.speed.speed(t);
  const double alpha = spec_.speed.acceleration(t);
  for (const auto& u : unbalance_dofs_) {
    // The mass at angle φ = r θ_p + φ₀ (about +x, from y towards z) pushes the shaft with
    // m e (φ̇² cos φ + φ̈ sin φ, φ̇² sin φ − φ̈ cos φ).
    const double r = spinRatio(u.shaft), phi = r * theta + u.phase;
    const double w2 = r * r * omega * omega, acc = r * alpha;
    const double c = std::cos(phi), s = std::sin(phi);
    if (u.y >= 0) f(u.y) += u.amount * (w2 * c + acc * s);
    if (u.z >= 0) f(u.z) += u.amount * (w2 * s - acc * c);
  }
}

}  // namespace geardyn

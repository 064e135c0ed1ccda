/// The FE geared rotor as its gear train with the FE rotor's numbering (fe_rotor_model.h).

#include "geardyn/system/fe_rotor_model.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geardyn/error.h"

namespace geardyn {
namespace {

constexpr const char* kDofNames[kNodeDofs] = {"ux", "uy", "uz", "rx", "ry", "rz"};
/// FE node DOF type (NodeDof) → offset in the train's node order (y, z, θ_x, x, θ_y, θ_z;
/// gear_train_model.h).
constexpr int kTrainOffset[kNodeDofs] = {3, 0, 1, 2, 4, 5};

Eigen::MatrixXd restricted(const Eigen::MatrixXd& a, const std::vector<int>& dofs) {
  const int n = static_cast<int>(dofs.size());
  Eigen::MatrixXd r(n, n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) r(i, j) = a(dofs[i], dofs[j]);
  return r;
}

void requireNode(int node, int nodes, const std::string& shaft, const std::string& key) {
  if (node < 0 || node >= nodes) {
    throw InputError(key, std::to_string(node),
                     fmt::format("a node index in [0, {}] of {}", nodes - 1, shaft));
  }
}

}  // namespace

FeRotorModel::FeRotorModel(GearTrainSpec train, FeRotorLayout layout) : layout_(std::move(layout)) {
  if (train.shafts.size() != 2 || train.meshes.size() != 1 || train.dofs != TrainDofs::kFull) {
    throw InputError("model.type", "\"fe_geared_rotor\"",
                     "two shafts, one mesh and full DOFs (the FE geared rotor's gearbox)");
  }
  train_ = std::make_unique<const GearTrainModel>(std::move(train));
  const GearTrainModel& t = *train_;
  for (int s = 0; s < 2; ++s) {
    const int nodes = nodeCount(s);
    const std::string& name = shaftName(s);
    requireNode(layout_.gear_nodes[s], nodes, name, name + ".gear_node");
    for (int node : layout_.bearing_nodes[s])
      requireNode(node, nodes, name, name + ".bearings.nodes");
    index_[s].assign(static_cast<std::size_t>(nodes) * kNodeDofs, -1);
    for (int node = 0; node < nodes; ++node) {
      const int first = t.bodies()[t.shaftNodes(s)[node]].first_dof;
      for (int d = 0; d < kNodeDofs; ++d) {
        if (d == kUx && !layout_.axial) continue;
        index_[s][node * kNodeDofs + d] = static_cast<int>(train_dofs_.size());
        train_dofs_.push_back(first + kTrainOffset[d]);
        dof_shaft_.push_back(s);
        dof_node_.push_back(node);
        dof_type_.push_back(d);
      }
    }
  }
  requireNode(layout_.drive_node, nodeCount(0), shaftName(0), "load.drive_node");
  requireNode(layout_.load_node, nodeCount(1), shaftName(1), "load.load_node");

  M_ = restricted(t.mass(), train_dofs_);
  K_ = restricted(t.stiffness(), train_dofs_);
  C_ = restricted(t.damping(), train_dofs_);
  G_ = restricted(t.gyroscopic(), train_dofs_);
  const Eigen::VectorXd v = t.meshVector(0);
  v_.resize(dofCount());
  for (int i = 0; i < dofCount(); ++i) v_(i) = v(train_dofs_[i]);

  F0_ = Eigen::VectorXd::Zero(dofCount());
  addLoads();
}

void FeRotorModel::addLoads() {
  // The train's F₀ in closed form: the torques at their nodes, and gravity as the elements'
  // consistent load (w L/2 at each end node, end moments ± w L²/12 about y for a load along −z)
  // and the disks' weight. The train's −g M e_z is the same vector to round-off (7e-15 of the
  // largest load); the closed form keeps the FE rotor's results bit-identical to its own
  // assembly's of earlier versions, which the undamped rolling mode would otherwise drift from
  // (2.6e-7 of the run-up example's order tracks).
  const GearTrainModel& t = *train_;
  const TrainMesh& mesh = t.meshes().front();
  const double torque = t.spec().operating.input_torque;
  F0_(dofIndex(0, layout_.drive_node, kRx)) += torque;
  F0_(dofIndex(1, layout_.load_node, kRx)) += torque * mesh.base_radius_b / mesh.base_radius_a;
  const double g = t.spec().gravity;
  for (int s = 0; s < 2; ++s) {
    const TrainShaftSpec& shaft = t.spec().shafts[s];
    for (int e = 0; e + 1 < nodeCount(s); ++e) {
      const double length = shaft.section_lengths[e];
      const double d_o = shaft.outer_diameters[e], d_i = shaft.inner_diameters[e];
      const double w =
          shaft.density * std::numbers::pi / 4.0 * (d_o * d_o - d_i * d_i) * length * g;
      F0_(dofIndex(s, e, kUz)) -= w / 2;
      F0_(dofIndex(s, e + 1, kUz)) -= w / 2;
      F0_(dofIndex(s, e, kRy)) += w * length / 12;
      F0_(dofIndex(s, e + 1, kRy)) -= w * length / 12;
    }
  }
  for (const TrainDiskSpec& d : t.spec().disks) {
    const int s = d.shaft == shaftName(0) ? 0 : 1;
    const std::vector<int>& nodes = t.shaftNodes(s);
    const int body = t.bodyAt(s, d.position, "disks." + d.name + ".position");
    const int node = static_cast<int>(std::find(nodes.begin(), nodes.end(), body) - nodes.begin());
    if (node == nodeCount(s)) {
      throw InputError("disks." + d.name + ".position", fmt::format("{:g} m", d.position),
                       "a node of " + shaftName(s));
    }
    F0_(dofIndex(s, node, kUz)) -= d.mass * g;
  }
}

int FeRotorModel::dofIndex(int shaft, int node, int dof) const {
  if (shaft < 0 || shaft > 1 || node < 0 || node >= nodeCount(shaft) || dof < 0 || dof >= kNodeDofs)
    return -1;
  return index_[shaft][node * kNodeDofs + dof];
}

std::string FeRotorModel::dofName(int index) const {
  return fmt::format("{}.{}.{}", shaftName(dof_shaft_[index]), dof_node_[index],
                     kDofNames[dof_type_[index]]);
}

double FeRotorModel::meshStiffness(double phase) const {
  return train_->meshes().front().stiffness->stiffness(phase);
}

double FeRotorModel::transmissionError(double phase) const {
  return train_->meshes().front().transmission_error.value(phase);
}

double FeRotorModel::meshPhase(double t) const {
  return layout_.speed.angle(t) * pinionTeeth() / (2.0 * std::numbers::pi);
}

double FeRotorModel::spinRatio(int shaft) const {
  return shaft == 0 ? 1.0 : -static_cast<double>(pinionTeeth()) / gearTeeth();
}

double FeRotorModel::nominalMeshForce() const {
  const TrainMesh& mesh = train_->meshes().front();
  return std::abs(train_->spec().operating.input_torque) /
         (mesh.base_radius_a * std::cos(mesh.base_helix_angle));
}

}  // namespace geardyn

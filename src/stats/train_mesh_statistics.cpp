#include "geardyn/stats/train_mesh_statistics.h"

#include <fmt/format.h>

#include <cmath>

#include "geardyn/error.h"

namespace geardyn {

RecordStatistics recordStatistics(const Eigen::Ref<const Eigen::VectorXd>& values) {
  RecordStatistics s;
  if (values.size() == 0) return s;
  const double n = static_cast<double>(values.size());
  s.mean = values.mean();
  s.rms = std::sqrt(values.squaredNorm() / n);
  s.std = std::sqrt((values.array() - s.mean).square().sum() / n);
  s.min = values.minCoeff();
  s.max = values.maxCoeff();
  return s;
}

GearPairModelSpec meshPairSpec(const TrainMesh& mesh, double static_force, double input_speed) {
  GearPairModelSpec spec;
  spec.mass = mesh.equivalent_mass;
  spec.damping = mesh.damping;
  spec.mean_force = static_force;
  spec.stiffness = mesh.stiffness;
  spec.mesh_frequency = mesh.frequency_ratio * std::abs(input_speed);
  spec.initial_phase = mesh.phase;
  spec.transmission_error = mesh.transmission_error;
  return spec;
}

std::vector<TrainMeshStatistics> trainMeshStatistics(const GearTrainModel& model,
                                                     double input_speed,
                                                     const TrainTimeResponse& record,
                                                     const std::vector<double>& static_force,
                                                     double baseload_scale) {
  if (!(baseload_scale > 0.0) || !std::isfinite(baseload_scale)) {
    throw InputError("stats.design_torque",
                     fmt::format("{:g} × the operating torque", baseload_scale),
                     "a design load > 0 in the operating torque's sense");
  }
  const auto& meshes = model.meshes();
  if (static_force.size() != meshes.size() ||
      record.mesh_force.cols() != static_cast<Eigen::Index>(meshes.size())) {
    throw InputError("meshes", fmt::format("{}", meshes.size()),
                     "one static force and one recorded force per mesh");
  }
  const Eigen::Index samples = record.t.size();
  std::vector<TrainMeshStatistics> out;
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    const TrainMesh& mesh = meshes[m];
    TrainMeshStatistics s;
    s.mesh = mesh.name;
    s.static_force = static_force[m];
    s.baseload = baseload_scale * static_force[m];
    Eigen::VectorXd delta(samples), k_delta(samples);
    for (Eigen::Index i = 0; i < samples; ++i) {
      delta(i) = mesh.deflection(record.displacement.row(i).transpose());
      k_delta(i) = mesh.stiffness->stiffness(mesh.phaseAt(record.t(i), input_speed)) * delta(i);
    }
    const Eigen::VectorXd force = record.mesh_force.col(static_cast<Eigen::Index>(m));
    s.force = recordStatistics(force);
    s.dte = recordStatistics(delta);
    if (s.static_force > 0.0) {
      // Gelman eqs. 5–7 on the mesh's SDOF pair (the header's generalisation).
      const GearPairModel pair(meshPairSpec(mesh, s.static_force, input_speed));
      s.excitation = meanExcitationFromModel(pair, s.baseload);
      const double peak = std::max(std::abs(s.force.max), std::abs(s.force.min));
      s.dynamic_factor = peak / s.static_force;
      const double mean_k_delta = samples > 0 ? k_delta.mean() : 0.0;
      s.simulated_dynamic_mean_excitation = mean_k_delta / s.baseload;
      s.simulated_ratio = mean_k_delta / s.static_force;
    }
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace geardyn

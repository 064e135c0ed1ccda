/// System deflection coupled with the loaded tooth contact of every mesh
/// (solvers/train_loaded_contact.h).

#include "geardyn/solvers/train_loaded_contact.h"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "geardyn/error.h"
#include "geardyn/stiffness/tabulated_stiffness.h"

namespace geardyn {

void TrainLoadedContactOptions::validate() const {
  if (slices < 1 || slices > 10000)
    throw InputError("whine.slices", std::to_string(slices), "an integer in [1, 10000]");
  if (positions < 8 || positions > 100000)
    throw InputError("whine.positions", std::to_string(positions), "an integer in [8, 100000]");
  if (harmonics < 1 || 2 * harmonics >= positions) {
    throw InputError("whine.harmonics", std::to_string(harmonics),
                     fmt::format("an integer in [1, positions/2) = [1, {})", positions / 2));
  }
  if (!(tolerance > 0.0) || !(tolerance < 1.0))
    throw InputError("whine.tolerance", fmt::format("{:g}", tolerance), "in (0, 1)");
  if (max_iterations < 1 || max_iterations > 10000) {
    throw InputError("whine.max_iterations", std::to_string(max_iterations),
                     "an integer in [1, 10000]");
  }
}

std::vector<std::shared_ptr<const LoadedToothContact>> trainMeshContacts(
    const GearTrainModel& model, int slices, const std::vector<PairModifications>& modifications) {
  std::vector<std::shared_ptr<const LoadedToothContact>> out(model.meshes().size());
  for (std::size_t i = 0; i < model.meshes().size(); ++i) {
    const TrainMesh& m = model.meshes()[i];
    if (m.kind != TrainMeshKind::kExternal || m.gear_a < 0 || m.gear_b < 0) continue;
    GearPairSpec spec;
    spec.pinion = model.spec().gears[m.gear_a].gear;
    spec.gear = model.spec().gears[m.gear_b].gear;
    spec.centre_distance = m.centre_distance;
    const GearPair pair(spec);
    PotentialEnergyOptions pe;
    if (pair.baseHelixAngle() > 0.0) pe.slices = slices;  // the contact's slices
    auto k = std::make_shared<const PotentialEnergyMeshStiffness>(pair, pe);
    out[i] = std::make_shared<const LoadedToothContact>(
        k, i < modifications.size() ? modifications[i] : PairModifications{}, slices);
  }
  return out;
}

namespace {

/// ΔF: the couples that move each mesh force F_n from the contact point to x_c + z_c.
Eigen::VectorXd loadCouples(const GearTrainModel& model, const std::vector<double>& force,
                            const std::vector<double>& shift) {
  Eigen::VectorXd dF = Eigen::VectorXd::Zero(model.dofCount());
  if (model.dofsPerBody() != 6) return dF;
  for (std::size_t i = 0; i < model.meshes().size(); ++i) {
    if (shift[i] == 0.0) continue;
    const TrainMesh& m = model.meshes()[i];
    // The 3-D normal's transverse part cos β_b n_t (system/train_mesh_gradient.cpp); the
    // force on gear a is −F n, its moment arm grows by z x̂: ΔM_a = −F z (x̂ × n) with
    // x̂ × n = (0, −n_z, n_y) about (x, y, z).
    const double cb = std::cos(m.base_helix_angle);
    const double ny = cb * m.normal.x(), nz = cb * m.normal.y();
    const double c = force[i] * shift[i];
    for (auto [body, sign] : {std::pair{m.body_a, -1.0}, std::pair{m.body_b, 1.0}}) {
      const int d = model.bodies()[body].first_dof;
      dF(d + 4) += sign * c * (-nz);
      dF(d + 5) += sign * c * ny;
    }
  }
  return dF;
}

}  // namespace

TrainLoadedContactResult solveTrainLoadedContact(
    const GearTrainModel& model,
    const std::vector<std::shared_ptr<const LoadedToothContact>>& contacts,
    const TrainLoadedContactOptions& options) {
  options.validate();
  if (contacts.size() != model.meshes().size()) {
    throw InputError("whine", fmt::format("{} contact models", contacts.size()),
                     fmt::format("one per mesh ({})", model.meshes().size()));
  }
  TrainLoadedContactResult r;
  r.statics = solveTrainStatic(model, model.inputSpeed());
  const Eigen::VectorXd q0 = r.statics.displacement;
  const std::vector<double> force0 = r.statics.mesh_force;
  // Superposition about q₀ with the (tangent) mean stiffness, factorised once.
  const Eigen::MatrixXd K = model.rollingBearings().empty()
                                ? model.meanStiffnessAt(model.inputSpeed())
                                : model.linearisedAt(q0).meanStiffnessAt(model.inputSpeed());
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(K);
  cod.setThreshold(1e-12);

  const std::size_t n = model.meshes().size();
  std::vector<double> shift(n, 0.0), force = force0, centre(n, 0.0);
  std::vector<TrainMeshLoadedContact> state(n);
  Eigen::VectorXd q = q0;
  for (int it = 0; it < options.max_iterations; ++it) {
    const auto mis = meshMisalignment(model, q);
    double change = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      if (!contacts[i]) continue;
      const TrainMesh& m = model.meshes()[i];
      PairModifications mods = contacts[i]->modifications();
      mods.misalignment = mis.empty() ? 0.0 : mis[i].mismatch;
      const LoadedToothContact contact(contacts[i]->sharedStiffness(), mods, contacts[i]->slices());
      TrainMeshLoadedContact& s = state[i];
      s.mesh = static_cast<int>(i);
      if (!mis.empty()) s.misalignment = mis[i];
      s.force_transverse = std::abs(force[i]) * std::cos(m.base_helix_angle);
      s.face = faceLoadDistribution(contact, s.force_transverse, options.positions);
      const double b = s.face.face_width;
      change = std::max(change, std::abs(s.face.centre_of_load - centre[i]) / b);
      centre[i] = s.face.centre_of_load;
      shift[i] = mis.empty() ? 0.0 : centre[i] + s.misalignment.mid_face - s.misalignment.contact_x;
    }
    r.change.push_back(change);
    r.iterations = it + 1;
    if (change < options.tolerance && it > 0) {
      r.converged = true;
      break;
    }
    const Eigen::VectorXd dq = cod.solve(loadCouples(model, force, shift));
    q = q0 + dq;
    for (std::size_t i = 0; i < n; ++i)
      force[i] = force0[i] + model.meshes()[i].mean_stiffness * model.meshes()[i].deflection(dq);
  }
  r.statics.displacement = q;
  r.statics.mesh_force = force;
  for (std::size_t i = 0; i < n; ++i) {
    if (!contacts[i]) continue;
    TrainMeshLoadedContact& s = state[i];
    const auto& pts = s.face.points;
    const auto [lo, hi] = std::minmax_element(
        pts.begin(), pts.end(), [](const auto& a, const auto& b) { return a.ste < b.ste; });
    s.ste_peak_to_peak = hi->ste - lo->ste;
    for (const auto& p : pts) {
      s.ste_mean += p.ste / static_cast<double>(pts.size());
      s.mean_tangent_stiffness += p.tangent / static_cast<double>(pts.size());
    }
    s.ste_harmonics = steHarmonics(pts, options.harmonics);
    r.meshes.push_back(std::move(s));
  }
  return r;
}

GearTrainSpec loadedContactExcitation(const GearTrainModel& model,
                                      const TrainLoadedContactResult& r,
                                      const std::vector<bool>& meshes) {
  GearTrainSpec spec = model.spec();
  for (const TrainMeshLoadedContact& m : r.meshes) {
    if (m.mesh >= static_cast<int>(meshes.size()) || !meshes[m.mesh]) continue;
    const TrainMesh& mesh = model.meshes()[m.mesh];
    const double cb = std::cos(mesh.base_helix_angle);
    std::vector<double> phases, k, e;
    for (const auto& p : m.face.points) {
      phases.push_back(p.phase);
      k.push_back(p.tangent / (cb * cb));
      e.push_back(cb * (p.ste - m.force_transverse / p.tangent));
    }
    for (TrainMeshSpec& s : spec.meshes) {
      if (s.name != mesh.name) continue;
      s.stiffness = std::make_shared<const TabulatedMeshStiffness>(
          phases, k, mesh.stiffness ? mesh.stiffness->contactRatio() : mesh.contact_ratio,
          "loaded_contact");
      s.transmission_error = TransmissionError();
      s.transmission_error.addTable(phases, e, "meshes." + mesh.name + ".excitation");
    }
  }
  return spec;
}

}  // namespace geardyn

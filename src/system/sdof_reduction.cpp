/// The single-pair train's gear-pair model (system/sdof_reduction.h).

#include "geardyn/system/sdof_reduction.h"

#include <fmt/format.h>

#include <cmath>

#include "geardyn/error.h"
#include "geardyn/models/scaled_contact_elements.h"
#include "geardyn/stiffness/scaled_stiffness.h"

namespace geardyn {

std::string sdofReductionObstacle(const GearTrainModel& train) {
  const GearTrainSpec& spec = train.spec();
  if (spec.dofs != TrainDofs::kTorsional) {
    return fmt::format("gearbox.dofs = \"{}\": the gear-pair model has torsional DOFs only",
                       toString(spec.dofs));
  }
  if (!spec.stages.empty()) return "a planetary stage: the gear-pair model is one external pair";
  if (train.meshes().size() != 1) {
    return fmt::format("{} meshes: the gear-pair model has one", train.meshes().size());
  }
  const TrainMesh& m = train.meshes()[0];
  if (m.kind != TrainMeshKind::kExternal) {
    return fmt::format("meshes.{} is {}: the gear-pair model is one external pair", m.name,
                       toString(m.kind));
  }
  if (train.bodies().size() != 2) {
    return fmt::format("{} bodies: the gear-pair model has the two gears' rigid shafts",
                       train.bodies().size());
  }
  for (const auto& b : spec.bearings) {
    if (b.k_torsion != 0.0 || b.c_torsion != 0.0) {
      return fmt::format("bearings.{} holds a shaft in torsion: the gear-pair model has no support",
                         b.name);
    }
  }
  for (const auto& c : spec.couplings) {
    if (c.k_torsion != 0.0 || c.c_torsion != 0.0) {
      return fmt::format("couplings.{}: the gear-pair model has no coupling", c.name);
    }
  }
  if (spec.mass_proportional_damping != 0.0 || spec.stiffness_proportional_damping != 0.0) {
    return "gearbox Rayleigh damping: the gear-pair model's only damping is the mesh dashpot";
  }
  if (m.dofs.size() != 2) return fmt::format("meshes.{} couples {} DOFs", m.name, m.dofs.size());
  return "";
}

GearPairModelSpec sdofReduction(const GearTrainModel& train) {
  if (const std::string why = sdofReductionObstacle(train); !why.empty()) {
    throw InputError("gearbox", "(a gear train)",
                     "a single rigid external pair with torsional DOFs to reduce to the "
                     "gear-pair model; found " +
                         why);
  }
  const TrainMesh& m = train.meshes()[0];
  // The mesh acts along the contact normal, the gear-pair model along the transverse line of
  // action: δ_n = δ_t cos β_b, so m_t = m_n cos² β_b, k_t = k_n cos² β_b, c_t = c_n cos² β_b,
  // F_t = F_n cos β_b, e_t = e_n / cos β_b, j_t = j_n / cos β_b (docs/theory/mesh_stiffness.md,
  // "Which plane"). Spur: cos β_b = 1, nothing changes.
  const double cb = std::cos(m.base_helix_angle), cb2 = cb * cb;
  GearPairModelSpec s;
  s.mass = m.equivalent_mass * cb2;  // 1 / (r_a²/I_a + r_b²/I_b)
  s.damping = m.damping * cb2;
  // Static balance of the input shaft: T_in = F ∂δ/∂θ_in, with ∂δ/∂θ_in = ±r_b of its gear.
  const auto& shafts = train.spec().shafts;
  int input_body = 0;
  for (std::size_t i = 0; i < shafts.size(); ++i) {
    if (shafts[i].name == train.spec().operating.input_shaft) {
      input_body = train.shaftBody(static_cast<int>(i));
    }
  }
  const int input_dof = train.rotationDof(input_body);
  double lever = 0.0;
  for (std::size_t d = 0; d < m.dofs.size(); ++d) {
    if (m.dofs[d] == input_dof) lever = m.gradient[d];
  }
  s.mean_force = lever != 0.0 ? cb * train.spec().operating.input_torque / lever : 0.0;
  s.stiffness = scaledMeshStiffness(m.stiffness, cb2);
  s.mesh_frequency = m.frequency_ratio * std::abs(train.inputSpeed());
  s.initial_phase = m.phase;
  s.transmission_error = cb == 1.0 ? m.transmission_error : m.transmission_error.scaled(1.0 / cb);
  if (m.contact.tooth_pairs) {
    s.contact = ContactLaw::kOneSided;
    s.contact_elements = scaledContactElements(m.contact.tooth_pairs, cb2, 1.0 / cb);
  } else {
    s.contact = m.contact.law;
    // Full normal clearance j (free play −j ≤ δ − e ≤ 0) → the SDOF half clearance b = j / 2.
    s.backlash = m.contact.law == ContactLaw::kBacklash ? 0.5 * m.contact.backlash / cb : 0.0;
  }
  return s;
}

}  // namespace geardyn

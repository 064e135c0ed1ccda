/// Unbalances, gear runouts and prescribed bearing displacements as harmonic forces
/// (train_excitation.h).

#include "geardyn/system/train_excitation.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "geardyn/error.h"
#include "geardyn/system/detail/train_building.h"
#include "geardyn/system/gear_train_model.h"

namespace geardyn {
namespace {

using Complex = std::complex<double>;
constexpr Complex kJ(0.0, 1.0);
constexpr double kTwoPi = 2.0 * std::numbers::pi;

void requireFinite(double value, const std::string& key, const std::string& range) {
  if (!std::isfinite(value)) throw InputError(key, fmt::format("{:g}", value), range);
}

void requireLateral(const GearTrainModel& model, const std::string& key) {
  if (model.spec().dofs == TrainDofs::kTorsional) {
    throw InputError("gearbox.dofs", "\"torsional\"",
                     fmt::format("\"planar\" or \"full\" for {}: a torsional train has no "
                                 "lateral displacements to excite",
                                 key));
  }
}

void requireFixedFrame(const GearTrainModel& model, int body, const std::string& key) {
  if (model.rotatingFrame(body) >= 0) {
    throw InputError(key, model.bodies()[body].name,
                     "a body in the fixed frame (this one is formulated in a rotating carrier "
                     "frame; set the stage's carrier_frame_terms = false)");
  }
}

/// A term over the DOFs of the point Jacobian (J: 2 × dofs), with the in-plane complex vectors
/// s, d, u (y, z) mapped by Jᵀ.
TrainExcitationTerm pointTerm(std::string name, double ratio, bool follows,
                              const detail::PointJacobian& p, const Eigen::Vector2cd& s,
                              const Eigen::Vector2cd& d, const Eigen::Vector2cd& u) {
  TrainExcitationTerm t;
  t.name = std::move(name);
  t.ratio = ratio;
  t.follows_direction = follows;
  t.dofs = p.dofs;
  const Eigen::MatrixXcd Jt = p.J.transpose().cast<Complex>();
  t.stiffness = Jt * s;
  t.damping = Jt * d;
  t.inertia = Jt * u;
  return t;
}

void addUnbalances(const GearTrainModel& model, std::vector<TrainExcitationTerm>& terms) {
  for (const TrainUnbalanceSpec& u : model.spec().unbalances) {
    const std::string key = "unbalances." + u.name;
    requireLateral(model, key);
    if (!(u.mass_eccentricity >= 0.0) || !std::isfinite(u.mass_eccentricity)) {
      throw InputError(key + ".mass_eccentricity", fmt::format("{:g} kg m", u.mass_eccentricity),
                       "a finite m e >= 0 kg m");
    }
    requireFinite(u.phase, key + ".phase_deg", "a finite angle [deg]");
    const int shaft = detail::shaftIndexOf(model.spec(), u.shaft, key + ".shaft");
    const int body = model.bodyAt(shaft, u.position, key + ".position");
    requireFixedFrame(model, body, key + ".shaft");
    const double dx = model.axialOffsetOf(body, shaft, u.position);
    // m e (cos ψ, sin ψ) = Re[m e e^{iψ₀} (1, −i) e^{i(ψ − ψ₀)}].
    const Complex me = u.mass_eccentricity * std::polar(1.0, u.phase);
    terms.push_back(pointTerm(key, model.bodies()[body].speed_ratio, true,
                              detail::translationJacobian(model, body, 1.0, dx),
                              Eigen::Vector2cd::Zero(), Eigen::Vector2cd::Zero(),
                              Eigen::Vector2cd(me, -kJ * me)));
  }
}

void addRunouts(const GearTrainModel& model, std::vector<TrainExcitationTerm>& terms) {
  for (const TrainRunoutSpec& r : model.spec().runouts) {
    const std::string key = "runouts." + r.name;
    requireLateral(model, key);
    if (!(r.amplitude >= 0.0) || !std::isfinite(r.amplitude)) {
      throw InputError(key + ".amplitude", fmt::format("{:g} m", r.amplitude),
                       "a finite runout >= 0 m");
    }
    requireFinite(r.phase, key + ".phase_deg", "a finite angle [deg]");
    const int gear = detail::gearIndexOf(model.spec(), r.gear, key + ".gear");
    int found = 0;
    for (std::size_t m = 0; m < model.meshes().size(); ++m) {
      const TrainMesh& mesh = model.meshes()[m];
      if (mesh.gear_a != gear && mesh.gear_b != gear) continue;
      const int body = mesh.gear_a == gear ? mesh.body_a : mesh.body_b;
      requireFixedFrame(model, body, key + ".gear");
      ++found;
      // v_gᵀ W with W = a e^{iϕ} (1, −i): the runout's part of the mesh deflection.
      const Eigen::VectorXd v = model.meshVector(static_cast<int>(m));
      const int y = model.translationDof(body);
      const Complex vw = r.amplitude * std::polar(1.0, r.phase) * Complex(v(y), -v(y + 1));
      TrainExcitationTerm t;
      t.name = key + "@" + mesh.name;
      t.ratio = model.bodies()[body].speed_ratio;
      t.follows_direction = true;
      t.mesh = static_cast<int>(m);
      for (std::size_t i = 0; i < mesh.dofs.size(); ++i) t.dofs.push_back(mesh.dofs[i]);
      t.stiffness.resize(static_cast<Eigen::Index>(t.dofs.size()));
      // The mesh's restoring force −v k (vᵀq + v_gᵀw − e): the load −v k v_gᵀ w (and c ẇ).
      for (std::size_t i = 0; i < mesh.dofs.size(); ++i) t.stiffness(i) = -mesh.gradient[i] * vw;
      t.damping = mesh.damping * t.stiffness;
      t.inertia = Eigen::VectorXcd::Zero(t.stiffness.size());
      terms.push_back(std::move(t));
    }
    if (found == 0) {
      throw InputError(key + ".gear", "\"" + r.gear + "\"",
                       "a gear with a fixed-axis mesh (a runout excites its meshes)");
    }
  }
}

/// The reference's order scale ν per unit order and its phase per unit order at t = 0 [rad].
std::pair<double, double> referenceOf(const GearTrainModel& model, const std::string& name,
                                      const std::string& key) {
  for (const TrainMesh& m : model.meshes()) {
    if (m.name == name) return {kTwoPi * m.frequency_ratio, kTwoPi * m.phase};
  }
  for (std::size_t s = 0; s < model.spec().shafts.size(); ++s) {
    if (model.spec().shafts[s].name != name) continue;
    const double r = std::abs(model.bodies()[model.shaftBody(static_cast<int>(s))].speed_ratio);
    if (!(r > 0.0)) {
      throw InputError(key, "\"" + name + "\"", "a turning shaft or a mesh (this shaft is held)");
    }
    return {r, 0.0};
  }
  throw InputError(key, "\"" + name + "\"", "the name of a shaft or a mesh of the gearbox");
}

void addBearingExcitations(const GearTrainModel& model, Eigen::VectorXd& static_load,
                           std::vector<TrainExcitationTerm>& terms) {
  const GearTrainSpec& spec = model.spec();
  for (const TrainBearingExcitationSpec& e : spec.bearing_excitations) {
    const std::string key = "bearing_excitations." + e.name;
    requireLateral(model, key);
    const TrainBearingSpec* bearing = nullptr;
    for (const auto& b : spec.bearings) bearing = b.name == e.bearing ? &b : bearing;
    const TrainElement* element = nullptr;
    for (const auto& el : model.elements())
      element = el.name == e.bearing && el.kind == "bearing" ? &el : element;
    if (!bearing || bearing->rolling || bearing->stiffness_matrix || !element) {
      throw InputError(key + ".bearing", "\"" + e.bearing + "\"",
                       "a linear bearing of the gearbox with lateral stiffness or damping "
                       "(kyy, kzz, cyy, czz; not one from its geometry)");
    }
    const int shaft = detail::shaftIndexOf(spec, bearing->shaft, key + ".bearing");
    requireFixedFrame(model, model.bodyAt(shaft, bearing->position, key + ".bearing"),
                      key + ".bearing");
    Eigen::Matrix2d kb, cb;
    kb << bearing->kyy, bearing->kyz, bearing->kzy, bearing->kzz;
    cb << bearing->cyy, bearing->cyz, bearing->czy, bearing->czz;
    cb += spec.stiffness_proportional_damping * kb;  // the Rayleigh β K_b acts on ḋ too
    const Eigen::MatrixXd& J = element->jacobian;
    requireFinite(e.mean_y, key + ".mean_y", "a finite displacement [m]");
    requireFinite(e.mean_z, key + ".mean_z", "a finite displacement [m]");
    const Eigen::VectorXd mean = J.transpose() * (kb * Eigen::Vector2d(e.mean_y, e.mean_z));
    for (std::size_t i = 0; i < element->dofs.size(); ++i) static_load(element->dofs[i]) += mean(i);
    const std::size_t n = e.orders.size();
    for (const auto& [list, name] : {std::pair{&e.amplitude_y, "amplitude_y"},
                                     {&e.phase_y, "phase_y_deg"},
                                     {&e.amplitude_z, "amplitude_z"},
                                     {&e.phase_z, "phase_z_deg"}}) {
      if (list->size() != n) {
        throw InputError(key + "." + name, fmt::format("{} values", list->size()),
                         fmt::format("one per order ({} in {}.orders)", n, key));
      }
    }
    if (n == 0) continue;
    const auto [scale, phase0] = referenceOf(model, e.reference, key + ".reference");
    for (std::size_t i = 0; i < n; ++i) {
      const double k = e.orders[i];
      if (!(k > 0.0) || !std::isfinite(k)) {
        throw InputError(key + ".orders", fmt::format("{:g}", k), "orders > 0 (finite)");
      }
      for (const auto& [a, name] :
           {std::pair{e.amplitude_y[i], ".amplitude_y"}, {e.amplitude_z[i], ".amplitude_z"}}) {
        if (!(a >= 0.0) || !std::isfinite(a)) {
          throw InputError(key + name, fmt::format("{:g} m", a), "finite amplitudes >= 0 m");
        }
      }
      requireFinite(e.phase_y[i], key + ".phase_y_deg", "finite angles [deg]");
      requireFinite(e.phase_z[i], key + ".phase_z_deg", "finite angles [deg]");
      const Eigen::Vector2cd delta(e.amplitude_y[i] * std::polar(1.0, e.phase_y[i] + k * phase0),
                                   e.amplitude_z[i] * std::polar(1.0, e.phase_z[i] + k * phase0));
      TrainExcitationTerm t;
      t.name = fmt::format("{}.order_{:g}", key, k);
      t.ratio = k * scale;
      t.dofs = element->dofs;
      const Eigen::MatrixXcd Jt = J.transpose().cast<Complex>();
      t.stiffness = Jt * (kb.cast<Complex>() * delta);
      t.damping = Jt * (cb.cast<Complex>() * delta);
      t.inertia = Eigen::VectorXcd::Zero(t.stiffness.size());
      terms.push_back(std::move(t));
    }
  }
}

}  // namespace

Eigen::VectorXcd TrainExcitationTerm::amplitude(double input_speed, double mesh_stiffness) const {
  const double rate = order(input_speed) * std::abs(input_speed);  // ψ̇
  return (mesh >= 0 ? mesh_stiffness : 1.0) * stiffness + Complex(0.0, rate) * damping +
         rate * rate * inertia;
}

std::vector<TrainExcitationTerm> buildTrainExcitation(const GearTrainModel& model,
                                                      Eigen::VectorXd& static_load) {
  std::vector<TrainExcitationTerm> terms;
  addUnbalances(model, terms);
  addRunouts(model, terms);
  addBearingExcitations(model, static_load, terms);
  return terms;
}

void addExcitationForce(const std::vector<TrainExcitationTerm>& terms, double input_angle,
                        double input_speed, double speed_rate, const double* mesh_stiffness,
                        Eigen::Ref<Eigen::VectorXd> f) {
  for (const TrainExcitationTerm& t : terms) {
    const double nu = t.order(input_speed);
    const double rate = nu * std::abs(input_speed), accel = nu * speed_rate;  // ψ̇, ψ̈
    const double k = t.mesh >= 0 ? mesh_stiffness[t.mesh] : 1.0;
    const Complex e = std::polar(1.0, nu * input_angle);
    const Complex a(rate * rate, -accel);  // ψ̇² − i ψ̈
    for (std::size_t i = 0; i < t.dofs.size(); ++i) {
      const Complex c = k * t.stiffness(i) + Complex(0.0, rate) * t.damping(i) + a * t.inertia(i);
      f(t.dofs[i]) += (c * e).real();
    }
  }
}

void refuseExcitations(const GearTrainModel& model, const std::string& what) {
  if (model.excitations().empty()) return;
  const std::string name = model.excitations().front().name;
  throw InputError(name.substr(0, name.find_first_of("@")), "(given)",
                   fmt::format("none with {}, which does not take unbalances, runouts or "
                               "bearing excitations yet (the linear steady state and the "
                               "linear time response do)",
                               what));
}

}  // namespace geardyn

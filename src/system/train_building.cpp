/// Shared internals of the gear-train assembly (detail/train_building.h).

#include "geardyn/system/detail/train_building.h"

#include <fmt/format.h>

#include <cmath>

#include "geardyn/did_you_mean.h"
#include "geardyn/error.h"

namespace geardyn::detail {
namespace {

[[noreturn]] void unknownName(const std::string& name, const std::string& key,
                              const std::vector<std::string>& known, const char* what) {
  std::string hint;
  if (auto match = closestMatch(name, known)) hint = fmt::format("; did you mean \"{}\"?", *match);
  std::string list;
  for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
  throw InputError(key, "\"" + name + "\"",
                   fmt::format("the name of one of the {} ({}){}", what, list, hint));
}

}  // namespace

int shaftBodyOf(const GearTrainModel& model, const GearTrainSpec& spec, const std::string& name,
                const std::string& key) {
  std::vector<std::string> known;
  for (std::size_t i = 0; i < spec.shafts.size(); ++i) {
    if (spec.shafts[i].name == name) return model.shaftBody(static_cast<int>(i));
    known.push_back(spec.shafts[i].name);
  }
  unknownName(name, key, known, "shafts");
}

int shaftIndexOf(const GearTrainSpec& spec, const std::string& name, const std::string& key) {
  std::vector<std::string> known;
  for (std::size_t i = 0; i < spec.shafts.size(); ++i) {
    if (spec.shafts[i].name == name) return static_cast<int>(i);
    known.push_back(spec.shafts[i].name);
  }
  unknownName(name, key, known, "shafts");
}

int bodyAtOf(const GearTrainModel& model, const std::string& name, const std::string& shaft_key,
             double position, const std::string& position_key) {
  return model.bodyAt(shaftIndexOf(model.spec(), name, shaft_key), position, position_key);
}

std::pair<int, int> couplingBodies(const GearTrainModel& model, const TrainCouplingSpec& c) {
  const std::string key = "couplings." + c.name + ".shafts";
  const int a = shaftIndexOf(model.spec(), c.shaft_a, key);
  const int b = shaftIndexOf(model.spec(), c.shaft_b, key);
  return {model.shaftNodes(a).back(), model.shaftNodes(b).front()};
}

int inputBody(const GearTrainModel& model) {
  const OperatingPoint& op = model.spec().operating;
  const int s = shaftIndexOf(model.spec(), op.input_shaft, "operating_point.input");
  return op.input_position ? model.bodyAt(s, *op.input_position, "operating_point.input_position")
                           : model.shaftNodes(s).front();
}

int outputBody(const GearTrainModel& model) {
  const OperatingPoint& op = model.spec().operating;
  const int s = shaftIndexOf(model.spec(), op.output_shaft, "operating_point.output");
  return op.output_position
             ? model.bodyAt(s, *op.output_position, "operating_point.output_position")
             : model.shaftNodes(s).back();
}

int gearIndexOf(const GearTrainSpec& spec, const std::string& name, const std::string& key) {
  std::vector<std::string> known;
  for (std::size_t i = 0; i < spec.gears.size(); ++i) {
    if (spec.gears[i].name == name) return static_cast<int>(i);
    known.push_back(spec.gears[i].name);
  }
  unknownName(name, key, known, "gears");
}

int carrierBody(const GearTrainModel& model, int stage) {
  const PlanetaryStageSpec& st = model.spec().stages[stage];
  return shaftBodyOf(model, model.spec(), st.carrier, "planetary." + st.name + ".carrier");
}

double carrierSpeedRatio(const GearTrainModel& model, const GearTrainSpec&, int stage) {
  return model.bodies()[carrierBody(model, stage)].speed_ratio;
}

PointJacobian translationJacobian(const GearTrainModel& model, int body, double sign, double dx) {
  PointJacobian p;
  const TrainBody& b = model.bodies()[body];
  if (model.spec().dofs == TrainDofs::kPlanar) {
    p.dofs = {b.first_dof, b.first_dof + 1};
    p.J = sign * Eigen::Matrix2d::Identity();
  } else if (model.spec().dofs == TrainDofs::kFull) {
    // u + θ × (dx, 0, 0): u_y + θ_z dx, u_z − θ_y dx.
    p.dofs = {b.first_dof, b.first_dof + 1, b.first_dof + 4, b.first_dof + 5};
    p.J.resize(2, 4);
    p.J << sign, 0, 0, sign * dx, 0, sign, -sign * dx, 0;
  } else if (b.kind == TrainBodyKind::kPlanet) {
    const int carrier = carrierBody(model, b.stage);
    const Eigen::Vector2d r = b.centre - model.bodies()[carrier].centre;
    p.dofs = {model.rotationDof(carrier)};
    p.J.resize(2, 1);
    p.J << -sign * r.y(), sign * r.x();  // θ_c x̂ × r
  } else {
    p.J.resize(2, 0);
  }
  return p;
}

PointJacobian pointJacobian(const GearTrainModel& model, int body, const Eigen::Vector2d& point,
                            double sign, double dx) {
  PointJacobian p = translationJacobian(model, body, sign, dx);
  const Eigen::Vector2d r = point - model.bodies()[body].centre;
  p.dofs.push_back(model.rotationDof(body));
  p.J.conservativeResize(2, p.J.cols() + 1);
  p.J.col(p.J.cols() - 1) << -sign * r.y(), sign * r.x();
  return p;
}

void stackJacobians(const std::vector<PointJacobian>& parts, std::vector<int>& dofs,
                    Eigen::MatrixXd& J) {
  dofs.clear();
  for (const auto& part : parts) {
    for (int d : part.dofs) {
      if (std::find(dofs.begin(), dofs.end(), d) == dofs.end()) dofs.push_back(d);
    }
  }
  J = Eigen::MatrixXd::Zero(2, static_cast<Eigen::Index>(dofs.size()));
  for (const auto& part : parts) {
    for (std::size_t i = 0; i < part.dofs.size(); ++i) {
      const auto at = std::find(dofs.begin(), dofs.end(), part.dofs[i]) - dofs.begin();
      J.col(at) += part.J.col(static_cast<Eigen::Index>(i));
    }
  }
}

void requireSameFrame(const GearTrainModel& model, int a, int b, const std::string& key) {
  if (model.spec().dofs != TrainDofs::kPlanar) return;
  const int fa = model.rotatingFrame(a), fb = model.rotatingFrame(b);
  if (fa == fb) return;
  const auto frame = [&](int f) {
    return f < 0 ? std::string("the fixed frame")
                 : "the carrier frame of planetary." + model.spec().stages[f].name;
  };
  throw InputError(
      key, "",
      fmt::format("connects {} (in {}) laterally to {} (in {}): with the carrier's Coriolis and "
                  "centripetal terms a planetary stage's members are written in its rotating "
                  "frame, and a lateral link to the fixed frame would vary in time; set "
                  "carrier_frame_terms = false on the stage (the classic lumped model), or use "
                  "torsional DOFs",
                  model.bodies()[a].name, frame(fa), model.bodies()[b].name, frame(fb)));
}

void applyOperatingLoads(const GearTrainModel& model, const GearTrainSpec& spec,
                         Eigen::VectorXd& F0, double& output_torque) {
  const OperatingPoint& op = spec.operating;
  const int in = inputBody(model);
  const int out = outputBody(model);
  if (in == out) {
    throw InputError("operating_point.output", "\"" + op.output_shaft + "\"",
                     "another shaft than the input");
  }
  if (!std::isfinite(op.input_torque)) {
    throw InputError("operating_point.torque", fmt::format("{:g} N m", op.input_torque),
                     "a finite torque");
  }
  const double ratio = model.bodies()[out].speed_ratio;
  if (std::abs(ratio) < 1e-12) {
    throw InputError("operating_point.output", "\"" + op.output_shaft + "\"",
                     "a shaft that turns: this one is held by the housing (speed 0)");
  }
  output_torque = -op.input_torque / ratio;
  F0(model.rotationDof(in)) += op.input_torque;
  F0(model.rotationDof(out)) += output_torque;

  // Pin position errors e_n: the pin sits e_n further along the tangent; the spring force on
  // the planet is −K (d − e_n t) with d the planet's displacement relative to the pin, so the
  // load vector is Jᵀ K e_n t (J the relative-displacement Jacobian).
  for (std::size_t s = 0; s < spec.stages.size(); ++s) {
    const PlanetaryStageSpec& st = spec.stages[s];
    if (st.pin_position_errors.empty()) continue;
    const std::string key = "planetary." + st.name + ".pin_position_errors";
    if (static_cast<int>(st.pin_position_errors.size()) != st.planets) {
      throw InputError(key, fmt::format("{} values", st.pin_position_errors.size()),
                       fmt::format("one error per planet ({})", st.planets));
    }
    if (spec.dofs == TrainDofs::kTorsional) {
      throw InputError(key, "", "planar or full DOFs (pins are rigid in the torsional model)");
    }
    const int carrier = carrierBody(model, static_cast<int>(s));
    for (std::size_t b = 0; b < model.bodies().size(); ++b) {
      const TrainBody& planet = model.bodies()[b];
      if (planet.stage != static_cast<int>(s) || planet.kind != TrainBodyKind::kPlanet) continue;
      const double e = st.pin_position_errors[planet.planet];
      if (!std::isfinite(e)) throw InputError(key, fmt::format("{:g} m", e), "finite values");
      const Eigen::Vector2d r = planet.centre - model.bodies()[carrier].centre;
      const Eigen::Vector2d er = r.normalized(), et(-er.y(), er.x());
      const Eigen::Matrix2d k = st.pin_radial_stiffness * er * er.transpose() +
                                st.pin_tangential_stiffness * et * et.transpose();
      std::vector<int> dofs;
      Eigen::MatrixXd J;
      const double dx = planet.axial - model.bodies()[carrier].axial;  // 0 unless full DOFs
      stackJacobians({translationJacobian(model, static_cast<int>(b), 1.0),
                      pointJacobian(model, carrier, planet.centre, -1.0, dx)},
                     dofs, J);
      const Eigen::VectorXd f = J.transpose() * (k * (e * et));
      for (std::size_t i = 0; i < dofs.size(); ++i) F0(dofs[i]) += f(static_cast<Eigen::Index>(i));
    }
  }
}

void addPlanetCentripetal(const GearTrainModel& model, int planet, double rc,
                          Eigen::MatrixXd& Komega) {
  const TrainBody& body = model.bodies()[planet];
  const int carrier = carrierBody(model, body.stage);
  const Eigen::Vector2d r = body.centre - model.bodies()[carrier].centre;
  const int idx[3] = {body.first_dof, body.first_dof + 1, model.rotationDof(carrier)};
  // J_p over (u_y, u_z, θ_c): u_p − θ_c (−r_z, r_y).
  const Eigen::Matrix<double, 2, 3> jp =
      (Eigen::Matrix<double, 2, 3>() << 1.0, 0.0, r.y(), 0.0, 1.0, -r.x()).finished();
  const Eigen::Matrix3d k = -body.mass * rc * rc * (jp.transpose() * jp);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) Komega(idx[i], idx[j]) += k(i, j);
  }
}

void requireNonNegative(double value, const std::string& key, const std::string& unit) {
  if (!std::isfinite(value) || value < 0.0) {
    throw InputError(key, fmt::format("{:g} {}", value, unit), "a finite number >= 0");
  }
}

}  // namespace geardyn::detail

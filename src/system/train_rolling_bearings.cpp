/// Rolling bearings from their geometry in a gear train (gear_train_model.h,
/// TrainRollingBearing): their place in the train's DOFs, and the train linearised about a
/// state.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "geardyn/error.h"
#include "geardyn/system/detail/train_building.h"
#include "geardyn/system/gear_train_model.h"

namespace geardyn {
namespace {

/// sign × the displacement (u_y, u_z, u_x, θ_y, θ_z) of body b's point at the axial offset dx
/// from its reference point: u + θ × (dx, 0, 0) = (u_y + θ_z dx, u_z − θ_y dx, u_x) and the two
/// tilts (full DOFs); (u_y, u_z) and zero rows otherwise. Columns over `dofs` (appended).
void addBearingPoint(const GearTrainModel& model, int body, double sign, double dx,
                     std::vector<int>& dofs, std::vector<Eigen::Matrix<double, 5, 1>>& columns) {
  const int f = model.bodies()[body].first_dof;
  auto column = [&](int dof, std::initializer_list<std::pair<int, double>> entries) {
    Eigen::Matrix<double, 5, 1> c = Eigen::Matrix<double, 5, 1>::Zero();
    for (auto [row, v] : entries) c(row) = sign * v;
    dofs.push_back(dof);
    columns.push_back(c);
  };
  column(f, {{0, 1.0}});
  column(f + 1, {{1, 1.0}});
  if (model.spec().dofs != TrainDofs::kFull) return;
  column(f + 3, {{2, 1.0}});
  column(f + 4, {{1, -dx}, {3, 1.0}});
  column(f + 5, {{0, dx}, {4, 1.0}});
}

}  // namespace

Eigen::Matrix<double, 5, 1> TrainRollingBearing::displacement(
    const Eigen::Ref<const Eigen::VectorXd>& q) const {
  Eigen::Matrix<double, 5, 1> qb = Eigen::Matrix<double, 5, 1>::Zero();
  for (std::size_t i = 0; i < dofs.size(); ++i) qb += jacobian.col(i) * q(dofs[i]);
  return qb;
}

void GearTrainModel::addRollingBearing(const TrainBearingSpec& b, const std::string& key, int body,
                                       int other, double dx, double other_dx) {
  const std::string type = b.rolling ? toString(b.rolling->geometry().type) : "linearised";
  for (auto [v, n] : {std::pair{b.kyy, "kyy"},
                      {b.kzz, "kzz"},
                      {b.kyz, "kyz"},
                      {b.kzy, "kzy"},
                      {b.k_axial, "k_axial"},
                      {b.k_tilt, "k_tilt"}}) {
    if (v != 0.0) {
      throw InputError(key + "." + n, fmt::format("{:g}", v),
                       fmt::format("0 (or no `type`): bearings.{} has type = \"{}\", whose "
                                   "stiffness follows from its geometry; give either the geometry "
                                   "or the stiffness keys kyy, kzz, kyz, kzy, k_axial, k_tilt",
                                   b.name, type));
    }
  }
  struct Value {
    double value;
    const char* name;
    const char* unit;
  };
  for (const Value& v : {Value{b.cyy, "cyy", "N s/m"},
                         {b.czz, "czz", "N s/m"},
                         {b.c_axial, "c_axial", "N s/m"},
                         {b.c_tilt, "c_tilt", "N m s/rad"},
                         {b.k_torsion, "k_torsion", "N m/rad"},
                         {b.c_torsion, "c_torsion", "N m s/rad"}}) {
    detail::requireNonNegative(v.value, key + "." + v.name, v.unit);
  }
  if ((b.full_law || b.nonlinear_law) && spec_.dofs == TrainDofs::kTorsional) {
    throw InputError(key + ".model", "\"nonlinear\"",
                     "\"linearised\" with gearbox.dofs = \"torsional\": the full bearing law "
                     "acts on the bearing's translations and tilts (planar or full DOFs)");
  }
  if (spec_.dofs == TrainDofs::kTorsional) {
    warnings_.push_back(fmt::format(
        "{}: a {} bearing acts only on translations and tilts; ignored with gearbox.dofs = "
        "\"torsional\"",
        key, type));
    return;
  }
  if (rotatingFrame(body) >= 0 || (other >= 0 && rotatingFrame(other) >= 0)) {
    throw InputError(key + ".type", "\"" + type + "\"",
                     "a bearing on a member formulated in a rotating carrier frame takes the "
                     "stiffness keys (a bearing from its geometry would vary in time there; set "
                     "the stage's carrier_frame_terms = false for the fixed-frame model)");
  }
  std::vector<int> dofs;
  std::vector<Eigen::Matrix<double, 5, 1>> columns;
  addBearingPoint(*this, body, 1.0, dx, dofs, columns);
  if (other >= 0) {
    detail::requireSameFrame(*this, body, other, key);
    addBearingPoint(*this, other, -1.0, other_dx, dofs, columns);
  }
  Eigen::Matrix<double, 5, Eigen::Dynamic> J(5, static_cast<Eigen::Index>(columns.size()));
  for (std::size_t i = 0; i < columns.size(); ++i) J.col(static_cast<Eigen::Index>(i)) = columns[i];
  // Damping: linear, on (u_y, u_z) with cross terms, axially and in tilt.
  Eigen::Matrix<double, 5, 5> c = Eigen::Matrix<double, 5, 5>::Zero();
  c(0, 0) = b.cyy, c(0, 1) = b.cyz, c(1, 0) = b.czy, c(1, 1) = b.czz;
  c(2, 2) = b.c_axial, c(3, 3) = b.c_tilt, c(4, 4) = b.c_tilt;
  const Eigen::Matrix<double, 5, 5> k =
      b.stiffness_matrix ? *b.stiffness_matrix : Eigen::Matrix<double, 5, 5>::Zero();
  if (b.stiffness_matrix || !c.isZero(0.0)) {
    // Rows (u_y, u_z, u_x, θ_y, θ_z): three forces, two moments.
    TrainElement e{
        b.name, "bearing", dofs, J.transpose() * k * J, J, k, {false, false, false, true, true}};
    elements_.push_back(e);
    element_damping_.push_back(J.transpose() * c * J);
  }
  if (b.nonlinear_law) {  // the full law in the nonlinear solvers (bearing_clearance.h)
    TrainClearanceBearing cb;
    cb.name = b.name;
    cb.dofs = dofs;
    // Planar DOFs: (u_y, u_z), the axial and tilt rows held; full DOFs: all five coordinates.
    cb.jacobian =
        spec_.dofs == TrainDofs::kFull ? Eigen::MatrixXd(J) : Eigen::MatrixXd(J.topRows(2));
    cb.clearance = std::max(0.0, 0.5 * b.nonlinear_law->geometry().clearance);
    cb.rolling = b.nonlinear_law;
    cb.linear = k.topLeftCorner<2, 2>();  // full DOFs: the whole k, in K (bearing_law.h)
    clearance_bearings_.push_back(std::move(cb));
  }
  if (b.rolling) {
    const int index = static_cast<int>(&b - spec_.bearings.data());
    rolling_bearings_.push_back({b.name, index, b.rolling, dofs, J});
  }
}

GearTrainModel GearTrainModel::linearisedAt(const Eigen::Ref<const Eigen::VectorXd>& q) const {
  GearTrainSpec spec = spec_;
  for (const TrainRollingBearing& rb : rolling_bearings_) {
    Eigen::Matrix<double, 5, 1> F;
    Eigen::Matrix<double, 5, 5> K;
    rb.bearing->evaluate(rb.displacement(q), F, &K);
    TrainBearingSpec& b = spec.bearings[rb.spec_index];
    b.stiffness_matrix = 0.5 * (K + K.transpose());
    if (b.full_law) b.nonlinear_law = b.rolling;
    b.rolling = nullptr;
  }
  return GearTrainModel(std::move(spec), memory_limit_);
}

}  // namespace geardyn

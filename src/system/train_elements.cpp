/// The elements of a gear train: bearings (with their radial clearance), couplings and planet
/// pins, each a stiffness and damping on the relative displacement of its bodies
/// (gear_train_model.h).

#include <fmt/format.h>

#include <cmath>
#include <string>
#include <vector>

#include "geardyn/error.h"
#include "geardyn/system/detail/train_building.h"
#include "geardyn/system/gear_train_model.h"

namespace geardyn {
namespace {

using detail::PointJacobian;
using detail::requireNonNegative;

/// Where buildElements puts what it assembles: the elements and their damping matrices.
struct ElementSink {
  std::vector<TrainElement>& elements;
  std::vector<Eigen::MatrixXd>& damping;

  /// A 2×2 spring and dashpot on the relative displacement d = Σ J_i q of `parts`:
  /// K = Jᵀ k J over the union of the DOFs.
  void add(std::string name, std::string kind, const std::vector<PointJacobian>& parts,
           const Eigen::Matrix2d& k2, const Eigen::Matrix2d& c2) {
    TrainElement e{std::move(name), std::move(kind), {}, {}, {}, k2, {false, false}};
    Eigen::MatrixXd J;
    detail::stackJacobians(parts, e.dofs, J);
    e.stiffness = J.transpose() * k2 * J;
    e.jacobian = J;
    const Eigen::MatrixXd c = J.transpose() * c2 * J;
    elements.push_back(e);
    damping.push_back(c);
  }
  /// One scalar spring on Σ s_i q_i: a rotation (torsion, tilt: a moment) unless `force` (an
  /// axial spring).
  void addScalar(std::string name, std::string kind, std::vector<int> dofs,
                 std::vector<double> signs, double k, double c, bool force = false) {
    TrainElement e{std::move(name), std::move(kind), std::move(dofs), {}, {}, {}, {!force}};
    Eigen::VectorXd s = Eigen::Map<Eigen::VectorXd>(signs.data(), signs.size());
    e.stiffness = k * s * s.transpose();
    e.jacobian = s.transpose();
    e.local_stiffness = Eigen::MatrixXd::Constant(1, 1, k);
    elements.push_back(e);
    damping.push_back(c * s * s.transpose());
  }
};

/// Couplings: a torsional spring on ratio θ_a − θ_b (a kinematic ratio; 1: a coupling) and,
/// with lateral DOFs, a lateral spring between the two shafts' centres.
void addCouplingElements(const GearTrainModel& model, bool lateral, ElementSink& sink) {
  for (const auto& c : model.spec().couplings) {
    const std::string key = "couplings." + c.name;
    if (c.shaft_a == c.shaft_b) {
      throw InputError(key + ".shafts", "\"" + c.shaft_a + "\"", "two different shafts");
    }
    const auto [a, b] = detail::couplingBodies(model, c);
    requireNonNegative(c.c_torsion, key + ".c_torsion", "N m s/rad");
    requireNonNegative(c.k_lateral, key + ".k_lateral", "N/m");
    requireNonNegative(c.c_lateral, key + ".c_lateral", "N s/m");
    if (!(c.k_torsion > 0.0)) {
      throw InputError(key + ".k_torsion", fmt::format("{:g} N m/rad", c.k_torsion),
                       "a torsional stiffness > 0 (a coupling transmits torque)");
    }
    if (!(c.ratio != 0.0) || !std::isfinite(c.ratio)) {
      throw InputError(key + ".ratio", fmt::format("{:g}", c.ratio),
                       "a finite speed ratio != 0 (omega_b = ratio omega_a; 1 for a coupling)");
    }
    // On ratio θ_a − θ_b: the torsional deformation of a kinematic ratio (1: a coupling).
    sink.addScalar(c.name, "coupling", {model.rotationDof(a), model.rotationDof(b)},
                   {c.ratio, -1.0}, c.k_torsion, c.c_torsion);
    if (lateral && (c.k_lateral > 0 || c.c_lateral > 0)) {
      detail::requireSameFrame(model, a, b, key);
      sink.add(
          c.name + ".lateral", "coupling",
          {detail::translationJacobian(model, a, 1.0), detail::translationJacobian(model, b, -1.0)},
          c.k_lateral * Eigen::Matrix2d::Identity(), c.c_lateral * Eigen::Matrix2d::Identity());
    }
  }
}

/// Planet pins (planar or full DOFs): the planet centre against the carrier's point at the
/// planet's position, radial and tangential springs (Lin & Parker 1999: k_p both ways); with full
/// DOFs also an axial and two tilting springs, the carrier's point in the planet's plane.
void addPlanetPins(const GearTrainModel& model, bool full, ElementSink& sink) {
  for (std::size_t p = 0; p < model.bodies().size(); ++p) {
    const TrainBody& planet = model.bodies()[p];
    if (planet.kind != TrainBodyKind::kPlanet) continue;
    const PlanetaryStageSpec& st = model.spec().stages[planet.stage];
    const std::string key = "planetary." + st.name;
    requireNonNegative(st.pin_radial_stiffness, key + ".pin_radial_stiffness", "N/m");
    requireNonNegative(st.pin_tangential_stiffness, key + ".pin_tangential_stiffness", "N/m");
    requireNonNegative(st.pin_damping, key + ".pin_damping", "N s/m");
    if (!(st.pin_radial_stiffness > 0.0 && st.pin_tangential_stiffness > 0.0)) {
      throw InputError(key + ".pin_radial_stiffness",
                       fmt::format("{:g} N/m", st.pin_radial_stiffness),
                       "pin stiffnesses > 0 radially and tangentially with planar or full "
                       "DOFs");
    }
    const int carrier = detail::carrierBody(model, planet.stage);
    const Eigen::Vector2d r = planet.centre - model.bodies()[carrier].centre;
    const Eigen::Vector2d er = r.normalized(), et(-er.y(), er.x());
    const Eigen::Matrix2d k = st.pin_radial_stiffness * er * er.transpose() +
                              st.pin_tangential_stiffness * et * et.transpose();
    const double dx = planet.axial - model.bodies()[carrier].axial;  // 0 unless full DOFs
    sink.add(planet.name + ".pin", "pin",
             {detail::translationJacobian(model, static_cast<int>(p), 1.0),
              detail::pointJacobian(model, carrier, planet.centre, -1.0, dx)},
             k, st.pin_damping * Eigen::Matrix2d::Identity());
    if (!full) continue;
    const double mean = 0.5 * (st.pin_radial_stiffness + st.pin_tangential_stiffness);
    const double b = st.planet.face_width;
    const double k_axial = st.pin_axial_stiffness >= 0.0 ? st.pin_axial_stiffness : mean;
    const double k_tilt =
        st.pin_tilt_stiffness >= 0.0 ? st.pin_tilt_stiffness : mean * b * b / 12.0;
    requireNonNegative(k_axial, key + ".pin_axial_stiffness", "N/m");
    requireNonNegative(k_tilt, key + ".pin_tilt_stiffness", "N m/rad");
    // Axial: u_x,p − (u_x,c + θ_y,c r_z − θ_z,c r_y), the carrier's point at (dx, r_y, r_z).
    const int pd = planet.first_dof, cd = model.bodies()[carrier].first_dof;
    sink.addScalar(planet.name + ".pin_axial", "pin", {pd + 3, cd + 3, cd + 4, cd + 5},
                   {1.0, -1.0, -r.y(), r.x()}, k_axial, st.pin_damping, true);
    sink.addScalar(planet.name + ".pin_tilt_y", "pin", {pd + 4, cd + 4}, {1.0, -1.0}, k_tilt,
                   st.pin_damping * b * b / 12.0);
    sink.addScalar(planet.name + ".pin_tilt_z", "pin", {pd + 5, cd + 5}, {1.0, -1.0}, k_tilt,
                   st.pin_damping * b * b / 12.0);
  }
}

}  // namespace

void GearTrainModel::checkClearance(const TrainBearingSpec& b, const std::string& key) const {
  const std::string ckey = key + ".radial_clearance";
  if (!(b.radial_clearance >= 0.0) || !std::isfinite(b.radial_clearance)) {
    throw InputError(ckey, fmt::format("{:g} m", b.radial_clearance),
                     "a finite radial clearance >= 0 m (0: a linear bearing)");
  }
  if (b.radial_clearance == 0.0) return;
  if (spec_.dofs == TrainDofs::kTorsional) {
    throw InputError(ckey, fmt::format("{:g} m", b.radial_clearance),
                     "0 with gearbox.dofs = \"torsional\": a torsional train has no radial "
                     "displacements (use \"planar\" or \"full\" DOFs for a clearance)");
  }
  if (!(b.kyy > 0.0) || b.kzz != b.kyy || b.kyz != 0.0 || b.kzy != 0.0) {
    throw InputError(key + (b.kyy > 0.0 ? ".kzz" : ".kyy"),
                     fmt::format("{:g} N/m", b.kyy > 0.0 ? b.kzz : b.kyy),
                     fmt::format("kyy = kzz > 0 without cross terms (kyy {:g} N/m, kyz {:g}, kzy "
                                 "{:g}): a bearing with radial_clearance {:g} m has one isotropic "
                                 "radial stiffness acting beyond the clearance",
                                 b.kyy, b.kyz, b.kzy, b.radial_clearance));
  }
}

void GearTrainModel::buildElements() {
  const bool planar = spec_.dofs == TrainDofs::kPlanar;
  const bool full = spec_.dofs == TrainDofs::kFull;
  const bool lateral = planar || full;
  addBeamElements();
  ElementSink sink{elements_, element_damping_};
  auto addTorsion = [&](const TrainBearingSpec& b, const std::string&, int body, int other) {
    if (!(b.k_torsion > 0 || b.c_torsion > 0)) return;
    std::vector<int> dofs{rotationDof(body)};
    std::vector<double> signs{1.0};
    if (other >= 0) dofs.push_back(rotationDof(other)), signs.push_back(-1.0);
    sink.addScalar(b.name + ".torsion", other >= 0 ? "coupling" : "support", dofs, signs,
                   b.k_torsion, b.c_torsion);
  };
  for (const auto& b : spec_.bearings) {
    const std::string key = "bearings." + b.name;
    const int shaft = detail::shaftIndexOf(spec_, b.shaft, key + ".shaft");
    const int body = bodyAt(shaft, b.position, key + ".position");
    const int other_shaft = b.other_shaft.empty()
                                ? -1
                                : detail::shaftIndexOf(spec_, b.other_shaft, key + ".other_shaft");
    const int other =
        other_shaft < 0 ? -1 : bodyAt(other_shaft, b.other_position, key + ".other_position");
    const double dx = axialOffsetOf(body, shaft, b.position);
    const double other_dx = other < 0 ? 0.0 : axialOffsetOf(other, other_shaft, b.other_position);
    if (other_shaft == shaft) {
      throw InputError(key + ".other_shaft", "\"" + b.other_shaft + "\"",
                       "another shaft than `shaft` (or empty for the housing)");
    }
    if (b.rolling || b.stiffness_matrix) {
      addRollingBearing(b, key, body, other, dx, other_dx);
      addTorsion(b, key, body, other);
      continue;
    }
    for (auto [v, n] : {std::pair{b.kyy, "kyy"},
                        {b.kzz, "kzz"},
                        {b.cyy, "cyy"},
                        {b.czz, "czz"},
                        {b.k_torsion, "k_torsion"},
                        {b.c_torsion, "c_torsion"},
                        {b.k_axial, "k_axial"},
                        {b.c_axial, "c_axial"},
                        {b.k_tilt, "k_tilt"},
                        {b.c_tilt, "c_tilt"}}) {
      requireNonNegative(v, key + "." + n, n[0] == 'k' ? "N/m" : "N s/m");
    }
    if (!full && (b.k_axial > 0 || b.c_axial > 0 || b.k_tilt > 0 || b.c_tilt > 0)) {
      // One gearbox file, many analyses: a lumped model simply has no axial or tilt DOFs.
      warnings_.push_back(
          fmt::format("{}: the axial and tilt terms act only with gearbox.dofs = "
                      "\"full\"; ignored with \"{}\"",
                      key, toString(spec_.dofs)));
    }
    const bool isotropic =
        b.kyy == b.kzz && b.kyz == 0 && b.kzy == 0 && b.cyy == b.czz && b.cyz == 0 && b.czy == 0;
    if (planar && !isotropic &&
        (bodies_[body].stage >= 0 || (other >= 0 && bodies_[other].stage >= 0))) {
      throw InputError(key + ".kzz", fmt::format("{:g} N/m", b.kzz),
                       fmt::format("equal to kyy ({:g} N/m) without cross terms: the bearing "
                                   "holds a member formulated in a rotating carrier frame, where "
                                   "an anisotropic support would vary in time (set the stage's "
                                   "carrier_frame_terms = false for the fixed-frame model)",
                                   b.kyy));
    }
    checkClearance(b, key);
    if (lateral && (b.kyy > 0 || b.kzz > 0 || b.cyy > 0 || b.czz > 0 || b.kyz != 0 || b.kzy != 0)) {
      Eigen::Matrix2d k, c;
      k << b.kyy, b.kyz, b.kzy, b.kzz;
      c << b.cyy, b.cyz, b.czy, b.czz;
      std::vector<PointJacobian> parts{detail::translationJacobian(*this, body, 1.0, dx)};
      if (other >= 0) {
        detail::requireSameFrame(*this, body, other, key);
        parts.push_back(detail::translationJacobian(*this, other, -1.0, other_dx));
      }
      sink.add(b.name, "bearing", parts, k, c);
      if (b.radial_clearance > 0.0) {
        TrainClearanceBearing cb;
        cb.name = b.name;
        cb.dofs = elements_.back().dofs;
        cb.jacobian = elements_.back().jacobian;
        cb.stiffness = b.kyy;
        cb.clearance = b.radial_clearance;
        clearance_bearings_.push_back(std::move(cb));
      }
    }
    // Axial spring on the axis, tilt springs about y and z (full DOFs).
    auto relative = [&](int offset) {
      std::vector<int> dofs{bodies_[body].first_dof + offset};
      if (other >= 0) dofs.push_back(bodies_[other].first_dof + offset);
      return dofs;
    };
    const std::vector<double> signs =
        other >= 0 ? std::vector<double>{1.0, -1.0} : std::vector<double>{1.0};
    if (full && (b.k_axial > 0 || b.c_axial > 0)) {
      sink.addScalar(b.name + ".axial", "bearing", relative(3), signs, b.k_axial, b.c_axial, true);
    }
    if (full && (b.k_tilt > 0 || b.c_tilt > 0)) {
      sink.addScalar(b.name + ".tilt_y", "bearing", relative(4), signs, b.k_tilt, b.c_tilt);
      sink.addScalar(b.name + ".tilt_z", "bearing", relative(5), signs, b.k_tilt, b.c_tilt);
    }
    addTorsion(b, key, body, other);
  }
  addCouplingElements(*this, lateral, sink);
  if (lateral) addPlanetPins(*this, full, sink);
}

}  // namespace geardyn

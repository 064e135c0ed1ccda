/// A flexible housing in the assembled train (train_housing.h): the housing's DOFs appended,
/// each linked bearing moved from the ground onto its seat (docs/theory/housing_superelement.md
/// §5).

#include "geardyn/system/train_housing.h"

#include <fmt/format.h>

#include <algorithm>

#include "geardyn/did_you_mean.h"
#include "geardyn/error.h"
#include "geardyn/system/detail/train_building.h"
#include "geardyn/system/gear_train_model.h"

namespace geardyn {
namespace {

/// " (did you mean \"x\"?)" when a candidate is close, else "".
std::string didYouMean(const std::string& word, const std::vector<std::string>& candidates) {
  const auto match = closestMatch(word, candidates);
  return match ? " (did you mean \"" + *match + "\"?)" : "";
}

/// The bearing's damping in an element's components (the model keeps it only assembled).
Eigen::MatrixXd elementDamping(const TrainBearingSpec& b, const std::string& part) {
  if (part.empty()) return (Eigen::Matrix2d() << b.cyy, b.cyz, b.czy, b.czz).finished();
  const double c = part == ".axial" ? b.c_axial : part == ".torsion" ? b.c_torsion : b.c_tilt;
  return Eigen::MatrixXd::Constant(1, 1, c);
}

/// Adds the small symmetric `block` over `dofs` to A.
void scatter(Eigen::MatrixXd& A, const std::vector<int>& dofs, const Eigen::MatrixXd& block,
             double factor = 1.0) {
  for (std::size_t i = 0; i < dofs.size(); ++i) {
    for (std::size_t j = 0; j < dofs.size(); ++j) {
      A(dofs[i], dofs[j]) +=
          factor * block(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
    }
  }
}

/// The spec's bearing `name` linked to the housing: a linear bearing from a shaft to the ground.
const TrainBearingSpec& linkedBearing(const GearTrainSpec& spec, const HousingLink& link) {
  const std::string key = "housing.seats." + link.bearing;
  const auto b = std::find_if(spec.bearings.begin(), spec.bearings.end(),
                              [&](const TrainBearingSpec& s) { return s.name == link.bearing; });
  if (b == spec.bearings.end()) {
    std::vector<std::string> names;
    for (const auto& s : spec.bearings) names.push_back(s.name);
    throw InputError(key, "\"" + link.bearing + "\"",
                     "a bearing of the gearbox" + didYouMean(link.bearing, names));
  }
  if (!b->other_shaft.empty() || b->rolling || b->stiffness_matrix || b->radial_clearance > 0.0) {
    throw InputError(key, "\"" + link.bearing + "\"",
                     "a linear bearing from a shaft to the housing without radial clearance "
                     "(bearings between shafts, rolling bearings and clearances on a flexible "
                     "housing are not supported yet)");
  }
  return *b;
}

}  // namespace

Eigen::Matrix<double, Eigen::Dynamic, 6> seatJacobian(const std::string& part,
                                                      const Eigen::Vector3d& r) {
  Eigen::Matrix<double, Eigen::Dynamic, 6> J;
  if (part.empty()) {  // lateral: (u_y, u_z) of u_c + θ_c × r
    J.resize(2, 6);
    J << 0, 1, 0, -r.z(), 0, r.x(),  //
        0, 0, 1, r.y(), -r.x(), 0;
  } else if (part == ".axial") {
    J.resize(1, 6);
    J << 1, 0, 0, 0, r.z(), -r.y();
  } else {
    J = Eigen::Matrix<double, 1, 6>::Zero();
    J(0, part == ".torsion" ? 3 : part == ".tilt_y" ? 4 : 5) = 1.0;
  }
  return J;
}

void GearTrainModel::attachHousing() {
  const TrainHousingSpec& spec = *spec_.housing;
  const ReducedHousing& h = spec.reduced;
  const int n = dof_count_;
  const int nh = static_cast<int>(h.K.rows());
  if (nh != h.interfaceDofs() + h.mode_frequencies_hz.size() || h.M.rows() != nh ||
      h.centres.size() != h.seats.size()) {
    throw InputError("housing", spec.source, "a reduced housing whose sizes agree");
  }
  if (!(spec.stiffness_proportional_damping >= 0.0)) {
    throw InputError("housing.stiffness_proportional_damping",
                     fmt::format("{:g} s", spec.stiffness_proportional_damping), "β >= 0 s");
  }
  checkDenseFits(n + nh, "housing", spec.source);
  housing_first_dof_ = n;
  dof_count_ = n + nh;
  for (Eigen::MatrixXd* A : {&M_, &K_, &C_, &G_, &Komega_, &Kmesh_}) {
    A->conservativeResize(n + nh, n + nh);
    A->rightCols(nh).setZero();
    A->bottomRows(nh).setZero();
  }
  F0_.conservativeResize(n + nh);
  F0_.tail(nh).setZero();
  M_.bottomRightCorner(nh, nh) = h.M;
  K_.bottomRightCorner(nh, nh) = h.K;
  C_.bottomRightCorner(nh, nh) = spec.stiffness_proportional_damping * h.K;

  std::vector<bool> seat_used(h.seats.size(), false);
  std::vector<std::string> linked;
  for (const HousingLink& link : spec.links) {
    const TrainBearingSpec& b = linkedBearing(spec_, link);
    const std::string key = "housing.seats." + link.bearing;
    if (std::find(linked.begin(), linked.end(), b.name) != linked.end()) {
      throw InputError(key, "\"" + link.seat + "\"", "one seat per bearing");
    }
    linked.push_back(b.name);
    const auto seat = std::find(h.seats.begin(), h.seats.end(), link.seat);
    if (seat == h.seats.end()) {
      throw InputError(key, "\"" + link.seat + "\"",
                       "a seat node set of the housing" + didYouMean(link.seat, h.seats));
    }
    const auto s = static_cast<std::size_t>(seat - h.seats.begin());
    seat_used[s] = true;
    const int shaft = detail::shaftIndexOf(spec_, b.shaft, "bearings." + b.name + ".shaft");
    const int body = bodyAt(shaft, b.position, "bearings." + b.name + ".position");
    const double dx = axialOffsetOf(body, shaft, b.position);
    const Eigen::Vector3d p(bodies_[body].axial + dx, bodies_[body].centre.x(),
                            bodies_[body].centre.y());
    Eigen::Vector3d r = p - h.centres[s];
    // Planar and torsional trains have no axial positions: the bearing sits in its seat's plane.
    if (spec_.dofs != TrainDofs::kFull) r.x() = 0.0;
    const int h0 = n + 6 * static_cast<int>(s);
    for (std::size_t e = 0; e < elements_.size(); ++e) {
      TrainElement& el = elements_[e];
      if (el.name.rfind(b.name, 0) != 0) continue;
      const std::string part = el.name.substr(b.name.size());
      if (!(part.empty() || part == ".axial" || part == ".tilt_y" || part == ".tilt_z" ||
            part == ".torsion")) {
        continue;
      }
      // d = J q_shaft − J_h q_seat: the element gains the seat's six DOFs.
      const Eigen::MatrixXd Jh = seatJacobian(part, r);
      const Eigen::Index m = el.jacobian.cols();
      Eigen::MatrixXd J(el.jacobian.rows(), m + 6);
      J << el.jacobian, -Jh;
      for (int k = 0; k < 6; ++k) el.dofs.push_back(h0 + k);
      const Eigen::MatrixXd stiffness = J.transpose() * el.local_stiffness * J;
      const Eigen::MatrixXd c = elementDamping(b, part);
      const Eigen::MatrixXd damping = J.transpose() * c * J;
      // The new terms less the old (which sit on the shaft DOFs only, already in K_ and C_).
      Eigen::MatrixXd dK = stiffness, dC = damping;
      dK.topLeftCorner(m, m) -= el.stiffness;
      dC.topLeftCorner(m, m) -= element_damping_[e];
      scatter(K_, el.dofs, dK);
      scatter(C_, el.dofs, dC);
      scatter(C_, el.dofs, dK, spec_.stiffness_proportional_damping);
      el.jacobian = J;
      el.stiffness = stiffness;
      element_damping_[e] = damping;
    }
  }
  for (std::size_t s = 0; s < seat_used.size(); ++s) {
    if (!seat_used[s]) {
      throw InputError("housing.seats", "\"" + h.seats[s] + "\"",
                       "a seat node set joined to a bearing (the set names no bearing)");
    }
  }
}

HousingLinkTerms housingLinkTerms(const GearTrainModel& model) {
  const GearTrainSpec& spec = model.spec();
  const int n_t = model.housingFirstDof();
  const int n_h = model.dofCount() - n_t;
  // The linked bearings' elements: those reaching into the housing's DOFs.
  std::vector<const TrainElement*> linked;
  std::vector<Eigen::MatrixXd> damping;
  Eigen::Index r = 0;
  for (const TrainElement& e : model.elements()) {
    if (std::none_of(e.dofs.begin(), e.dofs.end(), [&](int d) { return d >= n_t; })) continue;
    const HousingLink* link = nullptr;
    for (const HousingLink& l : spec.housing->links) {
      if (e.name.rfind(l.bearing, 0) == 0 &&
          (e.name.size() == l.bearing.size() || e.name[l.bearing.size()] == '.')) {
        link = &l;
      }
    }
    const auto b =
        std::find_if(spec.bearings.begin(), spec.bearings.end(),
                     [&](const TrainBearingSpec& s) { return link && s.name == link->bearing; });
    if (b == spec.bearings.end()) continue;  // not reached: only linked bearings join the housing
    linked.push_back(&e);
    damping.push_back(elementDamping(*b, e.name.substr(b->name.size())) +
                      spec.stiffness_proportional_damping * e.local_stiffness);
    r += e.jacobian.rows();
  }
  HousingLinkTerms t;
  t.J = Eigen::MatrixXd::Zero(r, n_t);
  t.JH = Eigen::MatrixXd::Zero(r, n_h);
  t.k = Eigen::MatrixXd::Zero(r, r);
  t.c = Eigen::MatrixXd::Zero(r, r);
  Eigen::Index row = 0;
  for (std::size_t i = 0; i < linked.size(); ++i) {
    const TrainElement& e = *linked[i];
    const Eigen::Index m = e.jacobian.rows();
    for (std::size_t j = 0; j < e.dofs.size(); ++j) {
      const auto col = static_cast<Eigen::Index>(j);
      if (e.dofs[j] < n_t) {
        t.J.block(row, e.dofs[j], m, 1) += e.jacobian.col(col);
      } else {
        t.JH.block(row, e.dofs[j] - n_t, m, 1) -= e.jacobian.col(col);
      }
    }
    t.k.block(row, row, m, m) = e.local_stiffness;
    t.c.block(row, row, m, m) = damping[i];
    row += m;
  }
  return t;
}

std::string housingDofName(const ReducedHousing& h, int i) {
  static constexpr const char* kNames[6] = {"x", "y", "z", "theta_x", "theta_y", "theta_z"};
  if (i < h.interfaceDofs()) return "housing." + h.seats[i / 6] + "." + kNames[i % 6];
  return fmt::format("housing.mode{}", i - h.interfaceDofs() + 1);
}

}  // namespace geardyn

/// A gear train joined to a reduced housing at its bearings (housing_coupling.h).

#include "geardyn/system/housing_coupling.h"

#include <fmt/format.h>

#include <algorithm>

#include "geardyn/config/did_you_mean.h"
#include "geardyn/error.h"
#include "geardyn/system/detail/train_building.h"

namespace geardyn {
namespace {

using Row6 = Eigen::Matrix<double, 1, 6>;

/// The seat's rigid motion at r = p − c in the component an element of the bearing measures
/// (seat DOFs u_x, u_y, u_z, θ_x, θ_y, θ_z; see the file comment of housing_coupling.h).
Eigen::Matrix<double, Eigen::Dynamic, 6> seatJacobian(const std::string& part,
                                                      const Eigen::Vector3d& r) {
  Eigen::Matrix<double, Eigen::Dynamic, 6> J;
  if (part.empty()) {  // lateral: (u_y, u_z)
    J.resize(2, 6);
    J << 0, 1, 0, -r.z(), 0, r.x(),  //
        0, 0, 1, r.y(), -r.x(), 0;
  } else if (part == ".axial") {
    J.resize(1, 6);
    J << 1, 0, 0, 0, r.z(), -r.y();
  } else {
    J = Row6::Zero();
    J(0, part == ".torsion" ? 3 : part == ".tilt_y" ? 4 : 5) = 1.0;
  }
  return J;
}

/// " (did you mean \"x\"?)" when a candidate is close, else "".
std::string didYouMean(const std::string& word, const std::vector<std::string>& candidates) {
  const auto match = config::closestMatch(word, candidates);
  return match ? " (did you mean \"" + *match + "\"?)" : "";
}

/// The bearing's damping in an element's components (the model keeps it only assembled).
Eigen::MatrixXd elementDamping(const TrainBearingSpec& b, const std::string& part) {
  if (part.empty()) return (Eigen::Matrix2d() << b.cyy, b.cyz, b.czy, b.czz).finished();
  const double c = part == ".axial" ? b.c_axial : part == ".torsion" ? b.c_torsion : b.c_tilt;
  return Eigen::MatrixXd::Constant(1, 1, c);
}

}  // namespace

HousedTrain coupleHousing(const GearTrainModel& model, const ReducedHousing& housing,
                          const std::vector<HousingLink>& links, double input_speed, double beta) {
  const GearTrainSpec& spec = model.spec();
  const int n = model.dofCount();
  const int nh = static_cast<int>(housing.K.rows());
  HousedTrain out;
  out.housing_first_dof = n;
  out.M = Eigen::MatrixXd::Zero(n + nh, n + nh);
  out.K = out.M;
  out.C = out.M;
  out.M.topLeftCorner(n, n) = model.mass();
  out.K.topLeftCorner(n, n) = model.meanStiffnessAt(input_speed);
  out.C.topLeftCorner(n, n) = model.dampingAt(input_speed);
  out.M.bottomRightCorner(nh, nh) = housing.M;
  out.K.bottomRightCorner(nh, nh) = housing.K;
  out.C.bottomRightCorner(nh, nh) = beta * housing.K;

  std::vector<bool> seat_used(housing.seats.size(), false);
  for (const HousingLink& link : links) {
    const std::string key = "housing.seats." + link.bearing;
    const auto b = std::find_if(spec.bearings.begin(), spec.bearings.end(),
                                [&](const TrainBearingSpec& s) { return s.name == link.bearing; });
    if (b == spec.bearings.end()) {
      std::vector<std::string> names;
      for (const auto& s : spec.bearings) names.push_back(s.name);
      throw InputError(key, "\"" + link.bearing + "\"",
                       "a bearing of the gearbox" + didYouMean(link.bearing, names));
    }
    if (!b->other_shaft.empty() || b->rolling || b->stiffness_matrix) {
      throw InputError(key, "\"" + link.bearing + "\"",
                       "a linear bearing from a shaft to the housing (bearings between shafts "
                       "and rolling bearings on a flexible housing are not supported yet)");
    }
    const auto seat = std::find(housing.seats.begin(), housing.seats.end(), link.seat);
    if (seat == housing.seats.end()) {
      throw InputError(key, "\"" + link.seat + "\"",
                       "a seat node set of the housing" + didYouMean(link.seat, housing.seats));
    }
    const int s = static_cast<int>(seat - housing.seats.begin());
    seat_used[static_cast<std::size_t>(s)] = true;
    const int shaft = detail::shaftIndexOf(spec, b->shaft, "bearings." + b->name + ".shaft");
    const int body = model.bodyAt(shaft, b->position, "bearings." + b->name + ".position");
    const double dx = model.axialOffsetOf(body, shaft, b->position);
    const Eigen::Vector3d p(model.bodies()[body].axial + dx, model.bodies()[body].centre.x(),
                            model.bodies()[body].centre.y());
    Eigen::Vector3d r = p - housing.centres[static_cast<std::size_t>(s)];
    // Planar and torsional trains have no axial positions: the bearing sits in its seat's plane.
    if (spec.dofs != TrainDofs::kFull) r.x() = 0.0;
    const int h0 = n + 6 * s;
    for (const TrainElement& e : model.elements()) {
      if (e.name.rfind(b->name, 0) != 0) continue;
      const std::string part = e.name.substr(b->name.size());
      if (!(part.empty() || part == ".axial" || part == ".tilt_y" || part == ".tilt_z" ||
            part == ".torsion")) {
        continue;
      }
      const Eigen::MatrixXd Jh = seatJacobian(part, r);
      for (const auto& [A, k] :
           {std::pair{&out.K, e.local_stiffness}, std::pair{&out.C, elementDamping(*b, part)}}) {
        const Eigen::MatrixXd cross = -e.jacobian.transpose() * k * Jh;  // |dofs| × 6
        for (std::size_t i = 0; i < e.dofs.size(); ++i) {
          A->block(e.dofs[i], h0, 1, 6) += cross.row(static_cast<Eigen::Index>(i));
          A->block(h0, e.dofs[i], 6, 1) += cross.row(static_cast<Eigen::Index>(i)).transpose();
        }
        A->block(h0, h0, 6, 6) += Jh.transpose() * k * Jh;
      }
    }
  }
  for (std::size_t s = 0; s < seat_used.size(); ++s) {
    if (!seat_used[s]) {
      throw InputError("housing", housing.seats[s],
                       "every seat node set joined to a bearing (housing.seats.<bearing> = \"" +
                           housing.seats[s] + "\")");
    }
  }
  return out;
}

}  // namespace geardyn

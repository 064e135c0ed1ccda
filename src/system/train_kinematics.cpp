/// Speed propagation over the constraint hypergraph of a gear train (train_kinematics.h).

#include "geardyn/system/train_kinematics.h"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <cmath>
#include <set>

#include "geardyn/error.h"

namespace geardyn {

TrainKinematics solveKinematics(const std::vector<std::string>& body_names,
                                const std::vector<SpeedConstraint>& constraints, int input_body,
                                const std::string& input_key) {
  const int n = static_cast<int>(body_names.size());
  const int m = static_cast<int>(constraints.size());
  if (input_body < 0 || input_body >= n) {
    throw InputError(input_key, "", "the input shaft must be one of the train's shafts");
  }
  // [A; e_inᵀ] ω = [0; 1], each constraint row scaled to unit norm so that the residuals of
  // different constraints compare.
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(m + 1, n);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(m + 1);
  for (int c = 0; c < m; ++c) {
    for (std::size_t i = 0; i < constraints[c].bodies.size(); ++i) {
      A(c, constraints[c].bodies[i]) += constraints[c].coefficients[i];
    }
    const double norm = A.row(c).norm();
    if (norm > 0.0) A.row(c) /= norm;
  }
  A(m, input_body) = 1.0;
  b(m) = 1.0;

  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(A);
  cod.setThreshold(1e-10);
  const Eigen::VectorXd omega = cod.solve(b);
  const Eigen::VectorXd residual = A * omega - b;

  // An inconsistent loop: least squares leaves a residual on every constraint of the cycles
  // that contradict each other (a tree branch can always be satisfied exactly).
  if (residual.norm() > 1e-9) {
    std::string loop;
    std::set<int> bodies;
    for (int c = 0; c < m; ++c) {
      if (std::abs(residual(c)) > 1e-10) {
        loop += (loop.empty() ? "" : ", ") + constraints[c].source;
        bodies.insert(constraints[c].bodies.begin(), constraints[c].bodies.end());
      }
    }
    std::string names;
    for (int body : bodies) names += (names.empty() ? "" : ", ") + body_names[body];
    int first = 0;
    while (first < m && std::abs(residual(first)) <= 1e-10) ++first;
    throw InputError(first < m ? constraints[first].source : input_key, "",
                     fmt::format("the train is locked: the loop through {} imposes speeds on {} "
                                 "that contradict each other; remove a mesh or coupling of this "
                                 "loop, or correct a tooth count",
                                 loop, names));
  }
  // Undetermined bodies: those that move in the null space of [A; e_inᵀ].
  if (cod.rank() < n) {
    const Eigen::MatrixXd null_space =
        Eigen::FullPivLU<Eigen::MatrixXd>(A).setThreshold(1e-10).kernel();
    std::string free;
    for (int body = 0; body < n; ++body) {
      if (null_space.row(body).norm() > 1e-8) {
        free += (free.empty() ? "" : ", ") + body_names[body];
      }
    }
    throw InputError(
        input_key, "",
        fmt::format("the speeds of {} are not determined by the input: they are not connected "
                    "to the input shaft by meshes or couplings, or they belong to a differential "
                    "with two free members (hold one with a torsional bearing to the housing)",
                    free));
  }
  return TrainKinematics{std::vector<double>(omega.data(), omega.data() + n)};
}

}  // namespace geardyn

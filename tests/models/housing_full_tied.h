#pragma once
/// \file
/// The full finite-element housing with its seats tied by geardyn's rigid tie, unreduced, and its
/// lowest natural frequencies by geardyn's own sparse shift-invert Lanczos: the reference that
/// isolates the Craig–Bampton truncation error from the difference between geardyn's tie and
/// CalculiX's *RIGID BODY (issue #37, validation; docs/theory/housing_superelement.md §4). The
/// tie is written here anew, independently of reduceHousing's: columns 6 per seat (u_c, θ_c),
/// then every other DOF in mesh order; u_n = u_c + θ_c × (x_n − c), c the seat nodes' centroid.

#include <Spectra/MatOp/SparseSymMatProd.h>
#include <Spectra/SymGEigsShiftSolver.h>
#include <gtest/gtest.h>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <map>
#include <numbers>
#include <set>
#include <vector>

#include "geardyn/io/fe_matrices.h"
#include "geardyn/models/housing_superelement.h"

namespace geardyn::testing {

/// The tie T (full DOFs × (6 per seat + the other DOFs)).
inline Eigen::SparseMatrix<double> rigidSeatTie(const io::FeMatrices& fe,
                                                const std::map<int, Eigen::Vector3d>& nodes,
                                                const std::vector<HousingNodeSet>& seats) {
  std::map<int, std::pair<int, Eigen::Vector3d>> seat_of;  // node -> (seat, centroid)
  for (std::size_t s = 0; s < seats.size(); ++s) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int n : seats[s].nodes) c += nodes.at(n);
    c /= static_cast<double>(seats[s].nodes.size());
    for (int n : seats[s].nodes) seat_of[n] = {static_cast<int>(s), c};
  }
  const Eigen::Index nb = 6 * static_cast<Eigen::Index>(seats.size());
  std::vector<Eigen::Triplet<double>> t;
  Eigen::Index other = 0;
  for (std::size_t i = 0; i < fe.dofs.size(); ++i) {
    const io::FeDof d = fe.dofs[i];
    const auto seat = seat_of.find(d.node);
    const Eigen::Index row = static_cast<Eigen::Index>(i);
    if (seat == seat_of.end()) {
      t.emplace_back(row, nb + other++, 1.0);
      continue;
    }
    const int s = seat->second.first;
    const Eigen::Vector3d r = nodes.at(d.node) - seat->second.second;
    for (int k = 0; k < 3; ++k) {
      const double v = Eigen::Vector3d::Unit(k).cross(r)[d.direction - 1];  // θ_k e_k × r
      if (v != 0.0) t.emplace_back(row, 6 * s + 3 + k, v);
    }
    t.emplace_back(row, 6 * s + d.direction - 1, 1.0);
  }
  Eigen::SparseMatrix<double> T(static_cast<Eigen::Index>(fe.dofs.size()), nb + other);
  T.setFromTriplets(t.begin(), t.end());
  return T;
}

/// y = K⁻¹ x, K factorised once (Spectra's shift-invert operator with the shift 0).
class TiedInverse {
 public:
  using Scalar = double;
  explicit TiedInverse(const Eigen::SparseMatrix<double>& K) : ldlt_(K) {}
  bool ok() const { return ldlt_.info() == Eigen::Success; }
  Eigen::Index rows() const { return ldlt_.rows(); }
  Eigen::Index cols() const { return ldlt_.cols(); }
  void set_shift(double) {}
  void perform_op(const double* x, double* y) const {
    Eigen::Map<Eigen::VectorXd>(y, rows()) =
        ldlt_.solve(Eigen::Map<const Eigen::VectorXd>(x, rows()));
  }

 private:
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt_;
};

/// The lowest `count` frequencies [Hz] of the full tied model Tᵀ K T, Tᵀ M T (mounted: positive
/// definite), by Spectra's SymGEigsShiftSolver with shift 0 to a relative tolerance 1e-12.
inline std::vector<double> fullTiedFrequenciesHz(const io::FeMatrices& fe,
                                                 const std::map<int, Eigen::Vector3d>& nodes,
                                                 const std::vector<HousingNodeSet>& seats,
                                                 int count) {
  const Eigen::SparseMatrix<double> T = rigidSeatTie(fe, nodes, seats);
  const Eigen::SparseMatrix<double> K = T.transpose() * fe.K * T, M = T.transpose() * fe.M * T;
  TiedInverse op(K);
  EXPECT_TRUE(op.ok()) << "the tied model's K is not factorisable";
  Spectra::SparseSymMatProd<double> bop(M);
  Spectra::SymGEigsShiftSolver<TiedInverse, Spectra::SparseSymMatProd<double>,
                               Spectra::GEigsMode::ShiftInvert>
      solver(op, bop, count, std::max(2 * count + 1, 30), 0.0);
  solver.init();
  solver.compute(Spectra::SortRule::LargestMagn, 1000, 1e-12);
  EXPECT_EQ(solver.info(), Spectra::CompInfo::Successful);
  const Eigen::VectorXd lambda = solver.eigenvalues().reverse();
  std::vector<double> hz;
  for (Eigen::Index i = 0; i < lambda.size(); ++i) {
    hz.push_back(std::sqrt(std::max(lambda[i], 0.0)) / (2.0 * std::numbers::pi));
  }
  return hz;
}

}  // namespace geardyn::testing

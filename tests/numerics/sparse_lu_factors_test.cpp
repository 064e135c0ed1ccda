// detail::SparseLuFactors solves like Eigen's SparseLU, whose factors it copies: on a random
// unsymmetric sparse matrix with pivoting and on the Newmark matrix of a 500-DOF FE gearbox
// (gyroscopic, so unsymmetric), to 1e-12 of the solution (both do the same operations in a
// different order: round-off ~ cond · 1e-16).

#include "geardyn/numerics/sparse_lu_factors.h"

#include <gtest/gtest.h>

#include <Eigen/Sparse>
#include <random>
#include <vector>

#include "geardyn/system/gear_train_model.h"
#include "system/sample_trains.h"

namespace geardyn {
namespace {

void expectSameAsSparseLu(const Eigen::SparseMatrix<double>& A) {
  detail::SparseLuFactors ours;
  ASSERT_TRUE(ours.factorize(A));
  Eigen::SparseLU<Eigen::SparseMatrix<double>> eigen;
  eigen.compute(A);
  ASSERT_EQ(eigen.info(), Eigen::Success);
  std::mt19937 rng(7);
  std::normal_distribution<double> normal;
  for (int k = 0; k < 3; ++k) {
    Eigen::VectorXd b(A.rows());
    for (Eigen::Index i = 0; i < b.size(); ++i) b(i) = normal(rng);
    Eigen::VectorXd x;
    ours.solve(b, x);
    const Eigen::VectorXd reference = eigen.solve(b);
    EXPECT_LT((x - reference).norm(), 1e-12 * reference.norm());
    EXPECT_LT((A * x - b).norm(), 1e-10 * b.norm());
  }
}

TEST(SparseLuFactors, SolveLikeSparseLuOnARandomUnsymmetricMatrix) {
  // Weak diagonal: partial pivoting must swap rows.
  const int n = 200;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  std::uniform_int_distribution<int> index(0, n - 1);
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i) {
    t.emplace_back(i, i, 0.05 * value(rng));
    for (int k = 0; k < 4; ++k) t.emplace_back(index(rng), i, value(rng));
    t.emplace_back((i + 1) % n, i, 2.0);
  }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  expectSameAsSparseLu(A);
}

TEST(SparseLuFactors, SolveLikeSparseLuOnAnFeGearboxNewmarkMatrix) {
  const GearTrainModel model(testing::flexibleChain(4, 0.03));
  const double dt = 1e-5, speed = model.inputSpeed();
  const Eigen::MatrixXd A = model.meanStiffnessAt(speed) + 4.0 / (dt * dt) * model.mass() +
                            2.0 / dt * model.dampingAt(speed);
  expectSameAsSparseLu(A.sparseView(1.0, 1e-14 * A.cwiseAbs().maxCoeff()));
}

}  // namespace
}  // namespace geardyn

// The mesh deflection gradient v: the corrected Visnadi eq. 11, symmetry and rank of k v vᵀ,
// and its null space (rigid-body motions and the rolling motion of the pair).

#include "geardyn/models/gear_mesh_coupling.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace geardyn {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

MeshCouplingGeometry visnadiLike(double psi_deg, double beta_b_deg, MeshContactPoint point) {
  MeshCouplingGeometry g;
  g.line_of_action_angle = psi_deg * kDeg;
  g.base_helix_angle = beta_b_deg * kDeg;
  g.pinion_base_radius = 0.0352;
  g.gear_base_radius = 0.0423;
  g.line_of_action_length = 0.0282;
  g.pitch_point_distance = 0.0352 * std::tan(20 * kDeg);
  g.contact_point = point;
  return g;
}

/// Visnadi eq. 11 with the two misprints corrected (θ_xg for the gear torsion, θ_zg for the
/// gear tilt): the mesh deflection for nodal DOFs in our order [u_x, u_y, u_z, θ_x, θ_y, θ_z].
double printedEq11(const MeshVector& q, double psi, double beta, double rbp, double rbg) {
  const double s = std::sin(psi), c = std::cos(psi);
  const int p = 0, g = kNodeDofs;
  return (q(p + kUy) * s - q(g + kUy) * s + q(p + kUz) * c - q(g + kUz) * c + rbp * q(p + kRx) +
          rbg * q(g + kRx)) *
             std::cos(beta) +
         (rbp * q(p + kRy) * s + rbg * q(g + kRy) * s + rbp * q(p + kRz) * c +
          rbg * q(g + kRz) * c) *
             std::sin(beta);
}

TEST(GearMeshCoupling, ReproducesTheCorrectedPrintedEquation11) {
  for (double psi : {0.0, 20.0, 73.0}) {
    for (double beta : {0.0, 4.7}) {
      for (auto point : {MeshContactPoint::kBaseTangentPoints, MeshContactPoint::kPitchPoint}) {
        const auto g = visnadiLike(psi, beta, point);
        const MeshVector v = meshDeflectionGradient(g);
        // The paper's helix sign is the opposite of ours (its β is our −β_b) and it has no
        // axial DOFs; with the pitch point only spur gears coincide (the helical tilt terms
        // then use the pitch-point arm, see the header).
        if (point == MeshContactPoint::kPitchPoint && beta != 0.0) continue;
        for (int i = 0; i < 2 * kNodeDofs; ++i) {
          if (i % kNodeDofs == kUx) continue;
          MeshVector q = MeshVector::Zero();
          q(i) = 1.0;
          EXPECT_NEAR(v(i),
                      printedEq11(q, g.line_of_action_angle, -g.base_helix_angle,
                                  g.pinion_base_radius, g.gear_base_radius),
                      1e-15)
              << "psi " << psi << " beta " << beta << " dof " << i;
        }
      }
    }
  }
}

TEST(GearMeshCoupling, MeshMatrixIsSymmetricRankOne) {
  const MeshVector v = meshDeflectionGradient(visnadiLike(20, 4.7, MeshContactPoint::kPitchPoint));
  const ElementMatrix K = 3e8 * v * v.transpose();
  EXPECT_LT((K - K.transpose()).norm(), 1e-15 * K.norm());
  const Eigen::JacobiSVD<ElementMatrix> svd(K);
  EXPECT_GT(svd.singularValues()(0), 0.0);
  EXPECT_LT(svd.singularValues()(1), 1e-13 * svd.singularValues()(0));
  // v vᵀ is positive semi-definite: the only non-zero eigenvalue is |v|² k.
  EXPECT_NEAR(svd.singularValues()(0), 3e8 * v.squaredNorm(), 1e-6 * svd.singularValues()(0));
}

/// Rigid motion of both nodes: translation d and small rotation w about the pinion centre.
MeshVector rigidMotion(const Eigen::Vector3d& d, const Eigen::Vector3d& w,
                       const Eigen::Vector2d& gear_centre) {
  MeshVector q;
  const Eigen::Vector3d C(0.0, gear_centre.x(), gear_centre.y());
  q.segment<3>(kUx) = d;
  q.segment<3>(kRx) = w;
  q.segment<3>(kNodeDofs + kUx) = d + w.cross(C);
  q.segment<3>(kNodeDofs + kRx) = w;
  return q;
}

TEST(GearMeshCoupling, RigidBodyAndRollingMotionsAreInTheNullSpace) {
  for (double beta : {0.0, 4.7, -12.0}) {
    for (auto point : {MeshContactPoint::kPitchPoint, MeshContactPoint::kBaseTangentPoints}) {
      const auto g = visnadiLike(20, beta, point);
      const MeshVector v = meshDeflectionGradient(g);
      const Eigen::Vector2d C = gearCentreOffset(g);
      // The centre distance closes the triangle (r_bp + r_bg)² + T₁T₂² = a².
      EXPECT_NEAR(C.norm(),
                  std::hypot(g.pinion_base_radius + g.gear_base_radius, g.line_of_action_length),
                  1e-15);
      for (int axis = 0; axis < 3; ++axis) {
        const Eigen::Vector3d e = Eigen::Vector3d::Unit(axis);
        EXPECT_NEAR(v.dot(rigidMotion(e, Eigen::Vector3d::Zero(), C)), 0.0, 1e-15);
        const double rotation = v.dot(rigidMotion(Eigen::Vector3d::Zero(), e, C));
        // With one contact point every rigid rotation is free; with the paper's two points
        // the helical axial force's arms differ, so tilting the pair about y or z strains the
        // mesh (the spurious couple of Kubur's form).
        if (point == MeshContactPoint::kPitchPoint || axis == 0 || beta == 0.0) {
          EXPECT_NEAR(rotation, 0.0, 1e-15) << "axis " << axis;
        } else {
          EXPECT_GT(std::abs(rotation), 1e-4);
        }
      }
      // Rolling: θ_xp = 1, θ_xg = −r_bp/r_bg (the gear turns the other way).
      MeshVector q = MeshVector::Zero();
      q(kRx) = 1.0;
      q(kNodeDofs + kRx) = -g.pinion_base_radius / g.gear_base_radius;
      EXPECT_NEAR(v.dot(q), 0.0, 1e-16);
      // And a pinion rotation alone compresses the mesh by r_bp cos β_b.
      q(kNodeDofs + kRx) = 0.0;
      EXPECT_NEAR(v.dot(q), g.pinion_base_radius * std::cos(g.base_helix_angle), 1e-16);
    }
  }
}

}  // namespace
}  // namespace geardyn

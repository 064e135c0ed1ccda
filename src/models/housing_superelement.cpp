/// Seat condensation and Craig–Bampton reduction of a housing (housing_superelement.h).

#include "geardyn/models/housing_superelement.h"

#include <Spectra/MatOp/SparseSymMatProd.h>
#include <Spectra/SymGEigsShiftSolver.h>
#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <numbers>
#include <stdexcept>

#include "cholmod_module.h"
#include "geardyn/error.h"
#include "geardyn/module_loader.h"

namespace geardyn {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;
using Triplet = Eigen::Triplet<double>;
using Ldlt = Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int>>;

/// Below this many interior DOFs, or when more than half of them are asked for, the
/// fixed-interface modes come from a dense generalised eigensolver (Lanczos needs nev < n).
constexpr Eigen::Index kDenseModesBelow = 400;
using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

/// CHOLMOD's functions (cholmod_module.h), or null when libgeardyn_cholmod.so cannot be loaded
/// or GEARDYN_SPARSE_CHOLESKY=simplicial asks for Eigen's factorisation (the bench's comparison).
const detail::CholmodModuleApi* cholmodModule() {
  const char* choice = std::getenv("GEARDYN_SPARSE_CHOLESKY");
  if (choice != nullptr && std::strcmp(choice, "simplicial") == 0) return nullptr;
  static const detail::CholmodModuleApi* api = []() -> const detail::CholmodModuleApi* {
    try {
      using Entry = const detail::CholmodModuleApi* (*)();
      const auto entry = reinterpret_cast<Entry>(
          loadModuleSymbol("libgeardyn_cholmod.so", "geardyn_cholmod_module"));
      const detail::CholmodModuleApi* loaded = entry();
      return loaded->version == detail::kCholmodModuleVersion ? loaded : nullptr;
    } catch (const IoError&) {
      return nullptr;  // built without SuiteSparse, or the module is missing: Eigen's LDLᵀ
    }
  }();
  return api;
}

/// K_oo factorised once: CHOLMOD's supernodal Cholesky with METIS ordering (cholmod_module.h
/// says why), or Eigen's SimplicialLDLT with AMD when the module is not available.
class KooFactor {
 public:
  explicit KooFactor(const SparseMatrix& Koo) : n_(Koo.rows()), api_(cholmodModule()) {
    if (api_ != nullptr) {
      SparseMatrix lower = Koo.triangularView<Eigen::Lower>();
      lower.makeCompressed();
      int status = detail::kCholmodFailed;
      double entries = 0.0;
      factor_ = api_->factorise(static_cast<int>(n_), lower.outerIndexPtr(), lower.innerIndexPtr(),
                                lower.valuePtr(), &status, &entries);
      if (factor_ == nullptr && status == detail::kCholmodFailed) {
        throw std::runtime_error("housing reduction: CHOLMOD could not factorise K_oo");
      }
      positive_ = factor_ != nullptr;
      return;
    }
    ldlt_ = std::make_unique<Ldlt>(Koo);
    positive_ = ldlt_->info() == Eigen::Success && (ldlt_->vectorD().array() > 0.0).all();
  }
  ~KooFactor() {
    if (factor_ != nullptr) api_->release(factor_);
  }
  KooFactor(const KooFactor&) = delete;
  KooFactor& operator=(const KooFactor&) = delete;
  bool positiveDefinite() const { return positive_; }
  Eigen::Index rows() const { return n_; }
  /// B ← K_oo⁻¹ B.
  void solveInPlace(Eigen::MatrixXd& B) const {
    if (factor_ != nullptr) {
      if (api_->solve(factor_, static_cast<int>(B.cols()), B.data()) != 0) {
        throw std::runtime_error("housing reduction: CHOLMOD's solve failed");
      }
      return;
    }
    B = ldlt_->solve(B).eval();
  }
  /// y = K_oo⁻¹ x for contiguous vectors of rows() entries.
  void solve(const double* x, double* y) const {
    Eigen::Map<const Eigen::VectorXd> in(x, n_);
    Eigen::Map<Eigen::VectorXd> out(y, n_);
    if (factor_ != nullptr) {
      out = in;
      if (api_->solve(factor_, 1, y) != 0) {
        throw std::runtime_error("housing reduction: CHOLMOD's solve failed");
      }
      return;
    }
    out = ldlt_->solve(in);
  }

 private:
  Eigen::Index n_ = 0;
  const detail::CholmodModuleApi* api_ = nullptr;
  void* factor_ = nullptr;
  std::unique_ptr<Ldlt> ldlt_;
  bool positive_ = false;
};

/// y = K_oo⁻¹ x with K_oo factorised once, in Spectra's shift-invert operator interface (the
/// shift is 0: K_oo is positive definite, its seats held by the interface).
class InverseOp {
 public:
  using Scalar = double;
  explicit InverseOp(const KooFactor& factor) : factor_(factor) {}
  Eigen::Index rows() const { return factor_.rows(); }
  Eigen::Index cols() const { return factor_.rows(); }
  void set_shift(const Scalar& sigma) {
    if (sigma != 0.0) throw std::logic_error("InverseOp: only the shift 0 is factorised");
  }
  void perform_op(const Scalar* x_in, Scalar* y_out) const { factor_.solve(x_in, y_out); }

 private:
  const KooFactor& factor_;
};

/// Where each mesh DOF goes: the interface (seat s, rigid) or interior column j.
struct DofPartition {
  std::vector<int> seat_of_node_dof;  ///< per full DOF: seat index or -1
  std::vector<int> interior;          ///< per full DOF: interior index or -1
  Eigen::Index n_interior = 0;
  std::map<int, std::array<int, 3>> dof_of_node;  ///< node -> full DOF per direction (-1: fixed)
};

DofPartition partition(const io::FeMatrices& fe) {
  DofPartition p;
  for (std::size_t i = 0; i < fe.dofs.size(); ++i) {
    auto [it, inserted] =
        p.dof_of_node.try_emplace(fe.dofs[i].node, std::array<int, 3>{-1, -1, -1});
    it->second[static_cast<std::size_t>(fe.dofs[i].direction - 1)] = static_cast<int>(i);
  }
  p.seat_of_node_dof.assign(fe.dofs.size(), -1);
  p.interior.assign(fe.dofs.size(), -1);
  return p;
}

/// The rigid-constraint coefficients of a seat node's DOF d on the seat's θ: (θ × r)_d.
Eigen::Vector3d rotationRow(int d, const Eigen::Vector3d& r) {
  switch (d) {
    case 0:
      return {0.0, r.z(), -r.y()};
    case 1:
      return {-r.z(), 0.0, r.x()};
    default:
      return {r.y(), -r.x(), 0.0};
  }
}

/// Checks a seat and returns its centroid; fills the partition's seat marks.
Eigen::Vector3d tieSeat(const HousingNodeSet& seat, int s,
                        const std::map<int, Eigen::Vector3d>& nodes, DofPartition& p,
                        const std::string& key) {
  const std::string set_key = key + ".seat." + seat.name;
  if (seat.nodes.size() < 3) {
    throw InputError(set_key, std::to_string(seat.nodes.size()) + " node(s)",
                     "a bearing seat node set (*NSET, NSET=" + seat.name +
                         ") of at least three nodes not on one line");
  }
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (int n : seat.nodes) {
    const auto x = nodes.find(n);
    const auto d = p.dof_of_node.find(n);
    if (x == nodes.end() || d == p.dof_of_node.end() ||
        std::find(d->second.begin(), d->second.end(), -1) != d->second.end()) {
      throw InputError(set_key, fmt::format("node {}", n),
                       "seat nodes of the mesh, none fixed by *BOUNDARY (the seat moves with "
                       "the bearing)");
    }
    for (int dof : d->second) {
      if (p.seat_of_node_dof[static_cast<std::size_t>(dof)] >= 0) {
        throw InputError(set_key, fmt::format("node {}", n),
                         "nodes of this seat only (the node is in another seat's set too)");
      }
      p.seat_of_node_dof[static_cast<std::size_t>(dof)] = s;
    }
    c += x->second;
  }
  c /= static_cast<double>(seat.nodes.size());
  Eigen::Matrix3d J = Eigen::Matrix3d::Zero();
  double radius = 0.0;
  for (int n : seat.nodes) {
    const Eigen::Vector3d r = nodes.at(n) - c;
    J += r * r.transpose();
    radius = std::max(radius, r.norm());
  }
  const Eigen::Vector3d lambda = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(J).eigenvalues();
  // Collinear nodes: the second moment has one non-zero principal value; 1e-10 of the largest
  // is round-off of coordinates printed to ~6 digits squared.
  if (lambda[1] <= 1e-10 * lambda[2]) {
    throw InputError(set_key, fmt::format("{} nodes on one line", seat.nodes.size()),
                     "seat nodes spanning a plane or a volume (a rigid tie to nodes on one line "
                     "leaves the rotation about it free)");
  }
  return c;
}

/// The `nev` lowest fixed-interface modes by shift-invert Lanczos on the factorised K_oo
/// (Spectra's SymGEigsShiftSolver, shift 0), ascending.
void lanczosModes(const SparseMatrix& Moo, const KooFactor& factor, Eigen::Index nev,
                  Eigen::MatrixXd& Phi, Eigen::VectorXd& lambda) {
  const Eigen::Index no = Moo.rows();
  InverseOp op(factor);
  Spectra::SparseSymMatProd<double> bop(Moo);
  const Eigen::Index ncv = std::min<Eigen::Index>(no, std::max<Eigen::Index>(2 * nev + 1, 20));
  Spectra::SymGEigsShiftSolver<InverseOp, Spectra::SparseSymMatProd<double>,
                               Spectra::GEigsMode::ShiftInvert>
      solver(op, bop, nev, ncv, 0.0);
  solver.init();
  solver.compute(Spectra::SortRule::LargestMagn, 1000, 1e-10);
  if (solver.info() != Spectra::CompInfo::Successful) {
    throw std::runtime_error(
        fmt::format("housing reduction: Lanczos found {} of the {} lowest fixed-interface modes",
                    solver.eigenvalues().size(), nev));
  }
  // Spectra returns them largest first.
  lambda = solver.eigenvalues().reverse();
  Phi = solver.eigenvectors().rowwise().reverse();
}

/// The fixed-interface modes (mass-normalised shapes, eigenvalues ω² [1/s²]): `options.modes`
/// of them, or those below the cut-off. Below the cut-off they are found by Lanczos on the one
/// factor of K_oo the constraint modes need, asking for twice as many until the highest found
/// lies above the cut-off (a second factorisation of K_oo − ω_c² M_oo to count them by Sylvester's
/// law of inertia cost as much as the first; issue #37's reduction budget).
void fixedInterfaceModes(const SparseMatrix& Koo, const SparseMatrix& Moo, const KooFactor& factor,
                         const CraigBamptonOptions& options, Eigen::MatrixXd& Phi,
                         Eigen::VectorXd& lambda) {
  const Eigen::Index no = Koo.rows();
  const bool by_cutoff = options.modes < 0;
  const double w = 2.0 * std::numbers::pi * options.cutoff_hz;
  Eigen::Index m = by_cutoff ? 0 : std::min<Eigen::Index>(options.modes, no);
  if (!by_cutoff && m == 0) {
    Phi.resize(no, 0);
    lambda.resize(0);
    return;
  }
  if (no < kDenseModesBelow || (!by_cutoff && 2 * m > no)) {
    const Eigen::MatrixXd Kd = Koo, Md = Moo;
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense(Kd, Md);
    lambda = dense.eigenvalues();
    Phi = dense.eigenvectors();
  } else {
    Eigen::Index nev = by_cutoff ? std::min<Eigen::Index>(12, no / 2) : m;
    while (true) {
      lanczosModes(Moo, factor, nev, Phi, lambda);
      if (!by_cutoff || lambda(lambda.size() - 1) >= w * w || nev >= no / 2) break;
      nev = std::min<Eigen::Index>(2 * nev, no / 2);
    }
  }
  if (by_cutoff) {
    m = (lambda.array() < w * w).count();
    if (m == 0) {
      throw InputError(options.key + ".cutoff_hz", fmt::format("{:g} Hz", options.cutoff_hz),
                       fmt::format("a cut-off above the first fixed-interface mode of the housing "
                                   "({:.6g} Hz; no mode lies below it: raise the cut-off or the "
                                   "analyses' frequency range)",
                                   std::sqrt(std::max(lambda(0), 0.0)) / (2.0 * std::numbers::pi)));
    }
  }
  Phi = Phi.leftCols(m).eval();
  lambda = lambda.head(m).eval();
  for (Eigen::Index j = 0; j < m; ++j) Phi.col(j) /= std::sqrt(Phi.col(j).dot(Moo * Phi.col(j)));
}

/// Residual vectors (modal truncation augmentation): the interior's quasi-static response to the
/// inertia load of the interface's accelerations, R = K_oo⁻¹ (M_ob + M_oo Ψ), less its part in
/// the kept modes. The interior's response to interface motion at frequency ω is
/// u_o = −(K_oo − ω² M_oo)⁻¹ (K_ob − ω² M_ob) q_b = [Ψ + ω² K_oo⁻¹ (M_ob + M_oo Ψ) + O(ω⁴)] q_b
/// (Neumann series of the inverse), so with R the basis holds the response exactly to second
/// order in ω. Less its part in the kept modes, R = F_rs (M_oo Ψ + M_ob) with the residual
/// flexibility F_rs = K_oo⁻¹ − Φ Λ⁻¹ Φᵀ: the term by which Kim & Lee (2015), "An enhanced
/// Craig–Bampton method", Int. J. Numer. Meth. Engng 103, 79–93, enhance the transformation
/// (they fold it into the interface columns with an estimated eigenvalue; here its columns are
/// Ritz vectors of their own, as modal truncation augmentation vectors are: Dickens, Nakagawa &
/// Wittbrodt 1997, Computers & Structures 62(6), 985–998). R is M_oo-orthogonal to the kept modes,
/// hence K_oo-orthogonal too (K_oo Φ = M_oo Φ Λ); a Rayleigh–Ritz step within span R makes its
/// vectors M_oo-orthonormal and K_oo-orthogonal, so the modal block stays diagonal and the
/// vectors are appended to Φ, Λ as modes with their Ritz values (all above the last kept mode:
/// min-max on the M-orthogonal complement). Directions of R already in span Φ (M-norm below
/// 1e-10 of the largest after the projection, round-off of the two solves) are dropped.
Eigen::Index appendResidualVectors(const SparseMatrix& Koo, const SparseMatrix& Moo,
                                   const Eigen::MatrixXd& Mob, const Eigen::MatrixXd& MooPsi,
                                   const KooFactor& factor, Eigen::MatrixXd& Phi,
                                   Eigen::VectorXd& lambda) {
  Eigen::MatrixXd R = Mob + MooPsi;
  factor.solveInPlace(R);
  for (int pass = 0; pass < 2; ++pass) R -= Phi * (Phi.transpose() * (Moo * R));  // twice: MGS
  // Each column scaled to unit M-norm first: the seat's translations and rotations differ by
  // the seat's radius squared in scale.
  Eigen::MatrixXd MR = Moo * R;
  for (Eigen::Index j = 0; j < R.cols(); ++j) {
    const double norm2 = R.col(j).dot(MR.col(j));
    if (norm2 > 0.0) R.col(j) /= std::sqrt(norm2), MR.col(j) /= std::sqrt(norm2);
  }
  const Eigen::MatrixXd Mr = R.transpose() * MR;
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> gram(0.5 * (Mr + Mr.transpose()));
  const Eigen::VectorXd& g = gram.eigenvalues();
  const double largest = g.size() > 0 ? g(g.size() - 1) : 0.0;
  const Eigen::Index keep = (g.array() > 1e-10 * largest).count();
  if (keep == 0) return 0;
  // B = R V D^(-1/2): M-orthonormal, spanning R's independent directions.
  const Eigen::MatrixXd B = R * (gram.eigenvectors().rightCols(keep) *
                                 g.tail(keep).cwiseSqrt().cwiseInverse().asDiagonal());
  const Eigen::MatrixXd Kr = B.transpose() * (Koo * B);
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> ritz(0.5 * (Kr + Kr.transpose()));
  const Eigen::Index m = Phi.cols();
  Phi.conservativeResize(Eigen::NoChange, m + keep);
  Phi.rightCols(keep) = B * ritz.eigenvectors();
  lambda.conservativeResize(m + keep);
  lambda.tail(keep) = ritz.eigenvalues();
  return keep;
}

}  // namespace

FeUnits feUnits(const std::string& name, const std::string& key) {
  if (name == "si") return {1.0, 1.0};
  if (name == "mm_t_s") return {1e-3, 1e3};
  throw InputError(key, name,
                   "\"si\" (m, kg, s, N) or \"mm_t_s\" (mm, t, s, N: E in MPa, density in "
                   "t/mm³)");
}

void scaleToSi(io::FeMatrices& fe, std::map<int, Eigen::Vector3d>& nodes, const FeUnits& units) {
  // Time is in s in both systems, so a stiffness scales as mass / time²: by mass_kg.
  fe.K *= units.mass_kg;
  fe.M *= units.mass_kg;
  for (auto& [n, x] : nodes) x *= units.length_m;
}

ReducedHousing reduceHousing(const io::FeMatrices& fe, const std::map<int, Eigen::Vector3d>& nodes,
                             const std::vector<HousingNodeSet>& seats,
                             const std::vector<HousingNodeSet>& points,
                             const CraigBamptonOptions& options) {
  const auto t_start = Clock::now();
  const std::string& key = options.key;
  const Eigen::Index n = static_cast<Eigen::Index>(fe.dofs.size());
  if (seats.empty()) throw InputError(key, "no seats", "at least one bearing seat node set");
  DofPartition p = partition(fe);
  ReducedHousing red;
  for (std::size_t s = 0; s < seats.size(); ++s) {
    red.seats.push_back(seats[s].name);
    red.centres.push_back(tieSeat(seats[s], static_cast<int>(s), nodes, p, key));
  }
  for (Eigen::Index i = 0; i < n; ++i) {
    if (p.seat_of_node_dof[static_cast<std::size_t>(i)] < 0) {
      p.interior[static_cast<std::size_t>(i)] = static_cast<int>(p.n_interior++);
    }
  }
  const Eigen::Index nb = red.interfaceDofs(), no = p.n_interior;

  // T_b (n × nb): the rigid tie of the seat DOFs; T_o (n × no): the interior DOFs' selection.
  std::vector<Triplet> tb, to;
  for (Eigen::Index i = 0; i < n; ++i) {
    const std::size_t iu = static_cast<std::size_t>(i);
    const int s = p.seat_of_node_dof[iu];
    if (s < 0) {
      to.emplace_back(i, p.interior[iu], 1.0);
      continue;
    }
    const int d = fe.dofs[iu].direction - 1;
    const Eigen::Vector3d r = nodes.at(fe.dofs[iu].node) - red.centres[static_cast<std::size_t>(s)];
    const Eigen::Vector3d rot = rotationRow(d, r);
    tb.emplace_back(i, 6 * s + d, 1.0);
    for (int k = 0; k < 3; ++k) {
      if (rot[k] != 0.0) tb.emplace_back(i, 6 * s + 3 + k, rot[k]);
    }
  }
  SparseMatrix Tb(n, nb), To(n, no);
  Tb.setFromTriplets(tb.begin(), tb.end());
  To.setFromTriplets(to.begin(), to.end());
  const SparseMatrix Koo = To.transpose() * fe.K * To, Moo = To.transpose() * fe.M * To;
  const SparseMatrix KTb = fe.K * Tb, MTb = fe.M * Tb;
  const Eigen::MatrixXd Kob = To.transpose() * KTb, Mob = To.transpose() * MTb;
  const Eigen::MatrixXd Kbb = Tb.transpose() * KTb, Mbb = Tb.transpose() * MTb;

  const auto t_factor = Clock::now();
  const KooFactor factor(Koo);
  red.factorisation_s = secondsSince(t_factor);
  if (!factor.positiveDefinite()) {
    throw InputError(key, "the housing with its seats held",
                     "a housing whose interior is held by its seats (K_oo positive definite): "
                     "check that every part of the mesh is connected to a seat or a *BOUNDARY");
  }
  Eigen::MatrixXd Psi = -Kob;
  factor.solveInPlace(Psi);

  Eigen::MatrixXd Phi;
  Eigen::VectorXd lambda;
  const auto t_modes = Clock::now();
  fixedInterfaceModes(Koo, Moo, factor, options, Phi, lambda);
  const Eigen::MatrixXd MooPsi = Moo * Psi;
  if (options.residual_vectors) {
    red.residual_vectors = appendResidualVectors(Koo, Moo, Mob, MooPsi, factor, Phi, lambda);
  }
  red.modes_s = secondsSince(t_modes);
  const Eigen::Index m = Phi.cols();
  red.mode_frequencies_hz = lambda.cwiseMax(0.0).cwiseSqrt() / (2.0 * std::numbers::pi);

  // Craig & Bampton (1968) eqs. (4)-(9), see the file comment.
  const Eigen::MatrixXd MooPhi = Moo * Phi;
  red.K = Eigen::MatrixXd::Zero(nb + m, nb + m);
  red.M = Eigen::MatrixXd::Zero(nb + m, nb + m);
  red.K.topLeftCorner(nb, nb) = Kbb + Kob.transpose() * Psi;
  red.K.bottomRightCorner(m, m) = Phi.transpose() * (Koo * Phi);
  red.M.topLeftCorner(nb, nb) =
      Mbb + Mob.transpose() * Psi + Psi.transpose() * Mob + Psi.transpose() * MooPsi;
  red.M.topRightCorner(nb, m) = Mob.transpose() * Phi + Psi.transpose() * MooPhi;
  red.M.bottomLeftCorner(m, nb) = red.M.topRightCorner(nb, m).transpose();
  red.M.bottomRightCorner(m, m) = Phi.transpose() * MooPhi;
  red.K = 0.5 * (red.K + red.K.transpose()).eval();
  red.M = 0.5 * (red.M + red.M.transpose()).eval();

  // Response points: each node's translation from its rigid tie or its interior row.
  red.recovery = Eigen::MatrixXd::Zero(3 * static_cast<Eigen::Index>(points.size()), nb + m);
  for (std::size_t k = 0; k < points.size(); ++k) {
    const HousingNodeSet& point = points[k];
    red.points.push_back(point.name);
    if (point.nodes.empty()) {
      throw InputError(key + ".points", point.name, "a response point node set with nodes");
    }
    for (int node : point.nodes) {
      const auto dofs = p.dof_of_node.find(node);
      if (!nodes.count(node)) {
        throw InputError(key + ".points", fmt::format("{}: node {}", point.name, node),
                         "nodes of the mesh");
      }
      if (dofs == p.dof_of_node.end()) continue;  // fixed by *BOUNDARY: no motion
      for (int d = 0; d < 3; ++d) {
        const int dof = dofs->second[static_cast<std::size_t>(d)];
        if (dof < 0) continue;
        auto row = red.recovery.row(3 * static_cast<Eigen::Index>(k) + d);
        const double w = 1.0 / static_cast<double>(point.nodes.size());
        const std::size_t du = static_cast<std::size_t>(dof);
        if (const int s = p.seat_of_node_dof[du]; s >= 0) {
          const Eigen::Vector3d r = nodes.at(node) - red.centres[static_cast<std::size_t>(s)];
          row(6 * s + d) += w;
          row.segment(6 * s + 3, 3) += w * rotationRow(d, r).transpose();
        } else {
          row.head(nb) += w * Psi.row(p.interior[du]);
          row.tail(m) += w * Phi.row(p.interior[du]);
        }
      }
    }
  }
  red.other_s = secondsSince(t_start) - red.factorisation_s - red.modes_s;
  return red;
}

}  // namespace geardyn

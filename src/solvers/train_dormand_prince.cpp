/// Dormand–Prince 5(4) for linear trains at constant speed (train_dormand_prince.h).

#include "geardyn/solvers/train_dormand_prince.h"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <complex>
#include <functional>
#include <map>
#include <numbers>

#include "geardyn/error.h"

namespace geardyn {
namespace {

using Complex = std::complex<double>;
using State = std::vector<double>;  // (q / L, q̇ / (L ω)) over the integrated DOFs

/// The DOFs a force reaches: connected components of the nonzero pattern of M, C̄ and K̄ that
/// hold a loaded DOF (file comment), in increasing order.
std::vector<int> reachedDofs(const GearTrainModel& model, const Eigen::MatrixXd& damping,
                             const Eigen::MatrixXd& stiffness, const Eigen::VectorXd& initial) {
  const int n = model.dofCount();
  std::vector<char> loaded(n, 0);
  for (int i = 0; i < n; ++i)
    loaded[i] = model.staticLoad()(i) != 0.0 || (initial.size() > 0 && initial(i) != 0.0);
  for (const TrainExcitationTerm& term : model.excitations())
    for (std::size_t j = 0; j < term.dofs.size(); ++j)
      loaded[term.dofs[j]] |=
          term.stiffness(j) != 0.0 || term.damping(j) != 0.0 || term.inertia(j) != 0.0;
  for (const TrainMesh& mesh : model.meshes())
    if (!mesh.transmission_error.isZero())
      for (int d : mesh.dofs) loaded[d] = 1;
  const Eigen::MatrixXd& mass = model.mass();
  std::vector<char> reached(loaded);
  std::vector<int> stack;
  for (int i = 0; i < n; ++i)
    if (reached[i]) stack.push_back(i);
  while (!stack.empty()) {
    const int i = stack.back();
    stack.pop_back();
    for (int j = 0; j < n; ++j) {
      if (!reached[j] && (mass(i, j) != 0.0 || damping(i, j) != 0.0 || stiffness(i, j) != 0.0)) {
        reached[j] = 1;
        stack.push_back(j);
      }
    }
  }
  std::vector<int> dofs;
  for (int i = 0; i < n; ++i)
    if (reached[i]) dofs.push_back(i);
  return dofs;
}

/// The train restricted to the integrated DOFs, with its forces at constant speed.
struct ReducedTrain {
  std::vector<int> dofs;          // model DOF of each integrated DOF
  std::vector<int> reduced_of;    // model DOF → integrated index, −1 when at rest
  Eigen::MatrixXd K, C;           // K̄ and C̄ = C + Ω G₁ over the integrated DOFs
  Eigen::VectorXd inverse_mass;   // M⁻¹ when M is diagonal there, else empty
  Eigen::LLT<Eigen::MatrixXd> M;  // otherwise
  Eigen::VectorXd F0;
  std::vector<double> orders;  // ν_k |Ω| [rad/s] of the pre-summed excitations, by |ν_k|
  std::vector<Eigen::VectorXcd> amplitudes;  // F_k
  /// How e^{i ν_k |Ω| t} is formed from the earlier ones: a sincos (both −1), the conjugate
  /// of `a` (b = −1), or the product of `a` and `b` (ν_k = ν_a + ν_b: harmonic families such as
  /// a transmission error's orders cost one complex product each).
  struct Phasor {
    int a = -1, b = -1;
  };
  std::vector<Phasor> phasors;
  std::vector<TrainExcitationTerm> mesh_terms;  // runouts on meshes: k(φ) at each t
  Eigen::MatrixXd V;                            // v_m over the integrated DOFs (columns)
};

ReducedTrain reduce(const GearTrainModel& model, double speed,
                    const Eigen::VectorXd& initial = {}) {
  ReducedTrain r;
  const Eigen::MatrixXd stiffness = model.meanStiffnessAt(speed);
  const Eigen::MatrixXd damping = model.dampingAt(speed);
  r.dofs = reachedDofs(model, damping, stiffness, initial);
  const int n = static_cast<int>(r.dofs.size());
  r.reduced_of.assign(model.dofCount(), -1);
  for (int i = 0; i < n; ++i) r.reduced_of[r.dofs[i]] = i;
  r.K = stiffness(r.dofs, r.dofs);
  r.C = damping(r.dofs, r.dofs);
  const Eigen::MatrixXd mass = model.mass()(r.dofs, r.dofs);
  if (mass.isDiagonal(0.0)) {
    r.inverse_mass = mass.diagonal().cwiseInverse();
  } else {
    r.M.compute(mass);
  }
  r.F0 = model.staticLoad()(r.dofs);
  std::map<double, Eigen::VectorXcd> by_order;
  for (const TrainExcitationTerm& term : model.excitations()) {
    if (term.mesh >= 0) {
      r.mesh_terms.push_back(term);
      continue;
    }
    const double order = term.order(speed) * std::abs(speed);
    auto [it, inserted] = by_order.try_emplace(order, Eigen::VectorXcd::Zero(n));
    const Eigen::VectorXcd amplitude = term.amplitude(speed);
    for (std::size_t j = 0; j < term.dofs.size(); ++j)
      if (r.reduced_of[term.dofs[j]] >= 0) it->second(r.reduced_of[term.dofs[j]]) += amplitude(j);
  }
  std::vector<std::pair<double, Eigen::VectorXcd>> sorted(by_order.begin(), by_order.end());
  std::stable_sort(sorted.begin(), sorted.end(), [](const auto& x, const auto& y) {
    return std::abs(x.first) < std::abs(y.first);
  });
  for (auto& [order, amplitude] : sorted) {
    ReducedTrain::Phasor phasor;
    const auto k = static_cast<int>(r.orders.size());
    const double nu = order;  // a structured binding: clang 14 cannot capture it
    const auto same = [nu](double x) { return std::abs(x - nu) <= 1e-12 * std::abs(nu); };
    for (int a = 0; a < k && phasor.a < 0; ++a) {
      if (same(-r.orders[a])) phasor.a = a;
      for (int b = a; b < k && phasor.a < 0; ++b) {
        if (same(r.orders[a] + r.orders[b])) phasor = {a, b};
      }
    }
    r.orders.push_back(order);
    r.amplitudes.push_back(std::move(amplitude));
    r.phasors.push_back(phasor);
  }
  const auto& meshes = model.meshes();
  r.V = Eigen::MatrixXd::Zero(n, static_cast<Eigen::Index>(meshes.size()));
  for (std::size_t m = 0; m < meshes.size(); ++m)
    for (std::size_t j = 0; j < meshes[m].dofs.size(); ++j)
      if (r.reduced_of[meshes[m].dofs[j]] >= 0)
        r.V(r.reduced_of[meshes[m].dofs[j]], static_cast<Eigen::Index>(m)) += meshes[m].gradient[j];
  return r;
}

/// ṡ = (ω s_v, M⁻¹(f(t) − C̄ q̇ − K̄ q − Σ (k_m − k̄_m) v_m v_mᵀ q) / (L ω)). Allocation-free
/// after construction (its scratch vectors are sized once).
struct TrainOde {
  const GearTrainModel* model;
  const ReducedTrain* train;
  double speed, length, omega;
  long long* evaluations;
  mutable Eigen::VectorXd q, v, a, k, full_f;
  mutable std::vector<Complex> phasor;  // e^{i ν_k |Ω| t}

  TrainOde(const GearTrainModel& m, const ReducedTrain& r, double s, double l, double w,
           long long* count)
      : model(&m), train(&r), speed(s), length(l), omega(w), evaluations(count) {
    const auto n = static_cast<Eigen::Index>(r.dofs.size());
    q.resize(n), v.resize(n), a.resize(n);
    k.resize(static_cast<Eigen::Index>(m.meshes().size()));
    if (!r.mesh_terms.empty()) full_f.resize(m.dofCount());
    phasor.resize(r.orders.size());
  }

  void operator()(const State& s, State& ds, double t) const {
    ++*evaluations;
    const auto n = q.size();
    q = Eigen::Map<const Eigen::VectorXd>(s.data(), n) * length;
    v = Eigen::Map<const Eigen::VectorXd>(s.data() + n, n) * (length * omega);
    a = train->F0;
    for (std::size_t i = 0; i < train->orders.size(); ++i) {
      const ReducedTrain::Phasor& p = train->phasors[i];
      phasor[i] = p.a < 0   ? std::polar(1.0, train->orders[i] * t)
                  : p.b < 0 ? std::conj(phasor[p.a])
                            : phasor[p.a] * phasor[p.b];
      a += train->amplitudes[i].real() * phasor[i].real() -
           train->amplitudes[i].imag() * phasor[i].imag();
    }
    a.noalias() -= train->C * v;
    a.noalias() -= train->K * q;
    const auto& meshes = model->meshes();
    for (std::size_t m = 0; m < meshes.size(); ++m) {
      const TrainMesh& mesh = meshes[m];
      const double phi = mesh.phaseAt(t, speed);
      k(m) = mesh.stiffness->stiffness(phi);
      const TransmissionError& te = mesh.transmission_error;
      const double rate = te.derivative(phi) * mesh.frequency_ratio * std::abs(speed);
      const auto column = train->V.col(static_cast<Eigen::Index>(m));
      // −(k − k̄) v vᵀ q + (k e + c ė) v
      a += column * (-(k(m) - mesh.mean_stiffness) * column.dot(q) + k(m) * te.value(phi) +
                     mesh.damping * rate);
    }
    if (!train->mesh_terms.empty()) {
      full_f.setZero();
      addExcitationForce(train->mesh_terms, std::abs(speed) * t, speed, 0.0, k.data(), full_f);
      for (Eigen::Index i = 0; i < n; ++i) a(i) += full_f(train->dofs[i]);
    }
    if (train->inverse_mass.size() > 0) {
      a.array() *= train->inverse_mass.array();
    } else {
      train->M.solveInPlace(a);
    }
    Eigen::Map<Eigen::VectorXd>(ds.data(), n) =
        Eigen::Map<const Eigen::VectorXd>(s.data() + n, n) * omega;
    Eigen::Map<Eigen::VectorXd>(ds.data() + n, n) = a / (length * omega);
  }
};

void refuseNonlinear(const GearTrainModel& model) {
  for (const TrainMesh& mesh : model.meshes()) {
    if (mesh.nonlinear() || mesh.toothPairs()) {
      throw InputError(fmt::format("meshes.{}", mesh.name), "nonlinear (backlash, contact loss)",
                       "a linear mesh for Dormand–Prince: use the nonlinear Newmark time analysis");
    }
  }
  if (!model.clearanceBearings().empty()) {
    throw InputError(fmt::format("bearings.{}.radial_clearance", model.clearanceBearings()[0].name),
                     "> 0", "0 for Dormand–Prince: use the nonlinear Newmark time analysis");
  }
  if (!model.rollingBearings().empty()) {
    throw InputError(fmt::format("bearings.{}", model.rollingBearings()[0].name),
                     "a bearing given by its geometry",
                     "a linear bearing for Dormand–Prince (linearise the train at its static "
                     "deflection first)");
  }
}

}  // namespace

void TrainDormandPrinceOptions::validate() const {
  if (!(relative_tolerance > 0.0 && relative_tolerance < 0.1)) {
    throw InputError("time.relative_tolerance", fmt::format("{:g}", relative_tolerance),
                     "a number in (0, 0.1)");
  }
  if (!(absolute_tolerance > 0.0) || !std::isfinite(absolute_tolerance)) {
    throw InputError("time.absolute_tolerance", fmt::format("{:g}", absolute_tolerance),
                     "must be finite and > 0");
  }
  if (!(displacement_scale >= 0.0) || !std::isfinite(displacement_scale) ||
      !(velocity_frequency >= 0.0) || !std::isfinite(velocity_frequency)) {
    throw InputError("time.scale",
                     fmt::format("{:g} m, {:g} rad/s", displacement_scale, velocity_frequency),
                     "finite and >= 0 (0: derived)");
  }
}

double trainForcingFrequency(const GearTrainModel& model, double input_speed) {
  double omega = 0.0;
  for (const TrainExcitationTerm& term : model.excitations())
    omega = std::max(omega, std::abs(term.order(input_speed) * input_speed));
  for (const TrainMesh& mesh : model.meshes())
    omega = std::max(omega, 2.0 * std::numbers::pi * mesh.frequency_ratio * std::abs(input_speed));
  return omega > 0.0 ? omega : 1.0;
}

namespace {

/// trainResponseScale of the reduced train `r` [m].
double responseScale(const GearTrainModel& model, const ReducedTrain& r) {
  if (r.dofs.empty()) return 1e-6;
  // Quasi-static responses K̄⁺ f (minimum norm: rigid-body modes carry no scale).
  const Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> k(r.K);
  std::vector<char> translation(r.dofs.size(), 1);
  for (std::size_t b = 0; b < model.bodies().size(); ++b) {
    const int theta = model.rotationDof(static_cast<int>(b));
    if (theta >= 0 && r.reduced_of[theta] >= 0) translation[r.reduced_of[theta]] = 0;
  }
  double scale = 0.0;
  const auto largest = [&](const Eigen::VectorXd& x) {
    for (Eigen::Index i = 0; i < x.size(); ++i)
      if (translation[i]) scale = std::max(scale, std::abs(x(i)));
  };
  largest(k.solve(r.F0));
  for (const Eigen::VectorXcd& f : r.amplitudes) {
    largest(k.solve(Eigen::VectorXd(f.real())).cwiseAbs() +
            k.solve(Eigen::VectorXd(f.imag())).cwiseAbs());
  }
  for (const TrainMesh& mesh : model.meshes())
    for (double phi = 0.0; phi < 1.0; phi += 1.0 / 16)
      scale = std::max(scale, std::abs(mesh.transmission_error.value(phi)));
  return scale > 0.0 ? scale : 1e-6;
}

}  // namespace

double trainResponseScale(const GearTrainModel& model, double input_speed) {
  return responseScale(model, reduce(model, input_speed));
}

TrainDormandPrinceRun integrateTrainDormandPrince(const GearTrainModel& model, double input_speed,
                                                  const std::vector<double>& times,
                                                  const std::vector<int>& dofs,
                                                  const TrainDormandPrinceOptions& options,
                                                  const TrainDormandPrinceObserver& observe) {
  namespace odeint = boost::numeric::odeint;
  options.validate();
  refuseNonlinear(model);
  for (std::size_t i = 0; i < times.size(); ++i) {
    if (!std::isfinite(times[i]) || times[i] < 0.0 || (i > 0 && !(times[i] > times[i - 1]))) {
      throw InputError("times", fmt::format("index {}: {:g}", i, times[i]),
                       "times must be finite, >= 0 and increasing");
    }
  }
  for (int d : dofs) {
    if (d < 0 || d >= model.dofCount())
      throw InputError("dofs", fmt::format("{}", d),
                       fmt::format("a DOF index in [0, {})", model.dofCount()));
  }
  const Eigen::VectorXd& initial = options.initial_displacement;
  if (initial.size() != 0 && (initial.size() != model.dofCount() || !initial.allFinite())) {
    throw InputError("initial_displacement", fmt::format("{} values", initial.size()),
                     fmt::format("{} finite values (one per DOF) or none", model.dofCount()));
  }
  TrainDormandPrinceRun run;
  if (times.empty()) return run;
  const ReducedTrain train = reduce(model, input_speed, initial);
  const auto n = static_cast<Eigen::Index>(train.dofs.size());
  run.integrated_dofs = static_cast<int>(n);
  const double length =
      options.displacement_scale > 0.0 ? options.displacement_scale : responseScale(model, train);
  const double omega = options.velocity_frequency > 0.0 ? options.velocity_frequency
                                                        : trainForcingFrequency(model, input_speed);
  const auto observed = static_cast<Eigen::Index>(dofs.size());
  Eigen::VectorXd out = Eigen::VectorXd::Zero(observed);
  Eigen::VectorXd out_rate = Eigen::VectorXd::Zero(options.rates ? observed : 0);
  Eigen::VectorXd out_acceleration = out_rate;
  std::vector<std::pair<int, int>> picks;  // (output index, integrated index)
  for (std::size_t c = 0; c < dofs.size(); ++c)
    if (train.reduced_of[dofs[c]] >= 0)
      picks.push_back({static_cast<int>(c), train.reduced_of[dofs[c]]});
  if (n == 0) {  // nothing is loaded: the train stays at rest
    for (std::size_t i = 0; i < times.size(); ++i) observe(i, out, out_rate, out_acceleration);
    return run;
  }
  // The grid starts at the initial time 0 (observed only when asked for); with a progress
  // callback, ~100 unobserved points before the first sample report the integration there.
  std::vector<double> grid;
  grid.reserve(times.size() + 101);
  if (times.front() > 0.0) grid.push_back(0.0);
  if (options.progress) {
    for (int k = 1; k < 100; ++k) {
      const double t = times.back() * k / 100.0;
      if (t < times.front() && (grid.empty() || t > grid.back())) grid.push_back(t);
    }
  }
  grid.insert(grid.end(), times.begin(), times.end());
  const std::size_t offset = grid.size() - times.size();
  const std::size_t progress_every = std::max<std::size_t>(1, times.size() / 100);
  State s(static_cast<std::size_t>(2 * n), 0.0);
  for (Eigen::Index i = 0; i < n && initial.size() > 0; ++i)
    s[static_cast<std::size_t>(i)] = initial(train.dofs[static_cast<std::size_t>(i)]) / length;
  State rate(s.size());
  auto stepper = odeint::make_dense_output(options.absolute_tolerance, options.relative_tolerance,
                                           odeint::runge_kutta_dopri5<State>());
  std::size_t index = 0;
  const double first_step = 0.05 / omega;
  // By reference: odeint copies a system passed by value at every step, and this one owns
  // its scratch vectors.
  TrainOde ode(model, train, input_speed, length, omega, &run.rhs_evaluations);
  try {
    run.steps = static_cast<long long>(
        odeint::integrate_times(stepper, std::ref(ode), s, grid.begin(), grid.end(), first_step,
                                [&](const State& state, double t) {
                                  const std::size_t i = index++;
                                  if (i < offset) {
                                    if (options.progress && i > 0) options.progress(t, grid.back());
                                    return;
                                  }
                                  for (const auto& [c, r] : picks)
                                    out(c) = state[static_cast<std::size_t>(r)] * length;
                                  if (!out.allFinite() && run.finite) {
                                    run.finite = false;
                                    throw std::overflow_error("non-finite");
                                  }
                                  if (options.rates) {
                                    // q̇ = L ω s_v; q̈ = L ω ṡ_v (one more evaluation).
                                    ode(state, rate, t);
                                    for (const auto& [c, r] : picks) {
                                      const auto v = static_cast<std::size_t>(n + r);
                                      out_rate(c) = state[v] * length * omega;
                                      out_acceleration(c) = rate[v] * length * omega;
                                    }
                                  }
                                  observe(i - offset, out, out_rate, out_acceleration);
                                  if (options.progress && (i - offset + 1) % progress_every == 0)
                                    options.progress(t, grid.back());
                                }));
  } catch (const std::overflow_error&) {
    run.finite = false;  // odeint's step-size control gives up on a non-finite state too
  }
  return run;
}

}  // namespace geardyn

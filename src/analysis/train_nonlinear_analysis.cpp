/// `train` analysis `nonlinear`: the periodic steady state of a gear train whose meshes lose
/// contact or hit their back flanks (train_harmonic_balance.h), over a range of input speed by
/// pseudo-arclength continuation up and/or down (continuation.h), with folds, bifurcations and
/// stability, and optional Newmark checks (train_nonlinear_time.h) at given speeds.

#include "train_nonlinear_analysis.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <mutex>
#include <numbers>
#include <thread>

#include "geardyn/config/train_analysis.h"
#include "geardyn/error.h"
#include "geardyn/solvers/continuation.h"
#include "geardyn/solvers/train_harmonic_balance.h"
#include "geardyn/solvers/train_modal.h"
#include "geardyn/solvers/train_nonlinear_time.h"
#include "geardyn/units.h"
#include "train_undamped_modes.h"
#include "wall_clock.h"

namespace geardyn::analysis::detail {
namespace {

using geardyn::units::kRpm;
constexpr double kTwoPi = 2.0 * std::numbers::pi;
/// A mode whose mesh strain energy is below this fraction of its total has (almost) no mesh
/// deflection v_mᵀφ for the mesh forces to work on (the fraction is Σ k̄_m (v_mᵀφ)² / φᵀKφ):
/// the meshes do not excite it, and it does not set the continuation steps.
constexpr double kExcitedMeshEnergy = 1e-3;
using Json = nlohmann::ordered_json;

/// What one continuation point reports (per mesh: p2p of δ and of the contact force, the
/// largest force, whether the teeth separate and whether they hit the back flank; per clearance
/// bearing: p2p and largest of the radial displacement |u|, whether the journal leaves contact).
struct Row {
  std::string sweep;
  int point = 0, branch = 0, iterations = 0, step_cuts = 0;
  double omega = 0.0, residual = 0.0, multiplier = 0.0;
  bool stable = true;
  std::vector<double> p2p_deflection, p2p_force, max_force;
  std::vector<int> loss, back;
  std::vector<double> p2p_radial, max_radial;
  std::vector<int> journal_loss;
};

Row rowOf(const GearTrainModel& model, TrainHarmonicBalance& hbm, const SweepPoint& sp,
          const std::string& sweep, int index) {
  const HarmonicBalancePoint& p = sp.solution;
  Row row;
  row.sweep = sweep;
  row.point = index;
  row.branch = sp.branch;
  row.iterations = p.iterations;
  row.step_cuts = sp.step_cuts;
  row.omega = p.omega;
  row.residual = p.residual;
  row.multiplier = std::abs(p.critical_multiplier);
  row.stable = p.stable;
  const Eigen::MatrixXd d = hbm.meshDeflections(p.q);
  const Eigen::MatrixXd f = hbm.meshContactForces(p.q);
  for (int m = 0; m < hbm.meshCount(); ++m) {
    row.p2p_deflection.push_back(d.col(m).maxCoeff() - d.col(m).minCoeff());
    row.p2p_force.push_back(f.col(m).maxCoeff() - f.col(m).minCoeff());
    row.max_force.push_back(f.col(m).maxCoeff());
    // k > 0: the force is 0 exactly in the free play, < 0 on the back flank (or, for a linear
    // mesh, where the teeth would pull: the linear law is invalid there).
    row.loss.push_back(f.col(m).minCoeff() <= 0.0);
    row.back.push_back(model.meshes()[m].contact.law == ContactLaw::kBacklash &&
                       f.col(m).minCoeff() < 0.0);
  }
  const Eigen::MatrixXd u = hbm.bearingDisplacements(p.q);
  for (int b = 0; b < hbm.bearingCount(); ++b) {
    const Eigen::VectorXd radius = u.middleCols(2 * b, 2).rowwise().norm();
    row.p2p_radial.push_back(radius.maxCoeff() - radius.minCoeff());
    row.max_radial.push_back(radius.maxCoeff());
    // Contact loss: at some sample no contact carries (the journal inside its clearance; no
    // rolling element compressed).
    bool loss = false;
    for (Eigen::Index i = 0; i < u.rows() && !loss; ++i) {
      loss = !model.clearanceBearings()[b].touching(u.block<1, 2>(i, 2 * b).transpose());
    }
    row.journal_loss.push_back(loss);
  }
  return row;
}

Json perMesh(const GearTrainModel& model, const std::vector<double>& values) {
  Json out = Json::object();
  for (std::size_t m = 0; m < values.size(); ++m) out[model.meshes()[m].name] = values[m];
  return out;
}

/// A mode the meshes excite (mesh strain energy >= kExcitedMeshEnergy) with a resonance
/// j ω₀ = ω_n inside the sweep's range (j <= H, the highest such j).
struct ExcitedResonance {
  const TrainMode* mode;
  int order;      ///< j
  double energy;  ///< the mode's share of strain energy in the meshes [-]
};

std::vector<ExcitedResonance> excitedResonances(const std::vector<TrainMode>& modes,
                                                const ContinuationOptions& sweep, int H) {
  const double lo = std::min(sweep.start, sweep.stop), hi = std::max(sweep.start, sweep.stop);
  std::vector<ExcitedResonance> out;
  for (const TrainMode& mode : modes) {
    double energy = 0.0;
    for (double e : mode.mesh_strain_energy) energy += e;
    if (!(mode.frequency > 0.0) || energy < kExcitedMeshEnergy) continue;
    const double w = kTwoPi * mode.frequency;
    int order = 0;
    for (int j = 1; j <= H; ++j) {
      if (w / j >= lo && w / j <= hi) order = j;
    }
    if (order > 0) out.push_back({&mode, order, energy});
  }
  return out;
}

/// Continuation steps from the train (deriveContinuationSteps): of the modes the meshes excite,
/// those with a resonance j ω₀ = ω_n (j <= H, the highest such j) inside the range; the narrowest,
/// ζ ω_n / j (ζ floored at 1e-3 as there), bounds the largest step, itself at most 1/50 of the
/// range. Steps the user gave are kept (and bound the derived ones). Returns that resonance
/// (null when no excited mode has one in the range) and which bound applied.
Json deriveTrainSteps(ContinuationOptions& sweep, const std::vector<TrainMode>& modes, int H,
                      double scale) {
  const double lo = std::min(sweep.start, sweep.stop), hi = std::max(sweep.start, sweep.stop);
  double narrowest = HUGE_VAL, wn = 0.0, zeta = 0.0;
  Json resonance = nullptr;
  for (const auto& [resonant, order, energy] : excitedResonances(modes, sweep, H)) {
    const TrainMode& mode = *resonant;
    const double w = kTwoPi * mode.frequency;
    const double width = std::clamp(mode.damping_ratio, 1e-3, 0.5) * w / order;
    if (width < narrowest) {
      narrowest = width, wn = w, zeta = mode.damping_ratio;
      resonance = {{"mode_frequency_hz", mode.frequency},
                   {"damping_ratio", mode.damping_ratio},
                   {"harmonic", order},
                   {"speed_rpm", w / order / scale},
                   {"mesh_strain_energy", energy},
                   {"half_width_rpm", width / scale}};
    }
  }
  deriveContinuationSteps(sweep, wn, zeta, H);
  return {{"narrowest_resonance", resonance},
          {"limited_by", narrowest < (hi - lo) / 50.0 ? "narrowest_resonance" : "range / 50"}};
}

/// The warning for the modes the meshes excite at a resonance j ω₀ = ω_n in the range whose
/// damping ratio is below the 1e-3 the derived steps assume (deriveContinuationSteps): the peak
/// stands about 1/(2ζ) above the response beside it, and with contact loss the continuation
/// climbs such a branch in steps of the resolution in ω (seen: a 29/47 stage on undamped
/// bearings, ζ = 1.8e-4, used its 20 000 points there). Empty when there is none.
std::string lightDampingWarning(const GearTrainModel& model, const std::vector<TrainMode>& modes,
                                const ContinuationOptions& sweep, int H, double scale) {
  constexpr double kLightDamping = 1e-3;
  std::vector<std::string> listed, keys;
  for (const auto& [resonant, order, energy] : excitedResonances(modes, sweep, H)) {
    const TrainMode& mode = *resonant;
    if (!(mode.damping_ratio > 0.0) || mode.damping_ratio >= kLightDamping) continue;
    const double w = kTwoPi * mode.frequency;
    listed.push_back(fmt::format("{:.1f} Hz (ζ = {:.2g}, harmonic {} at {:.1f} rpm)",
                                 mode.frequency, mode.damping_ratio, order, w / order / scale));
    for (const std::string& key : dampingKeysOf(model, dampingPlacesOf(model, mode, true))) {
      if (std::find(keys.begin(), keys.end(), key) == keys.end()) keys.push_back(key);
    }
  }
  if (listed.empty()) return "";
  keys.push_back("gearbox.mass_proportional_damping");
  return fmt::format(
      "nonlinear: the meshes excite {} mode(s) with damping ratio below {:g} at a resonance in "
      "the sweep: {}; a resonance peaks at about 1/(2ζ) times the response beside it, and with "
      "contact loss the continuation climbs it in steps that resolve the sweep in speed (it may "
      "spend nonlinear.max_points there); damp them with {}",
      listed.size(), kLightDamping, fmt::join(listed, ", "), fmt::join(keys, ", "));
}

/// The steps the user gave must be ordered (the derived ones are by construction).
void checkSteps(const ContinuationOptions& s, double scale) {
  const auto shown = [&](double w) { return fmt::format("{:g} rpm", w / scale); };
  if (s.max_step < s.min_step) {
    throw InputError("nonlinear.max_step_rpm", shown(s.max_step),
                     ">= nonlinear.min_step_rpm = " + shown(s.min_step));
  }
  if (s.initial_step < s.min_step || s.initial_step > s.max_step) {
    throw InputError("nonlinear.initial_step_rpm", shown(s.initial_step),
                     fmt::format("within [min_step_rpm, max_step_rpm] = [{}, {}]",
                                 shown(s.min_step), shown(s.max_step)));
  }
}

io::CsvTable sweepTable(const GearTrainModel& model, const std::vector<Row>& rows, double scale,
                        bool stability) {
  // Column names end in their unit, lower case (docs/cli.md); flags have none.
  std::vector<std::string> header{"point", "branch", "speed_rpm", "base_frequency_hz"};
  for (const TrainMesh& m : model.meshes()) {
    header.push_back("p2p_deflection_" + m.name + "_m");
    header.push_back("p2p_force_" + m.name + "_n");
    header.push_back("max_force_" + m.name + "_n");
    header.push_back("contact_loss_" + m.name);
    header.push_back("back_flank_" + m.name);
  }
  for (const TrainClearanceBearing& b : model.clearanceBearings()) {
    header.push_back("p2p_radial_" + b.name + "_m");
    header.push_back("max_radial_" + b.name + "_m");
    header.push_back("contact_loss_" + b.name);
  }
  for (const char* c : {"contact_loss", "stable", "critical_multiplier_abs", "newton_iterations",
                        "relative_residual", "step_cuts"})
    header.emplace_back(c);
  io::CsvTable table(header);
  for (const Row& r : rows) {
    std::vector<io::CsvCell> cells{static_cast<long long>(r.point),
                                   static_cast<long long>(r.branch), r.omega / scale,
                                   r.omega / kTwoPi};
    long long any = 0;
    for (std::size_t m = 0; m < r.loss.size(); ++m) {
      cells.insert(cells.end(),
                   {r.p2p_deflection[m], r.p2p_force[m], r.max_force[m],
                    static_cast<long long>(r.loss[m]), static_cast<long long>(r.back[m])});
      any = any || r.loss[m];
    }
    for (std::size_t b = 0; b < r.journal_loss.size(); ++b) {
      cells.insert(cells.end(),
                   {r.p2p_radial[b], r.max_radial[b], static_cast<long long>(r.journal_loss[b])});
      any = any || r.journal_loss[b];
    }
    cells.push_back(any);
    if (stability) {
      cells.push_back(static_cast<long long>(r.stable));
      cells.push_back(r.multiplier);
    } else {
      cells.insert(cells.end(), {std::string(), std::string()});
    }
    cells.insert(cells.end(), {static_cast<long long>(r.iterations), r.residual,
                               static_cast<long long>(r.step_cuts)});
    table.addRow(cells);
  }
  return table;
}

/// One bifurcation of a sweep as summary.json lists it: type, speed, base frequency and the
/// p2p mesh deflections (and clearance bearings' radial p2p) of its point.
Json bifurcationJson(const GearTrainModel& model, TrainHarmonicBalance& hbm,
                     const std::string& which, const Row& r, BifurcationType type, double scale) {
  Json j = {{"sweep", which},
            {"type", toString(type)},
            {"speed_rpm", r.omega / scale},
            {"base_frequency_hz", r.omega / kTwoPi},
            {"p2p_deflection_m", perMesh(model, r.p2p_deflection)}};
  if (hbm.bearingCount() > 0) {
    Json radial = Json::object();
    for (int k = 0; k < hbm.bearingCount(); ++k)
      radial[model.clearanceBearings()[k].name] = r.p2p_radial[k];
    j["p2p_radial_m"] = radial;
  }
  return j;
}

/// Per mesh: the point of the largest p2p deflection over every sweep (its force, speed,
/// sweep and stability).
Json meshPeaks(const GearTrainModel& model, TrainHarmonicBalance& hbm, const std::vector<Row>& all,
               double scale) {
  Json peaks = Json::object();
  for (int m = 0; m < hbm.meshCount(); ++m) {
    const Row* best = nullptr;
    for (const Row& r : all) {
      if (!best || r.p2p_deflection[m] > best->p2p_deflection[m]) best = &r;
    }
    if (best) {
      peaks[model.meshes()[m].name] = {{"p2p_deflection_m", best->p2p_deflection[m]},
                                       {"p2p_force_n", best->p2p_force[m]},
                                       {"speed_rpm", best->omega / scale},
                                       {"sweep", best->sweep},
                                       {"stable", best->stable}};
    }
  }
  return peaks;
}

/// Per clearance bearing: its largest orbit over every sweep, and whether the journal leaves
/// contact anywhere.
Json journalPeaks(const GearTrainModel& model, TrainHarmonicBalance& hbm,
                  const std::vector<Row>& all, double scale) {
  Json journals = Json::object();  // per clearance bearing: its largest orbit, contact loss
  for (int b = 0; b < hbm.bearingCount(); ++b) {
    const Row* best = nullptr;
    bool loss = false;
    for (const Row& r : all) {
      if (!best || r.max_radial[b] > best->max_radial[b]) best = &r;
      loss = loss || r.journal_loss[b];
    }
    if (best) {
      const TrainClearanceBearing& bearing = model.clearanceBearings()[b];
      journals[bearing.name] = {{"radial_clearance_m", bearing.clearance},
                                {"max_radial_m", best->max_radial[b]},
                                {"p2p_radial_m", best->p2p_radial[b]},
                                {"speed_rpm", best->omega / scale},
                                {"sweep", best->sweep},
                                {"contact_loss_somewhere", loss}};
    }
  }
  return journals;
}

/// The Newmark checks' lines of the text report.
std::string newmarkChecksText(const Json& checks) {
  std::string text;
  for (const Json& c : checks) {
    if (c.contains("max_relative_difference")) {
      text += fmt::format("  Newmark at {:g} rpm (solution {}): {}, p2p within {:.2g} %\n",
                          c["speed_rpm"].get<double>(), c["solution"].get<std::size_t>(),
                          c["newmark_status"].get<std::string>(),
                          100 * c["max_relative_difference"].get<double>());
    }
  }
  return text;
}

/// Per mesh: its multiple of the base frequency [-], and (into `per_rpm`) its frequency per
/// rpm of input speed [Hz/rpm].
Json meshMultiplesJson(const GearTrainModel& model, TrainHarmonicBalance& hbm, double scale,
                       Json& per_rpm) {
  Json multiples = Json::object();
  per_rpm = Json::object();
  for (int m = 0; m < hbm.meshCount(); ++m) {
    multiples[model.meshes()[m].name] = hbm.meshMultiples()[m];
    per_rpm[model.meshes()[m].name] = hbm.meshMultiples()[m] * scale / kTwoPi;
  }
  return multiples;
}

}  // namespace

/// One continuation sweep with its table rows (computed by the balance that ran it).
struct SweepRun {
  std::string which;  ///< "up" or "down"
  ContinuationResult run;
  std::vector<Row> rows;
  double seconds = 0.0;   ///< wall time [s]
  bool parallel = false;  ///< ran beside the other direction's sweep
};

/// The sweeps `direction` asks for. Up and down are independent: with two or more worker
/// threads the down sweep runs beside the up one, on a balance of its own (FFTW plans are made
/// on this thread), and one progress line counts both.
std::vector<SweepRun> runSweeps(const GearTrainModel& model, TrainHarmonicBalance& hbm,
                                const TrainHarmonicBalanceOptions& options,
                                const ContinuationOptions& sweep, const std::string& direction,
                                double scale, const AnalysisContext& context) {
  std::vector<SweepRun> done;
  for (const std::string which : {"up", "down"}) {
    if (direction == "both" || direction == which) done.push_back({which, {}, {}, 0.0, false});
  }
  const unsigned threads =
      context.threads > 0 ? context.threads : std::max(1u, std::thread::hardware_concurrency());
  const bool parallel = done.size() == 2 && threads >= 2;
  std::unique_ptr<TrainHarmonicBalance> second;
  if (parallel) second = std::make_unique<TrainHarmonicBalance>(model, options);
  for (SweepRun& d : done) d.parallel = parallel;
  std::mutex progress_lock;
  std::vector<double> progress_done(done.size(), 0.0);
  const ProgressCallback both =
      parallel ? context.progressFor("train: nonlinear sweep up and down", "rpm") : nullptr;
  const auto run = [&](std::size_t k, TrainHarmonicBalance& balance,
                       const Eigen::VectorXd& guess = Eigen::VectorXd()) {
    const auto start = Clock::now();
    ContinuationOptions o = sweep;
    if (done[k].which == "down") std::swap(o.start, o.stop);
    o.initial_guess = guess;
    done[k].rows.clear();
    const ProgressCallback progress =
        parallel ? both : context.progressFor("train: nonlinear sweep " + done[k].which, "rpm");
    if (progress && parallel) {
      o.progress = [&, k](double value, double total) {
        const std::lock_guard<std::mutex> guard(progress_lock);
        progress_done[k] = value;
        progress((progress_done[0] + progress_done[1]) / scale, 2.0 * total / scale);
      };
    } else if (progress) {
      o.progress = [&](double value, double total) { progress(value / scale, total / scale); };
    }
    done[k].run = continueInFrequency(balance, o);
    for (std::size_t i = 0; i < done[k].run.points.size(); ++i) {
      done[k].rows.push_back(
          rowOf(model, balance, done[k].run.points[i], done[k].which, static_cast<int>(i)));
    }
    done[k].seconds = secondsSince(start);
  };
  // A sweep without a solution at its start (Newton from the closed-contact guess lost among
  // contact-loss branches) starts again from the other sweep's last solution, when that one
  // reached the far end of the range: a solution at (just past) this start.
  const auto restartFromTheOther = [&]() {
    if (done.size() != 2) return;
    for (std::size_t k = 0; k < 2; ++k) {
      const ContinuationResult &mine = done[k].run, &other = done[1 - k].run;
      if (!mine.points.empty() || !other.completed || other.points.empty()) continue;
      const std::string first_message = mine.message;
      run(k, hbm, other.points.back().solution.q);
      done[k].run.message = fmt::format("{} (from the {} sweep's last solution: {})",
                                        done[k].run.message, done[1 - k].which, first_message);
    }
  };
  if (!parallel) {
    for (std::size_t k = 0; k < done.size(); ++k) run(k, hbm);
    restartFromTheOther();
    return done;
  }
  std::exception_ptr failure;
  std::thread down([&] {
    try {
      run(1, *second);
    } catch (...) {
      failure = std::current_exception();
    }
  });
  try {
    run(0, hbm);
  } catch (...) {
    down.join();
    throw;
  }
  down.join();
  if (failure) std::rethrow_exception(failure);
  restartFromTheOther();
  return done;
}

std::string runTrainNonlinear(const GearTrainModel& model, const config::Config& analysis,
                              AnalysisResult& result, std::string& text,
                              const AnalysisContext& context) {
  const auto start = Clock::now();
  io::RunSummary& summary = result.summary;
  if (!model.hasNonlinearElements()) {
    summary.warnings.push_back(
        "nonlinear: no mesh has a contact law (meshes.<name>.contact or backlash) and no bearing "
        "a radial clearance (bearings.<name>.radial_clearance) or its full law "
        "(bearings.<name>.model = \"nonlinear\"): the teeth never separate and the "
        "response is the linear one");
  }
  if (nonlinearOnTorus(model, analysis)) {
    // Full-law bearings, planar or full DOFs, are nonlinear coordinates there too.
    return runTrainNonlinearTorus(model, analysis, result, text, context);
  }
  const TrainHarmonicBalanceOptions options =
      config::trainHarmonicBalanceOptionsFromConfig(analysis);
  TrainHarmonicBalance hbm(model, options);  // InputError when H is below a mesh's multiple
  const auto [lo, hi] = config::nonlinearSpeedRange(analysis, model.inputSpeed());
  const double scale = hbm.baseFrequency(kRpm);  // ω₀ per rpm [rad/s]
  for (double s : analysis.realList("nonlinear.newmark_speeds_rpm")) {
    if (s * kRpm < lo * (1 - 1e-12) || s * kRpm > hi * (1 + 1e-12)) {
      throw InputError("nonlinear.newmark_speeds_rpm", fmt::format("{:g} rpm", s),
                       fmt::format("within the sweep, [{:g}, {:g}] rpm", lo / kRpm, hi / kRpm));
    }
  }

  ContinuationOptions sweep;
  const auto given = [&](const std::string& key) {
    return analysis.has(key) ? analysis.real(key) * scale : 0.0;
  };
  sweep.initial_step = given("nonlinear.initial_step_rpm");
  sweep.min_step = given("nonlinear.min_step_rpm");
  sweep.max_step = given("nonlinear.max_step_rpm");
  sweep.fold_tolerance = given("nonlinear.fold_tolerance_rpm");
  if (sweep.fold_tolerance == 0.0) sweep.fold_tolerance = 1e-3 * (hi - lo) / kRpm * scale;
  sweep.max_points = static_cast<int>(analysis.integer("nonlinear.max_points"));
  sweep.stability = analysis.boolean("nonlinear.stability");
  sweep.stability_method = stabilityMethod(analysis);
  sweep.display_scale = scale;
  sweep.display_unit = "rpm";
  sweep.start = hbm.baseFrequency(lo);
  sweep.stop = hbm.baseFrequency(hi);
  TrainModalOptions modal;
  modal.keep_rigid = false;
  const auto modes = trainModes(model, hbm.inputSpeed(0.5 * (sweep.start + sweep.stop)), modal);
  const std::string undamped =
      undampedModesWarning(model, trainUndampedModes(model, modes),
                           hbm.inputSpeed(0.5 * (sweep.start + sweep.stop)) / kRpm);
  if (!undamped.empty()) {
    summary.warnings.push_back(fmt::format(
        "{} (their Floquet multipliers lie on the unit circle: within {:g} of it a point counts "
        "as stable, not as a bifurcation)",
        undamped, kNeutralMultiplier));
  }
  const std::string light = lightDampingWarning(model, modes, sweep, options.harmonics, scale);
  if (!light.empty()) summary.warnings.push_back(light);
  const Json step_source = deriveTrainSteps(sweep, modes, options.harmonics, scale);
  checkSteps(sweep, scale);
  if (step_source["narrowest_resonance"].is_null()) {
    summary.warnings.push_back(fmt::format(
        "nonlinear: no mode the meshes excite has a resonance (f_n = j f₀, j <= H = {}) between "
        "{:g} and {:g} rpm: the response there is quasi-static",
        options.harmonics, lo / kRpm, hi / kRpm));
  }

  const std::string direction = analysis.string("nonlinear.direction");
  std::vector<std::pair<std::string, ContinuationResult>> runs;
  Json sweeps = Json::object(), folds = Json::array(), bifurcations = Json::array();
  std::vector<Row> all;
  int points = 0;
  std::string status = "ok";
  const auto sweep_start = Clock::now();
  std::vector<SweepRun> done = runSweeps(model, hbm, options, sweep, direction, scale, context);
  for (SweepRun& sweep_run : done) {
    const std::string which = sweep_run.which;
    runs.emplace_back(which, std::move(sweep_run.run));
    const ContinuationResult& run = runs.back().second;
    const std::vector<Row>& rows = sweep_run.rows;
    const std::string file = "nonlinear_" + which + ".csv";
    result.addTable(file, sweepTable(model, rows, scale, sweep.stability));
    for (const Bifurcation& b : run.bifurcations) {
      const Json j = bifurcationJson(model, hbm, which, rows[b.index], b.type, scale);
      bifurcations.push_back(j);
      if (b.type == BifurcationType::kFold) folds.push_back(j);
    }
    points += static_cast<int>(run.points.size());
    sweeps[which] = {{"file", file},
                     {"points", run.points.size()},
                     {"completed", run.completed},
                     {"folds", run.folds.size()},
                     {"step_cuts", run.failures},
                     {"message", run.message},
                     {"wall_time_s", sweep_run.seconds},
                     {"parallel", sweep_run.parallel}};
    if (!run.completed) {
      result.errors.push_back("nonlinear sweep " + which + ": " + run.message);
      status = "incomplete_sweep";
    }
    text += fmt::format("nonlinear sweep {}: {}\n", which, run.message);
    all.insert(all.end(), rows.begin(), rows.end());
  }
  const double sweep_seconds = secondsSince(sweep_start);
  for (const Json& b : bifurcations) {
    text += fmt::format("  {} ({} sweep) at {:.6g} rpm\n", b["type"].get<std::string>(),
                        b["sweep"].get<std::string>(), b["speed_rpm"].get<double>());
  }
  const Json peaks = meshPeaks(model, hbm, all, scale);
  const Json journals = journalPeaks(model, hbm, all, scale);
  Json per_rpm;
  const Json multiples = meshMultiplesJson(model, hbm, scale, per_rpm);
  summary.results["nonlinear"] = {{"method", "common_period"},
                                  {"harmonics", options.harmonics},
                                  {"samples", options.samples},
                                  {"mesh_multiples", multiples},
                                  {"base_frequency_hz_per_rpm", scale / kTwoPi},
                                  {"mesh_frequency_hz_per_rpm", per_rpm},
                                  {"speed_min_rpm", lo / kRpm},
                                  {"speed_max_rpm", hi / kRpm},
                                  {"stability", sweep.stability},
                                  {"continuation_steps",
                                   {{"initial_step_rpm", sweep.initial_step / scale},
                                    {"min_step_rpm", sweep.min_step / scale},
                                    {"max_step_rpm", sweep.max_step / scale},
                                    {"fold_tolerance_rpm", sweep.fold_tolerance / scale},
                                    {"derived", !analysis.has("nonlinear.max_step_rpm")},
                                    {"narrowest_resonance", step_source["narrowest_resonance"]},
                                    {"limited_by", step_source["limited_by"]}}},
                                  {"sweeps", sweeps},
                                  {"points", points},
                                  {"wall_time_s", sweep_seconds},
                                  {"time_per_point_s", points > 0 ? sweep_seconds / points : 0.0},
                                  {"folds", folds},
                                  {"bifurcations", bifurcations},
                                  {"peaks", peaks},
                                  {"clearance_bearings", journals}};
  summary.results["nonlinear"]["stability_method"] = analysis.string("nonlinear.stability_method");
  const Json checks =
      newmarkChecks(model, analysis, hbm, runs, scale, sweep.stability, result, context);
  if (!checks.empty()) summary.results["nonlinear"]["newmark_checks"] = checks;
  text += newmarkChecksText(checks);
  text += fmt::format("nonlinear: H = {}, N = {}, {} points in {:.2f} s ({:.2f} ms a point)\n",
                      options.harmonics, options.samples, points, sweep_seconds,
                      points > 0 ? 1e3 * sweep_seconds / points : 0.0);
  summary.results["nonlinear"]["total_wall_time_s"] = secondsSince(start);
  return status;
}

}  // namespace geardyn::analysis::detail

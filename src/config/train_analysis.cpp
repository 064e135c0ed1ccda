/// The analysis file of `geardyn train` (train_analysis.h).

#include "geardyn/config/train_analysis.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "geardyn/config/gearbox_config.h"
#include "geardyn/config/output_section.h"
#include "geardyn/error.h"
#include "geardyn/units.h"

namespace geardyn::config {
namespace {
using geardyn::units::kRpm;

void addSpeedRange(config::ConfigSchema& schema, const std::string& s, int points,
                   const std::string& default_min) {
  schema.real(s + ".speed_min_rpm")
      .unit("rpm")
      .min(0.0)
      .optional()
      .doc("lowest input speed (default: " + default_min + ")");
  schema.real(s + ".speed_max_rpm")
      .unit("rpm")
      .positive()
      .optional()
      .doc("highest input speed (default: 1.5 × the operating speed)");
  schema.integer(s + ".points").min(2).max(100000).defaultValue(points).doc("speeds in the range");
}
/// [nonlinear]: the train harmonic balance (train_harmonic_balance.h) swept by continuation.
void addNonlinearSection(config::ConfigSchema& schema) {
  schema.section("nonlinear",
                 "Nonlinear periodic steady state over a speed range: each mesh's contact law "
                 "(contact / backlash keys of the gearbox: contact loss, back-flank impacts), "
                 "harmonic balance condensed on the mesh deflections, pseudo-arclength "
                 "continuation up and/or down in speed with folds, stability by the monodromy "
                 "matrix, optional Newmark checks.");
  schema.real("nonlinear.speed_min_rpm")
      .unit("rpm")
      .positive()
      .optional()
      .doc(
          "lowest input speed (> 0: at 0 rpm there is no mesh frequency; default: 0.5 × the "
          "operating speed)");
  schema.real("nonlinear.speed_max_rpm")
      .unit("rpm")
      .positive()
      .optional()
      .doc("highest input speed (default: 1.5 × the operating speed)");
  schema.string("nonlinear.direction")
      .choices({"up", "down", "both"})
      .defaultValue("both")
      .doc("continuation up from speed_min_rpm, down from speed_max_rpm, or both");
  schema.string("nonlinear.method")
      .choices({"auto", "common_period", "torus"})
      .defaultValue("auto")
      .doc(
          "balance over the meshes' common period, or on the torus of their phases "
          "(quasi-periodic; stability by Newmark checks at nonlinear.newmark_speeds_rpm); auto: "
          "the torus when the largest mesh multiple of the base × nonlinear.torus_mesh_harmonics "
          "exceeds forced.torus_above");
  schema.integer("nonlinear.torus_mesh_harmonics")
      .min(1)
      .max(40)
      .defaultValue(6)
      .doc("on the torus: harmonics of each mesh frequency (a box of tones per generator)");
  schema.integer("nonlinear.harmonics")
      .min(1)
      .max(512)
      .defaultValue(15)
      .doc(
          "H, harmonics of the base (common-period) frequency; every mesh needs >= its multiple "
          "P_m of it (meshes.csv, summary)");
  schema.integer("nonlinear.samples")
      .min(3)
      .max(1 << 16)
      .defaultValue(256)
      .doc(
          "N, AFT samples per base period (> 2H, else harmonics alias; 8H or more for contact "
          "loss)");
  schema.real("nonlinear.tolerance")
      .unit("-")
      .positive()
      .defaultValue(1e-10)
      .doc("relative residual ‖R‖ / (‖δ‖ + ‖b₀‖) of the first point's Newton solve");
  schema.integer("nonlinear.max_iterations").min(1).defaultValue(40).doc("Newton iterations");
  schema.boolean("nonlinear.stability")
      .defaultValue(true)
      .doc(
          "stability of every point (Floquet multipliers or exponents, "
          "nonlinear.stability_method)");
  schema.string("nonlinear.stability_method")
      .choices({"monodromy", "hill"})
      .defaultValue("monodromy")
      .doc(
          "the monodromy matrix of the variational equation by Newmark over the N samples (the "
          "default), or Hill's method (Floquet exponents from the Hill matrix on the elastic "
          "subspace, its low-rank periodic part by Woodbury: its resolvent applied to a Dirac "
          "comb, with more harmonics than the balance where its fastest mode needs them, or its "
          "eigenvalues by shift-invert Arnoldi where that costs less; "
          "docs/theory/nonlinear_gear_trains.md)");
  schema.real("nonlinear.max_step_rpm")
      .unit("rpm")
      .positive()
      .optional()
      .doc(
          "largest continuation step (along the scaled arc, in speed units); absent: derived "
          "from the train, the smaller of range / 50 and ζ n_r, n_r the speed of the narrowest "
          "resonance j f₀ = f_n (j <= H) in the range of a mode the meshes excite");
  schema.real("nonlinear.initial_step_rpm")
      .unit("rpm")
      .positive()
      .optional()
      .doc("first step; absent: a fifth of max_step_rpm");
  schema.real("nonlinear.min_step_rpm")
      .unit("rpm")
      .positive()
      .optional()
      .doc("smallest step before the sweep stops with a failure; absent: 1e-6 max_step_rpm");
  schema.real("nonlinear.fold_tolerance_rpm")
      .unit("rpm")
      .positive()
      .optional()
      .doc("how far the branch must turn back to confirm a fold; absent: 1e-3 of the range");
  schema.integer("nonlinear.max_points")
      .min(2)
      .max(1000000)
      .defaultValue(20000)
      .doc("continuation points per sweep");
  schema.realList("nonlinear.newmark_speeds_rpm")
      .unit("rpm")
      .min(0.0)
      .defaultValue(nlohmann::ordered_json::array())
      .doc(
          "input speeds at which every stable harmonic-balance solution is checked by nonlinear "
          "Newmark integration started on it (newmark_checks.csv, overlaid on the plot)");
  schema.integer("nonlinear.newmark_steps_per_mesh_period")
      .min(16)
      .defaultValue(256)
      .doc("Newmark steps per period of the fastest mesh");
  schema.integer("nonlinear.newmark_event_refinement")
      .min(0)
      .max(TrainNonlinearTimeOptions::kMaxEventRefinement)
      .defaultValue(6)
      .doc(
          "halvings of a Newmark step in which the force jumps: a mesh stiffness jumps, a tooth "
          "pair in contact enters or leaves the path of contact (0: fixed steps, first order "
          "there; steps_per_mesh_period x 2^refinement <= 2^19)");
  schema.integer("nonlinear.newmark_contact_refinement")
      .min(0)
      .max(TrainNonlinearTimeOptions::kMaxEventRefinement)
      .defaultValue(0)
      .doc(
          "halvings of a Newmark step in which a contact changes state (only the force's slope "
          "jumps: fixed steps stay second order, refining measured no gain; same bound)");
  schema.integer("nonlinear.newmark_max_periods")
      .min(3)
      .defaultValue(2000)
      .doc("common periods before a check that has not settled is reported");
}

/// [probes]: simulated probe records of the `time` analysis (train_probes_analysis.cpp).
void addProbesSection(config::ConfigSchema& schema) {
  schema.section("probes",
                 "Simulated probe records of the time analysis's steady-state window (x/y at each "
                 "station, then a keyphasor) in the forms `geardyn spectrum` reads. Channel x_i is "
                 "the station's global y translation and y_i its global z translation times the "
                 "sign of its shaft's rotation about x, so that x_i -> y_i turns with the shaft "
                 "and forward whirl (spectrum's probe frame) is the shaft's own rotation sense.");
  schema.stringList("probes.stations")
      .defaultValue(nlohmann::ordered_json::array())
      .doc(
          "probe stations, channels x1, y1, x2, y2, ... in this order: a shaft name (a rigid "
          "shaft's body; not a member of a rotating carrier frame), \"shaft@position\" (a flexible "
          "shaft's node at that position "
          "[m] from its first section start) or a bearing name (its node on its shaft); empty: "
          "no probes. `spectrum` reads two stations: pinion (x1, y1) and gear (x2, y2)");
  schema.string("probes.quantity")
      .choices({"displacement", "velocity", "acceleration"})
      .defaultValue("displacement")
      .doc("what the probes measure [m, m/s, m/s²]");
  schema.integer("probes.mesh_harmonics")
      .min(1)
      .max(50)
      .defaultValue(3)
      .doc(
          "harmonics 1..n of every mesh frequency tracked: the Nyquist check, the default "
          "sample rate and the frequency-domain whirl reported beside the records");
  schema.real("probes.sample_rate")
      .unit("Hz")
      .positive()
      .optional()
      .doc(
          "default: 8 × the highest tracked frequency (n × the fastest mesh frequency), rounded "
          "up to whole Hz (a WAV header holds an integer rate): 8 samples per cycle of the "
          "highest order draw its orbit; the whirl extraction itself needs only > 2×");
  schema.stringList("probes.formats")
      .choices({"csv", "wav", "hdf5"})
      .defaultValue(nlohmann::ordered_json::array({"csv"}))
      .doc("files to write: probes.csv / probes.wav (64-bit float) / probes.h5");
  schema.string("probes.keyphasor")
      .defaultValue("")
      .doc(
          "the shaft whose once-per-revolution pulse (rising through 0.5 at its rigid-body angle "
          "2πk from t = 0) is the last channel; empty: the first station's shaft; \"none\": no "
          "keyphasor");
  schema.real("probes.noise_level")
      .unit("-")
      .min(0.0)
      .max(10.0)
      .defaultValue(0.0)
      .doc("white Gaussian noise in the probe channels: level x std(channel) (not the keyphasor)");
  schema.integer("probes.seed").min(0).defaultValue(1).doc("seed of the probe noise");
}

/// [runup]: Newmark along a linear input-speed ramp with order tracking (train_runup.h).
void addRunUpSection(config::ConfigSchema& schema) {
  schema.section("runup",
                 "Run-up (or run-down) of the train: Newmark integration while the input speed "
                 "follows a linear ramp (every mesh phase the integral of its mesh frequency, the "
                 "speed-dependent matrices refactorised within speed_tolerance), order tracking "
                 "of every mesh order and the input's 1x against the input angle, and a waterfall "
                 "of the first channel.");
  schema.real("runup.speed_min_rpm")
      .unit("rpm")
      .min(0.0)
      .optional()
      .doc("lowest input speed (default: 0.1 × the operating speed)");
  schema.real("runup.speed_max_rpm")
      .unit("rpm")
      .positive()
      .optional()
      .doc(
          "highest input speed (default: 1.5 × the operating speed; equal to speed_min_rpm: a "
          "constant-speed run)");
  schema.string("runup.direction")
      .choices({"up", "down"})
      .defaultValue("up")
      .doc("from speed_min_rpm to speed_max_rpm (up) or back (down)");
  schema.real("runup.duration")
      .unit("s")
      .min(0.0)
      .defaultValue(0.0)
      .doc(
          "ramp time (0: derived so that every resonance the mesh orders pass is swept "
          "quasi-statically: order-line sweep rate <= 4π ζ² f_n² / 5 over the resonances whose "
          "modes hold >= 0.1 % of their strain energy in the meshes, and at least 100 windows)");
  schema.real("runup.window")
      .unit("s")
      .min(0.0)
      .defaultValue(0.0)
      .doc(
          "order-tracking and waterfall window (0: 8 common periods of the meshes but at most 32 "
          "periods of the slowest mesh, and at least one input revolution, at the mean speed; "
          "order tracking lengthens it where the input turns too little to tell the orders "
          "apart and cuts it to whole common periods)");
  schema.real("runup.time_step")
      .unit("s")
      .min(0.0)
      .defaultValue(0.0)
      .doc("Δt (0: the fastest mesh period at the highest speed / steps_per_mesh_period)");
  schema.integer("runup.steps_per_mesh_period").min(8).defaultValue(64).doc("for the default Δt");
  schema.real("runup.speed_tolerance")
      .unit("-")
      .positive()
      .max(0.5)
      .defaultValue(kTrainSpeedTolerance)
      .doc(
          "relative speed change (of the highest speed) after which the gyroscopic and "
          "carrier-frame terms are refactorised");
  schema.integer("runup.mesh_harmonics")
      .min(1)
      .max(10)
      .defaultValue(2)
      .doc("harmonics 1..n of every mesh frequency tracked (and searched for resonances)");
  schema.stringList("runup.channels")
      .defaultValue(nlohmann::ordered_json::array())
      .doc(
          "what is tracked: mesh names (dynamic mesh force [N]) or DOF names such as "
          "\"input.y\", \"output.theta\" (mode_shapes.csv; [m] or [rad]); empty: every mesh");
  schema.string("runup.start")
      .choices({"steady_state", "static", "rest"})
      .defaultValue("steady_state")
      .doc(
          "initial state: the periodic steady state at the first speed (frequency domain: no "
          "start transient; the static deflection when the common period is too long for "
          "it), the static deflection there, or rest");
}

/// gearbox.file, .load_case and .all_load_cases: which gearbox the analyses run on.
void addGearboxFileKeys(config::ConfigSchema& schema) {
  schema.string("gearbox.file")
      .optional()
      .doc(
          "the gearbox description file, relative to this file (absent: the gearbox sections are "
          "in this file)");
  schema.integer("gearbox.load_case")
      .min(0)
      .optional()
      .doc(
          "with a REXS gearbox file (.rexs, .rexsj, .rexsz): the REXS id of the load case that "
          "becomes the operating point (default: the first)");
  schema.boolean("gearbox.all_load_cases")
      .defaultValue(false)
      .doc(
          "with a REXS gearbox file: run the analyses at every load case of its spectrum, each "
          "into <out>/load_case_<id>/");
}

/// [contact]: system deflection with the loaded tooth contact across the face.
void addContactSection(config::ConfigSchema& schema) {
  schema.section("contact",
                 "System deflection coupled with the loaded tooth contact across the face of every "
                 "external mesh (full DOFs): misalignment, load distribution, K_Hbeta, loaded STE; "
                 "also what meshes with excitation = \"ltca\" take (issue 36).");
  schema.integer("contact.slices").min(1).max(10000).defaultValue(40).doc("face slices per pair");
  schema.integer("contact.positions")
      .min(8)
      .max(100000)
      .defaultValue(64)
      .doc("mesh positions per mesh period");
  schema.integer("contact.harmonics")
      .min(1)
      .max(1000)
      .defaultValue(8)
      .doc("loaded-STE mesh harmonics reported (< positions / 2)");
  schema.real("contact.tolerance")
      .unit("-")
      .positive()
      .lessThan(1.0)
      .defaultValue(1e-4)
      .doc("fixed point: every mesh's centre of load moves by less than this × its face width");
  schema.integer("contact.max_iterations")
      .min(1)
      .max(10000)
      .defaultValue(50)
      .doc("deflection <-> load distribution iterations at most");
  schema.realList("contact.load_factors")
      .unit("-")
      .defaultValue(nlohmann::ordered_json::array({0.25, 0.5, 0.75, 1.0, 1.25, 1.5}))
      .doc(
          "load cases as multiples of the operating torque, each coupled anew: K_Hbeta and the "
          "loaded STE harmonics against load (contact_load_cases.csv); empty: none");
}

/// [modal] and [campbell].
void addModalSections(config::ConfigSchema& schema) {
  schema.section("modal", "Modes at one speed.");
  schema.integer("modal.modes").min(0).defaultValue(0).doc("lowest modes reported (0: all)");
  schema.real("modal.speed_rpm")
      .unit("rpm")
      .optional()
      .doc("input speed (default: the operating point's)");
  schema.section("campbell", "Modes over a speed range, tracked by MAC; critical speeds.");
  addSpeedRange(schema, "campbell", 101, "0");
  schema.integer("campbell.modes").min(1).defaultValue(12).doc("tracked modes");
  schema.integer("campbell.mesh_harmonics")
      .min(1)
      .max(20)
      .defaultValue(3)
      .doc("mesh-order lines 1× … n× of every mesh frequency");
}

/// [forced]: the frequency-domain steady state over a speed range (common period or torus).
void addForcedSection(config::ConfigSchema& schema) {
  schema.section("forced", "Frequency-domain steady state over a speed range (gear whine).");
  addSpeedRange(schema, "forced", 200, "0.1 × the operating speed");
  schema.integer("forced.mesh_harmonics")
      .min(1)
      .max(200)
      .optional()
      .doc(
          "harmonics of each mesh frequency in the balance (default: derived per mesh, the "
          "smallest number whose neglected mesh-force orders, estimated by each mesh's own "
          "balance with the train's dynamic compliance at the mesh, stay below 1e-3 of the "
          "largest at every speed; solvers/train_truncation.h)");
  schema.integer("forced.max_base_harmonics")
      .min(1)
      .defaultValue(4000)
      .doc("refuse trains whose common period needs more harmonics (use time)");
  schema.string("forced.method")
      .choices({"auto", "common_period", "torus"})
      .defaultValue("auto")
      .doc(
          "balance over the meshes' common period, or on the torus of their phases (one "
          "generator per group of meshes with a short common period); auto: the torus when the "
          "common period needs more than forced.torus_above harmonics");
  schema.integer("forced.torus_above")
      .min(1)
      .defaultValue(100)
      .doc(
          "base harmonics (mesh_harmonics × the largest mesh multiple of the base) above which "
          "auto uses the torus; also the most one generator's group of meshes may need");
  schema.string("forced.torus_truncation")
      .choices({"auto", "box", "diamond", "product"})
      .defaultValue("auto")
      .doc(
          "torus tones kept: box |n_j| <= N_j (every sideband of every kept mesh order), "
          "diamond Σ|n_j|/N_j <= 1 (fewer tones for three or more generators), or product: the "
          "box's tones whose estimated relative amplitude Π_j a_j(|n_j|) (the derived "
          "truncation's orders) is >= forced.torus_floor; auto: product when mesh_harmonics is "
          "derived, else box");
  schema.real("forced.torus_floor")
      .min(1e-12)
      .max(0.5)
      .defaultValue(1e-2)
      .doc("product truncation: the smallest estimated relative amplitude of a tone kept");
}

/// [time] (Newmark at one speed) and [stats] (mesh statistics of its record).
void addTimeAndStatsSections(config::ConfigSchema& schema) {
  schema.section("time", "Newmark time response at one speed to the periodic steady state.");
  schema.real("time.speed_rpm").unit("rpm").optional().doc("input speed (default: operating)");
  schema.real("time.duration")
      .unit("s")
      .min(0.0)
      .defaultValue(0.0)
      .doc(
          "simulated time (0: until every mode the meshes or the other excitations "
          "(unbalances, runouts, bearing excitations) excite has decayed by 1e-6, then the "
          "window; undamped modes they do not excite are not waited for; "
          "solvers/train_transient.h)");
  schema.real("time.time_step")
      .unit("s")
      .min(0.0)
      .defaultValue(0.0)
      .doc(
          "Δt (0: the fastest mesh period / steps_per_mesh_period; a train without meshes: "
          "the period of its fastest excitation order, e.g. an unbalance's 1x)");
  schema.integer("time.steps_per_mesh_period").min(8).defaultValue(128).doc("for the default Δt");
  schema.string("time.method")
      .choices({"newmark", "dormand_prince"})
      .defaultValue("newmark")
      .doc(
          "newmark: fixed step Δt, any train; dormand_prince: error-controlled Dormand–Prince 5(4) "
          "sampled at the same times (linear trains: no backlash, clearances or rolling bearings; "
          "constant speed)");
  schema.real("time.relative_tolerance")
      .min(1e-14)
      .max(1e-2)
      .defaultValue(1e-8)
      .doc("dormand_prince: relative (and absolute, in units of the response) tolerance");
  schema.integer("time.record_periods")
      .min(1)
      .max(1000)
      .defaultValue(2)
      .doc("common periods recorded at the end");
  schema.integer("time.history_stride")
      .min(1)
      .max(1000000)
      .defaultValue(1)
      .doc(
          "time_history.csv keeps every n-th recorded step (the comparisons, statistics and "
          "probes use every step)");
  schema.boolean("time.start_from_static")
      .defaultValue(true)
      .doc("start from the static deflection (else from rest)");
  schema.integer("time.mesh_harmonics")
      .min(1)
      .max(200)
      .defaultValue(20)
      .doc("harmonics of the frequency-domain steady state it is compared with");
  schema.section("stats",
                 "Gelman's (2005) mean excitation ratio R and the statistics of the dynamic mesh "
                 "force and transmission error at every mesh, from a Newmark run with the [time] "
                 "options (speed, steps, record).");
  schema.real("stats.design_torque")
      .unit("N m")
      .optional()
      .doc(
          "input torque the profile modifications were designed for: each mesh's baseload F₀ is "
          "its static force at this torque (default: the operating torque, a = 1)");
}

}  // namespace

config::ConfigSchema trainSchema(bool inline_gearbox) {
  config::ConfigSchema schema(
      "train",
      "Any gear train (shafts, gears, meshes, bearings, couplings, planetary stages): kinematics "
      "and mesh phasing, static load sharing, modal analysis with Lin & Parker mode types, "
      "Campbell diagram with critical speeds of every shaft and mesh order, frequency-domain "
      "forced response (linear harmonic balance over the common period), Newmark time "
      "response with the time-varying stiffness of every mesh, and the nonlinear steady state "
      "with contact loss and backlash at every mesh (harmonic balance condensed on the mesh "
      "deflections, continuation with folds and stability).");
  if (inline_gearbox) {
    addGearboxSections(schema);
  } else {
    schema.section("gearbox", "The gearbox this analysis is run on.");
  }
  addGearboxFileKeys(schema);
  schema.section("analysis", "What to run.");
  schema.stringList("analysis.run")
      .choices({"static", "contact", "modal", "campbell", "forced", "time", "runup", "nonlinear",
                "stats"})
      .defaultValue(nlohmann::ordered_json::array({"static", "modal"}))
      .doc("analyses, in any combination");
  addContactSection(schema);
  addModalSections(schema);
  addForcedSection(schema);
  addTimeAndStatsSections(schema);
  addProbesSection(schema);
  addRunUpSection(schema);
  addNonlinearSection(schema);
  config::addOutputSection(schema);
  return schema;
}

}  // namespace geardyn::config

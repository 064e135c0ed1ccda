/// Rao's lateral rotor as the fast path of a gearbox of its form (lateral_rotor_reduction.h).

#include "geardyn/system/lateral_rotor_reduction.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <map>
#include <numbers>
#include <numeric>
#include <optional>
#include <tuple>

#include "geardyn/error.h"
#include "geardyn/units.h"

namespace geardyn {
namespace {

using Phasor = std::complex<double>;
constexpr double kHalfPi = 0.5 * std::numbers::pi;
/// Runouts stated in three places agree to this fraction of their size (lateral_rotor_reduction.h).
constexpr double kAgreement = 1e-9;

/// The y and z phasors a cos(ν α + ϕ) ↦ a e^{iϕ} of one spring's excitations at one order.
struct Excitation {
  Phasor y, z;
};

/// The two springs' excitations summed per (spring, reference shaft, order); the mesh spring's
/// signed as pinion minus gear.
struct SpringExcitations {
  std::map<std::tuple<std::string, std::string, double>, Excitation> by_order;
  double mean_y = 0.0, mean_z = 0.0;  ///< the mesh spring's constant part [m]
};

/// A runout's offset e (cos ϕ, ...) from the phasor of its y component, e e^{i(ϕ + shift)}.
struct Offset {
  double amplitude = 0.0, phase = 0.0;
};

Offset offsetOf(Phasor y, double shift) {
  return {std::abs(y), std::arg(y) - shift};
}

/// Empty when e_a e^{iϕ_a} = e_b e^{iϕ_b} to kAgreement of the larger; else what differs.
std::string differs(const Offset& a, const Offset& b, const std::string& what) {
  const Phasor pa = std::polar(a.amplitude, a.phase), pb = std::polar(b.amplitude, b.phase);
  const double scale = std::max(a.amplitude, b.amplitude);
  if (std::abs(pa - pb) <= kAgreement * scale) return "";
  return fmt::format("{}: {:.6g} m at {:.6g} deg against {:.6g} m at {:.6g} deg", what, a.amplitude,
                     a.phase * 180.0 / std::numbers::pi, b.amplitude,
                     b.phase * 180.0 / std::numbers::pi);
}

const TrainShaftSpec* shaftNamed(const GearTrainSpec& t, const std::string& name) {
  for (const auto& s : t.shafts)
    if (s.name == name) return &s;
  return nullptr;
}

/// Why a spring is not an isotropic linear spring in y and z only (empty: it is).
std::string notIsotropic(const TrainBearingSpec& b) {
  if (b.kyy != b.kzz || b.cyy != b.czz || b.kyz != 0.0 || b.kzy != 0.0 || b.cyz != 0.0 ||
      b.czy != 0.0) {
    return fmt::format("bearings.{} is not isotropic (kyy = kzz, cyy = czz, no cross terms)",
                       b.name);
  }
  if (b.k_torsion != 0.0 || b.c_torsion != 0.0 || b.k_axial != 0.0 || b.k_tilt != 0.0 ||
      b.radial_clearance != 0.0 || b.rolling || b.full_law || b.nonlinear_law) {
    return fmt::format("bearings.{} is more than a linear lateral spring", b.name);
  }
  return "";
}

/// The parts' shape: two rigid shafts, one ratio, three isotropic springs. Fills the masses,
/// springs, gravity and speed of `s`; `ratio` = |ω_g/ω_p|.
std::string readStructure(const GearTrainSpec& t, LateralRotorSpec& s, double& ratio) {
  if (t.dofs != TrainDofs::kPlanar) {
    return fmt::format("gearbox.dofs = \"{}\": the lateral rotor is planar", toString(t.dofs));
  }
  if (!t.gears.empty() || !t.meshes.empty() || !t.stages.empty()) {
    return "gears or meshes: the lateral rotor's mesh is an isotropic spring between the shafts";
  }
  if (!t.disks.empty() || !t.runouts.empty() || t.housing) {
    return "disks, gear runouts or a housing: the lateral rotor has none";
  }
  if (t.mass_proportional_damping != 0.0 || t.stiffness_proportional_damping != 0.0) {
    return "gearbox Rayleigh damping: the lateral rotor's damping is its dashpots";
  }
  const std::string& p = t.operating.input_shaft;
  const std::string& g = t.operating.output_shaft;
  const TrainShaftSpec* pinion = shaftNamed(t, p);
  const TrainShaftSpec* gear = shaftNamed(t, g);
  if (t.shafts.size() != 2 || !pinion || !gear || p == g) {
    return fmt::format(
        "{} shafts: the lateral rotor has two, the operating input (pinion) and "
        "output (gear)",
        t.shafts.size());
  }
  for (const auto* shaft : {pinion, gear}) {
    if (shaft->flexible || !shaft->section_lengths.empty()) {
      return fmt::format("shafts.{} has sections: the lateral rotor's shafts are springs",
                         shaft->name);
    }
  }
  if (t.couplings.size() != 1) {
    return fmt::format("{} couplings: the lateral rotor has the gear ratio only",
                       t.couplings.size());
  }
  const TrainCouplingSpec& c = t.couplings[0];
  if (c.k_lateral != 0.0 || c.c_lateral != 0.0 || c.ratio == 0.0 ||
      !((c.shaft_a == p && c.shaft_b == g) || (c.shaft_a == g && c.shaft_b == p))) {
    return fmt::format(
        "couplings.{} is not a gear ratio between {} and {} without lateral "
        "stiffness",
        c.name, p, g);
  }
  ratio = std::abs(c.shaft_a == p ? c.ratio : 1.0 / c.ratio);
  if (c.ratio > 0.0) {
    return fmt::format("couplings.{}.ratio = {}: an external pair turns the gear the other way",
                       c.name, c.ratio);
  }
  if (t.operating.input_speed >= 0.0) {
    return "operating_point.speed_rpm >= 0: the lateral rotor's pinion turns about -x";
  }
  s.pinion_mass = pinion->mass;
  s.gear_mass = gear->mass;
  s.gravity = t.gravity;
  // Undone in the order the gearbox reading did it (speed_rpm × kRpm): a round number of rpm
  // comes back exactly, so the rotor's sampling (common period × samples) is the file's.
  s.pinion_speed = -t.operating.input_speed / units::kRpm / 60.0;
  if (t.bearings.size() != 3) {
    return fmt::format("{} bearings: the lateral rotor has a spring per shaft and the mesh's",
                       t.bearings.size());
  }
  int found = 0;
  for (const auto& b : t.bearings) {
    if (std::string why = notIsotropic(b); !why.empty()) return why;
    const bool between = !b.other_shaft.empty();
    if (between && ((b.shaft == p && b.other_shaft == g) || (b.shaft == g && b.other_shaft == p))) {
      s.mesh_stiffness = b.kyy, s.mesh_damping = b.cyy, found |= 1;
    } else if (!between && b.shaft == p) {
      s.pinion_shaft_stiffness = b.kyy, s.pinion_shaft_damping = b.cyy, found |= 2;
    } else if (!between && b.shaft == g) {
      s.gear_shaft_stiffness = b.kyy, s.gear_shaft_damping = b.cyy, found |= 4;
    }
  }
  if (found != 7) {
    return "bearings: the lateral rotor has one spring from each shaft to the housing and one "
           "between them";
  }
  return "";
}

/// The excitations summed per spring, reference and order (bearing names replaced by "mesh",
/// "pinion", "gear"; the mesh spring's made pinion minus gear).
std::string readExcitations(const GearTrainSpec& t, SpringExcitations& out) {
  const std::string& p = t.operating.input_shaft;
  const std::string& g = t.operating.output_shaft;
  for (const auto& e : t.bearing_excitations) {
    std::string spring;
    double sign = 1.0;
    for (const auto& b : t.bearings) {
      if (b.name != e.bearing) continue;
      spring = !b.other_shaft.empty() ? "mesh" : (b.shaft == p ? "pinion" : "gear");
      if (!b.other_shaft.empty() && b.shaft == g) sign = -1.0;
    }
    if (e.reference != p && e.reference != g) {
      return fmt::format(
          "bearing_excitations.{}.reference = \"{}\": the lateral rotor's "
          "excitations are orders of a shaft",
          e.name, e.reference);
    }
    if (spring != "mesh" && (e.mean_y != 0.0 || e.mean_z != 0.0)) {
      return fmt::format("bearing_excitations.{}: a mean offset of a shaft's spring", e.name);
    }
    if (spring == "mesh") out.mean_y += sign * e.mean_y, out.mean_z += sign * e.mean_z;
    const std::string shaft = e.reference == p ? "pinion" : "gear";
    for (std::size_t i = 0; i < e.orders.size(); ++i) {
      Excitation& x = out.by_order[{spring, shaft, e.orders[i]}];
      x.y += sign * std::polar(e.amplitude_y[i], e.phase_y[i]);
      x.z += sign * std::polar(e.amplitude_z[i], e.phase_z[i]);
    }
  }
  return "";
}

/// A runout from its three places: the shaft spring's −w, the mesh spring's ±w and the
/// unbalance m e. `pinion`: −w_p on both springs, (y, z) phases (ϕ + 180°, ϕ − 90°), unbalance
/// at −ϕ; the gear: +w_g on the mesh (ϕ, ϕ − 90°), −w_g on its spring (ϕ + 180°, ϕ + 90°),
/// unbalance at ϕ.
std::string readRunout(const GearTrainSpec& t, const SpringExcitations& x, bool pinion, double mass,
                       double& amplitude, double& phase) {
  const std::string shaft = pinion ? "pinion" : "gear";
  const std::string& name = pinion ? t.operating.input_shaft : t.operating.output_shaft;
  const auto at = [&](const std::string& spring) {
    const auto it = x.by_order.find({spring, shaft, 1.0});
    return it == x.by_order.end() ? Excitation{} : it->second;
  };
  const Excitation own = at(shaft), mesh = at("mesh");
  const Offset w = offsetOf(own.y, std::numbers::pi);
  amplitude = w.amplitude;
  phase = w.phase;
  const double z_shift = pinion ? -kHalfPi : kHalfPi;
  const Offset in_z = offsetOf(own.z, z_shift);
  const Offset on_mesh = offsetOf(mesh.y, pinion ? std::numbers::pi : 0.0);
  const Offset on_mesh_z = offsetOf(mesh.z, -kHalfPi);
  Offset unbalance;
  for (const auto& u : t.unbalances) {
    if (u.shaft != name) continue;
    const Phasor sum = std::polar(unbalance.amplitude, unbalance.phase) +
                       std::polar(u.mass_eccentricity / mass, pinion ? -u.phase : u.phase);
    unbalance = {std::abs(sum), std::arg(sum)};
  }
  for (const auto& why :
       {differs(in_z, w,
                fmt::format("the {} runout in z on bearing of {} against in y", shaft, name)),
        differs(on_mesh, w,
                fmt::format("the {} runout on the mesh spring against on its own", shaft)),
        differs(on_mesh_z, w, fmt::format("the {} runout on the mesh spring in z", shaft)),
        differs(unbalance, w,
                fmt::format("unbalances of {} (m e / m) against its runout", name))}) {
    if (!why.empty()) return "runouts are stated once in three places (eq. 2.3); " + why;
  }
  return "";
}

/// The TE: the mesh spring's orders of the pinion other than 1, at i t_p; fills the teeth.
std::string readTransmissionError(const SpringExcitations& x, double ratio, LateralRotorSpec& s) {
  std::vector<std::pair<double, Excitation>> te;
  for (const auto& [key, e] : x.by_order) {
    const auto& [spring, shaft, order] = key;
    if (order == 1.0) continue;  // the runouts (readRunout)
    if (spring != "mesh" || shaft != "pinion") {
      return fmt::format(
          "an excitation at order {} of the {} on the {} spring: the lateral "
          "rotor's are the runouts (order 1) and the TE (the pinion's on the mesh)",
          order, shaft, spring);
    }
    te.emplace_back(order, e);
  }
  if (x.mean_y != x.mean_z) {
    return fmt::format("the mean TE in y ({} m) and z ({} m) differ: the model has one e_m",
                       x.mean_y, x.mean_z);
  }
  s.mean_te = x.mean_y;
  // t_p: the smallest TE order; without harmonics the ratio's smallest integers.
  int tp = 0;
  if (!te.empty()) {
    tp = static_cast<int>(std::lround(te.front().first));
  } else {
    for (int n = 1; n <= 10000 && tp == 0; ++n)
      if (std::abs(n / ratio - std::round(n / ratio)) <= 1e-9 * n / ratio) tp = n;
  }
  const int tg = static_cast<int>(std::lround(tp / ratio));
  if (tp < 1 || tg < 1 || std::abs(static_cast<double>(tp) / tg - ratio) > 1e-12 * ratio) {
    return fmt::format("the TE orders and the gear ratio {} give no tooth numbers", ratio);
  }
  s.pinion_teeth = tp, s.gear_teeth = tg;
  s.te_x.clear(), s.te_y.clear();
  // A TE of zero amplitudes only states t_p (config/rotor_gearbox.cpp): no harmonics.
  if (std::all_of(te.begin(), te.end(),
                  [](const auto& h) { return h.second.y == Phasor{} && h.second.z == Phasor{}; })) {
    return "";
  }
  for (const auto& [order, e] : te) {
    const double i = order / tp;
    if (std::abs(i - std::round(i)) > 1e-12 * i) {
      return fmt::format("the TE order {} is not a multiple of t_p = {}", order, tp);
    }
    const auto index = static_cast<std::size_t>(std::lround(i));
    s.te_x.resize(std::max(s.te_x.size(), index)), s.te_y.resize(std::max(s.te_y.size(), index));
    // a sin(θ + ϕ) = a cos(θ + ϕ − 90°): ϕ = arg + 90°.
    s.te_x[index - 1] = {std::abs(e.y), std::arg(e.y) + kHalfPi};
    s.te_y[index - 1] = {std::abs(e.z), std::arg(e.z) + kHalfPi};
  }
  return "";
}

std::string reduce(const GearTrainSpec& t, LateralRotorSpec& s) {
  double ratio = 1.0;
  if (std::string why = readStructure(t, s, ratio); !why.empty()) return why;
  SpringExcitations x;
  if (std::string why = readExcitations(t, x); !why.empty()) return why;
  for (const auto& u : t.unbalances) {
    if (u.shaft != t.operating.input_shaft && u.shaft != t.operating.output_shaft) {
      return fmt::format("unbalances.{}: on a shaft the lateral rotor does not have", u.name);
    }
  }
  if (std::string why =
          readRunout(t, x, true, s.pinion_mass, s.pinion_runout, s.pinion_runout_phase);
      !why.empty()) {
    return why;
  }
  if (std::string why = readRunout(t, x, false, s.gear_mass, s.gear_runout, s.gear_runout_phase);
      !why.empty()) {
    return why;
  }
  return readTransmissionError(x, ratio, s);
}

}  // namespace

std::string lateralRotorReductionObstacle(const GearTrainSpec& train) {
  LateralRotorSpec ignored;
  return reduce(train, ignored);
}

LateralRotorSpec lateralRotorReduction(const GearTrainSpec& train) {
  LateralRotorSpec s;
  if (const std::string why = reduce(train, s); !why.empty()) {
    throw InputError("gearbox", "(a gear train)",
                     "a gearbox of the lateral rotor's form (geardyn rotor --print-gearbox) to "
                     "reduce to it; found " +
                         why);
  }
  s.validate();
  return s;
}

}  // namespace geardyn

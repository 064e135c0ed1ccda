/// The gearbox Rao's lateral geared rotor is (rotor_gearbox.h).

#include "geardyn/config/rotor_gearbox.h"

#include <fmt/format.h>

#include <numbers>

#include "geardyn/config/detail/toml_text.h"
#include "geardyn/config/gearbox_config.h"
#include "geardyn/config/rotor_config.h"

namespace geardyn::config {
namespace {

constexpr double kDegPerRad = 180.0 / std::numbers::pi;

using detail::tomlReal;
using detail::tomlReals;

/// One [bearing_excitations.<name>] table: `orders` of `reference` with amplitudes and phases
/// [rad] per direction.
void addExcitation(std::string& out, const std::string& name, const std::string& bearing,
                   const std::string& reference, const std::vector<double>& orders,
                   const std::vector<double>& ay, const std::vector<double>& py,
                   const std::vector<double>& az, const std::vector<double>& pz,
                   const std::string& comment, double mean = 0.0) {
  auto degrees = [](std::vector<double> v) {
    for (double& a : v) a *= kDegPerRad;
    return v;
  };
  out += fmt::format("\n[bearing_excitations.{}]   # {}\n", name, comment);
  out += fmt::format("bearing = \"{}\"\nreference = \"{}\"\n", bearing, reference);
  if (mean != 0.0) out += fmt::format("mean_y = {0}   # m\nmean_z = {0}   # m\n", tomlReal(mean));
  out += fmt::format("orders = {}\n", tomlReals(orders));
  out += fmt::format("amplitude_y = {}   # m\nphase_y_deg = {}\n", tomlReals(ay),
                     tomlReals(degrees(py)));
  out += fmt::format("amplitude_z = {}   # m\nphase_z_deg = {}\n", tomlReals(az),
                     tomlReals(degrees(pz)));
}

}  // namespace

std::string lateralRotorGearboxToml(const LateralRotorSpec& s, const std::string& source) {
  s.validate();
  const double pi = std::numbers::pi, half = 0.5 * pi;
  std::string out = fmt::format(
      "# The gearbox of {} (`geardyn rotor --print-gearbox`): Rao's lateral geared rotor\n"
      "# (thesis Fig. 2.1) as a gearbox description (docs/theory/lateral_rotor.md, \"The\n"
      "# gearbox it is\"). Thesis axes (x, y, z) are the gearbox's (y, z, x).\n",
      source);
  out += "\n[gearbox]\nname = \"rao_lateral_rotor\"\ndofs = \"planar\"\n";
  out += fmt::format("gravity = {}   # m/s^2, along -z (the thesis's -y)\n", tomlReal(s.gravity));
  for (const auto& [name, mass] : {std::pair{"pinion", s.pinion_mass}, {"gear", s.gear_mass}}) {
    out += fmt::format("\n[shafts.{}]\nmass = {}   # kg, m at the gear centre\n", name,
                       tomlReal(mass));
    out += "polar_inertia = 1e-3   # kg m^2, keeps the (uncoupled) rotation regular\n";
  }
  out += fmt::format(
      "\n[couplings.gear_ratio]   # the gear turns at -t_p/t_g of the pinion: a ratio, no mesh\n"
      "shafts = [\"pinion\", \"gear\"]\nk_torsion = 1.0   # N m/rad, rotations only\n"
      "c_torsion = 0.1   # N m s/rad, over-damps that rotation mode (no resonance)\n"
      "ratio = {}\n",
      tomlReal(-static_cast<double>(s.pinion_teeth) / s.gear_teeth));
  const auto bearing = [&](const std::string& name, const std::string& shaft,
                           const std::string& other, double k, double c, const char* what) {
    out += fmt::format("\n[bearings.{}]   # {}\nshaft = \"{}\"\n", name, what, shaft);
    if (!other.empty()) out += fmt::format("other_shaft = \"{}\"\n", other);
    out += fmt::format("kyy = {0}   # N/m\nkzz = {0}\ncyy = {1}   # N s/m\nczz = {1}\n",
                       tomlReal(k), tomlReal(c));
  };
  bearing("pinion_shaft", "pinion", "", s.pinion_shaft_stiffness, s.pinion_shaft_damping,
          "the pinion shaft's lateral stiffness k_s1, c_s1");
  bearing("gear_shaft", "gear", "", s.gear_shaft_stiffness, s.gear_shaft_damping,
          "the gear shaft's k_s2, c_s2");
  bearing("mesh", "pinion", "gear", s.mesh_stiffness, s.mesh_damping,
          "the thesis's mesh: k_m, c_m in x and in y");
  // Transmission error e = e_m + Σ a_i sin(i ω_e t + ϕ_i), ω_e = t_p ω_p (eqs. 2.8–2.9).
  std::vector<double> orders, ax, px, ay, py;
  for (std::size_t i = 0; i < s.te_x.size(); ++i) {
    orders.push_back(static_cast<double>((i + 1) * s.pinion_teeth));
    ax.push_back(s.te_x[i].amplitude), px.push_back(s.te_x[i].phase - half);
    ay.push_back(s.te_y[i].amplitude), py.push_back(s.te_y[i].phase - half);
  }
  if (orders.empty()) {
    // No TE harmonics: the order t_p at zero amplitude still states the pinion's teeth, which
    // the ratio alone does not (20/40 is 1/2; system/lateral_rotor_reduction.h).
    orders = {static_cast<double>(s.pinion_teeth)}, ax = ay = {0.0}, px = py = {-half};
  }
  addExcitation(out, "transmission_error", "mesh", "pinion", orders, ax, px, ay, py,
                "e_m + sum a sin(i t_p w_p t + phi) = cos(... - 90 deg), eqs. 2.8-2.9", s.mean_te);
  const double ep = s.pinion_runout, eg = s.gear_runout;
  const double fp = s.pinion_runout_phase, fg = s.gear_runout_phase;
  // −w_p = e_p (−cos φ_p, sin φ_p) = e_p (cos(φ_p + 180°), cos(φ_p − 90°)); w_g, −w_g likewise.
  addExcitation(out, "mesh_pinion_runout", "mesh", "pinion", {1.0}, {ep}, {fp + pi}, {ep},
                {fp - half}, "-w_p across the mesh (eq. 2.3)");
  addExcitation(out, "mesh_gear_runout", "mesh", "gear", {1.0}, {eg}, {fg}, {eg}, {fg - half},
                "+w_g across the mesh");
  addExcitation(out, "pinion_runout", "pinion_shaft", "pinion", {1.0}, {ep}, {fp + pi}, {ep},
                {fp - half}, "-w_p: the shaft acts on the gear centre");
  addExcitation(out, "gear_runout", "gear_shaft", "gear", {1.0}, {eg}, {fg + pi}, {eg}, {fg + half},
                "-w_g");
  // −M ẅ: m e ω² along the offset; the pinion's turns about −x (ψ = −φ_p).
  out += fmt::format(
      "\n[unbalances.pinion_runout]   # m_1 e_p: the -M w'' of the pinion's centre\n"
      "shaft = \"pinion\"\nmass_eccentricity = {}   # kg m\nphase_deg = {}\n",
      tomlReal(s.pinion_mass * ep), tomlReal(-fp * kDegPerRad));
  out += fmt::format(
      "\n[unbalances.gear_runout]   # m_2 e_g\nshaft = \"gear\"\nmass_eccentricity = {}   # kg "
      "m\nphase_deg = {}\n",
      tomlReal(s.gear_mass * eg), tomlReal(fg * kDegPerRad));
  out += fmt::format(
      "\n[operating_point]\ninput = \"pinion\"\noutput = \"gear\"\n"
      "speed_rpm = {}   # the pinion turns about -x\ntorque = 0.0\n",
      tomlReal(-60.0 * s.pinion_speed));
  return out;
}

std::string lateralRotorGearbox(const Config& config) {
  return lateralRotorGearboxToml(lateralRotorSpecFromConfig(config), config.source());
}

GearTrainSpec lateralRotorGearTrain(const LateralRotorSpec& spec, const std::string& source,
                                    std::vector<std::string>& warnings) {
  const Config gearbox = parseConfig(lateralRotorGearboxToml(spec, source),
                                     source + " (as a gearbox)", gearboxSchema());
  return gearTrainFromConfig(gearbox, warnings);
}

std::vector<int> lateralRotorProbeDofs(const GearTrainModel& train) {
  std::vector<int> dofs;
  for (const char* name : {"pinion", "gear"}) {
    const int y = train.translationDof(train.bodyIndex(name));
    dofs.push_back(y);
    dofs.push_back(y + 1);
  }
  return dofs;
}

}  // namespace geardyn::config

/// The gearbox a gear-pair file is (config/gear_pair_gearbox.h).

#include "geardyn/config/gear_pair_gearbox.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "geardyn/config/detail/toml_text.h"
#include "geardyn/config/gear_pair_keys.h"
#include "geardyn/config/gearbox_config.h"
#include "geardyn/config/geometry_config.h"
#include "geardyn/error.h"
#include "geardyn/geometry/gear_pair.h"
#include "geardyn/stiffness/fourier_stiffness.h"
#include "geardyn/stiffness/step_stiffness.h"
#include "geardyn/stiffness/tabulated_stiffness.h"
#include "geardyn/system/gear_train_model.h"
#include "geardyn/system/sdof_reduction.h"
#include "geardyn/units.h"

namespace geardyn::config {
namespace {

using Json = nlohmann::ordered_json;
constexpr double kDeg = geardyn::units::kDegree;

/// The nominal spur pair of a file without gear geometry: it only sets the base radii (which
/// the inertias compensate) and the teeth (which the speed compensates).
constexpr int kNominalTeeth = 25;
constexpr double kNominalModule = 3e-3;          // [m]
constexpr double kNominalPressureAngleDeg = 20;  // [deg]
constexpr double kNominalFaceWidth = 20e-3;      // [m]

using detail::tomlReal;
using detail::tomlReals;

/// A TOML basic string: quotes, backslashes and control characters escaped.
std::string quoted(const std::string& text) {
  std::string s = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      s += '\\';
      s += c;
    } else if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
      s += fmt::format("\\u{:04x}", static_cast<unsigned char>(c));
    } else {
      s += c;
    }
  }
  return s + "\"";
}

/// A resolved configuration value as TOML (numbers keep their integer/float kind).
std::string value(const Json& v) {
  if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
  if (v.is_number_integer()) return fmt::format("{}", v.get<long long>());
  if (v.is_number()) return tomlReal(v.get<double>());
  if (v.is_string()) return quoted(v.get<std::string>());
  std::string s = "[";
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + value(v[i]);
  return s + "]";
}

/// The plain keys of a resolved table, one "key = value" line each (sub-tables left out).
std::string keys(const Json& table) {
  std::string s;
  for (const auto& [key, v] : table.items()) {
    if (!v.is_object() && !v.is_null()) s += fmt::format("{} = {}\n", key, value(v));
  }
  return s;
}

/// The resolved table at a dotted path, or null.
const Json* tableAt(const Config& config, const std::string& path) {
  const Json* node = &config.resolved();
  std::size_t begin = 0;
  while (node) {
    const std::size_t end = path.find('.', begin);
    const std::string part = path.substr(begin, end - begin);
    node = node->is_object() && node->contains(part) ? &(*node)[part] : nullptr;
    if (end == std::string::npos) break;
    begin = end + 1;
  }
  return node;
}

/// [mesh_stiffness.<model>] tables of the file, copied (the gear-based models read them).
std::string meshStiffnessTables(const Config& config, const std::string& prefix) {
  std::string s;
  const Json* table = tableAt(config, prefix);
  if (!table || !table->is_object()) return s;
  for (const auto& [key, v] : table->items()) {
    if (!v.is_object()) continue;
    s += fmt::format("\n[{}.{}]\n{}", prefix, key, keys(v));
    for (const auto& [sub, w] : v.items()) {
      if (w.is_object()) s += fmt::format("\n[{}.{}.{}]\n{}", prefix, key, sub, keys(w));
    }
  }
  return s;
}

/// A helical pair: its gearbox mesh acts along the contact normal.
bool helical(const Config& config) {
  return hasGearPair(config) && (config.real("pinion.helix_angle_deg") != 0.0 ||
                                 config.real("gear.helix_angle_deg") != 0.0);
}

GearSpec nominalGear() {
  GearSpec g;
  g.teeth = kNominalTeeth;
  g.normal_module = kNominalModule;
  g.normal_pressure_angle = kNominalPressureAngleDeg * kDeg;
  g.face_width = kNominalFaceWidth;
  return g;
}

/// The mesh's stiffness keys; the [mesh_stiffness.*] tables they need go to `tables`.
std::string stiffnessKeys(const Config& config, const GearPairKeys& k, std::string& tables) {
  std::string t;
  const MeshStiffness* given = k.numeric_stiffness.get();
  if (const auto* f = dynamic_cast<const FourierMeshStiffness*>(given)) {
    std::vector<double> phases_deg;
    for (double p : f->phases()) phases_deg.push_back(p / kDeg);
    t += "stiffness = \"fourier\"  # k = k0 (1 + sum s_i cos(2 pi i phi - phi_i))\n";
    tables = fmt::format(
        "\n[mesh_stiffness.fourier]\nfit = \"given\"\nmean = \"given\"\nmean_value = {}  # "
        "[N/m]\namplitudes = {}\nphases_deg = {}\ncontact_ratio = {}\n",
        tomlReal(f->mean()), tomlReals(f->relativeAmplitudes()), tomlReals(phases_deg),
        tomlReal(f->contactRatio()));
  } else if (const auto* step = dynamic_cast<const StepMeshStiffness*>(given)) {
    t += "stiffness = \"step\"\n";
    tables = fmt::format(
        "\n[mesh_stiffness.step]\nlevels = \"given\"\nk_min = {}  # [N/m]\nk_max = {}  # "
        "[N/m]\ncontact_ratio = {}\n",
        tomlReal(step->kMin()), tomlReal(step->kMax()), tomlReal(step->contactRatio()));
  } else if (k.linearised) {
    // Tabulated at the loaded contact's positions: the table reads back its values there.
    const TabulatedMeshStiffness table(k.linearised->phases, k.linearised->tangent,
                                       k.linearised->contact_ratio, "ltca");
    const std::vector<double> phases = table.discontinuities();
    std::vector<double> values;
    for (double p : phases) values.push_back(table.stiffness(p));
    t += fmt::format(
        "stiffness = \"table\"  # the file's model.stiffness.type = \"ltca\": the loaded "
        "contact's\n# tangent stiffness K(phi) at the mean force F = {} N, at {} positions\n"
        "stiffness_table_source = \"ltca\"\nstiffness_table_phases = {}\n"
        "stiffness_table_values = {}  # [N/m]\n",
        tomlReal(k.mean_force), phases.size(), tomlReals(phases), tomlReals(values));
  } else {
    // gear_pair_ltca: k(φ) is the unmodified potential-energy stiffness (scales, k̄, linear
    // analyses); the tooth-pair elements carry the modifications.
    t += "stiffness = " +
         quoted(k.tooth_pairs ? "potential_energy" : config.string("model.stiffness.type")) + "\n";
    tables = meshStiffnessTables(config, "mesh_stiffness");
  }
  return t;
}

/// The mesh's damping: the file's dashpot c, or its ratio ζ (the same c = 2ζ√(k̄ m_e) on the
/// train's mean stiffness and equivalent mass).
std::string dampingKeys(const GearPairKeys& k) {
  if (k.damping) return fmt::format("damping = {}  # [N s/m]\n", tomlReal(*k.damping));
  return fmt::format("damping_ratio = {}  # on m_e and the mean stiffness\n",
                     tomlReal(k.damping_ratio));
}

/// The mesh's transmission-error keys.
std::string errorKeys(const Config& config, const GearPairKeys& k) {
  std::string t;
  const auto te_amplitudes = config.realList("model.transmission_error.amplitudes");
  if (!te_amplitudes.empty()) {
    t += "te_amplitudes = " + tomlReals(te_amplitudes) + "  # [m]\n";
    t += "te_phases_deg = " + tomlReals(config.realList("model.transmission_error.phases_deg")) +
         "\n";
  }
  const std::string te = "model.transmission_error.";
  if (config.real(te + "rectangular_amplitude") != 0.0) {
    t += fmt::format("te_rectangular_amplitude = {}  # [m]\n",
                     tomlReal(config.real(te + "rectangular_amplitude")));
    t += "te_rectangular_duty = " + tomlReal(config.real(te + "rectangular_duty")) + "\n";
    t += "te_rectangular_start = " + tomlReal(config.real(te + "rectangular_start")) + "\n";
  }
  if (!config.realList(te + "table_phases").empty() ||
      !config.realList(te + "table_values").empty()) {
    t += "te_table_phases = " + tomlReals(config.realList(te + "table_phases")) + "\n";
    t += "te_table_values = " + tomlReals(config.realList(te + "table_values")) + "  # [m]\n";
  } else if (k.linearised) {
    // E = δ − F/K of the loaded contact, read back at the stiffness table's positions.
    TransmissionError table;
    table.addTable(k.linearised->phases, k.linearised->error, te + "table_phases");
    const TabulatedMeshStiffness stiffness(k.linearised->phases, k.linearised->tangent,
                                           k.linearised->contact_ratio, "ltca");
    const std::vector<double> phases = stiffness.discontinuities();
    std::vector<double> values;
    for (double p : phases) values.push_back(table.value(p));
    t += "te_table_phases = " + tomlReals(phases) +
         "  # the loaded contact's error delta - F/K (model.stiffness.type = \"ltca\")\n";
    t += "te_table_values = " + tomlReals(values) + "  # [m]\n";
  }
  return t;
}

/// The mesh's contact keys; the tooth pairs' [meshes.mesh.modifications] go before `tables`.
std::string contactKeys(const Config& config, const GearPairKeys& k, std::string& tables) {
  if (k.tooth_pairs) {
    // The file's [modifications], the gaps of the tooth-pair elements.
    if (const Json* m = tableAt(config, "modifications")) {
      tables = "\n[meshes.mesh.modifications]\n" + keys(*m) + tables;
    }
    return fmt::format(
        "contact = \"tooth_pairs\"  # the file's model.type = \"gear_pair_ltca\"\n"
        "tooth_pair_slices = {}  # model.stiffness.ltca_slices\n",
        config.integer("model.stiffness.ltca_slices"));
  }
  switch (k.contact) {
    case ContactLaw::kLinear:
      return "contact = \"linear\"\n";
    case ContactLaw::kOneSided:
      return "contact = \"one_sided\"\n";
    case ContactLaw::kBacklash:
      break;
  }
  return fmt::format(
      "contact = \"backlash\"\nbacklash = {}  # [m] the file's model.normal_backlash: "
      "the full clearance j\n",
      tomlReal(k.backlash));
}

/// The header comment, [gearbox], the shafts and the gears.
std::string gearsAndShafts(const Config& config, const GearPairKeys& k, const GearPair& pair) {
  const double r_a = pair.pinion().base_radius, r_b = pair.gear().base_radius;
  // I = 2 m_e r_b² on each shaft: 1 / (r_a²/I_a + r_b²/I_b) = m_e.
  const double inertia_a = 2.0 * k.mass * r_a * r_a, inertia_b = 2.0 * k.mass * r_b * r_b;
  std::string t = fmt::format(
      "# The gearbox of {}, written by geardyn --print-gearbox.\n"
      "# The gear-pair model is a train of two rigid shafts with torsional DOFs and one\n"
      "# external spur mesh (docs/design.md, system/sdof_reduction.h):\n"
      "#   m_e = 1 / (r_a^2/I_a + r_b^2/I_b),  F = T / r_a,  f_m = z_a n / 60.\n",
      config.source().empty() ? std::string("the gear-pair file") : config.source());
  if (k.nondimensional) {
    t += "# The file is nondimensional (Gelman's form): its numbers are taken in SI units,\n"
         "# m_e = 1 kg, mean k = 1 N/m, F = a N, time omega_n t in s, mesh frequency Omega / 2 pi "
         "Hz.\n";
  }
  if (k.pair) {
    t += "# The gears are the file's [pinion] and [gear]; their bodies are off and each shaft\n"
         "# carries I = 2 m_e r_b^2, so that the equivalent mass is the file's m_e = " +
         tomlReal(k.mass) + " kg.\n";
  } else {
    t += fmt::format(
        "# The file gives no gear geometry: a nominal spur pair carries the model (z = {},\n"
        "# m_n = {} mm, alpha_n = {} deg, b = {} mm, ratio 1). It only sets the base radii\n"
        "# r_b = {} m and the teeth: the gear bodies are off, each shaft carries\n"
        "# I = 2 m_e r_b^2 (so that the equivalent mass is the file's m_e = {} kg), the torque\n"
        "# is F r_b and the speed 60 f_m / z.\n",
        kNominalTeeth, kNominalModule * 1e3, kNominalPressureAngleDeg, kNominalFaceWidth * 1e3,
        tomlReal(r_a), tomlReal(k.mass));
  }
  t += "\n[gearbox]\n";
  const Json* title = tableAt(config, "title");
  t += "name = " + quoted(title && title->is_string() ? title->get<std::string>() : "gear pair") +
       "\n";
  t += "dofs = \"torsional\"\n";
  t +=
      fmt::format("\n[shafts.pinion_shaft]\npolar_inertia = {}  # [kg m^2]\n", tomlReal(inertia_a));
  t += fmt::format("\n[shafts.gear_shaft]\npolar_inertia = {}  # [kg m^2]\n", tomlReal(inertia_b));
  for (const char* gear : {"pinion", "gear"}) {
    t += fmt::format("\n[gears.{}]\nshaft = \"{}_shaft\"\nbody = false\n", gear, gear);
    if (k.pair) {
      t += keys(*tableAt(config, gear));
    } else {
      t += fmt::format("teeth = {}\nmodule = {}\npressure_angle_deg = {}\nface_width = {}\n",
                       kNominalTeeth, tomlReal(kNominalModule), tomlReal(kNominalPressureAngleDeg),
                       tomlReal(kNominalFaceWidth));
    }
  }
  return t;
}

}  // namespace

std::string gearPairGearboxToml(const Config& config, const GearPairKeys& k) {
  GearPairSpec pair_spec;
  if (k.pair) {
    pair_spec = k.pair->spec();
  } else {
    pair_spec.pinion = pair_spec.gear = nominalGear();
  }
  const GearPair pair = makeGearPair(pair_spec, "pinion", "gear", "pair");
  const double r_a = pair.pinion().base_radius;
  const int z_a = pair.spec().pinion.teeth;
  std::string t = gearsAndShafts(config, k, pair);
  t += "\n[meshes.mesh]\ngears = [\"pinion\", \"gear\"]\n";
  if (k.pair && config.has("pair.centre_distance")) {
    t += "centre_distance = " + tomlReal(config.real("pair.centre_distance")) + "\n";
  }
  if (k.pair && k.pair->spec().driver == Driver::kGear) t += "driver = \"gear\"  # pair.driver\n";
  std::string tables;
  t += stiffnessKeys(config, k, tables);
  if (helical(config)) {
    t += "stiffness_plane = \"transverse\"  # k, c, e and j of the gear-pair file are transverse\n";
  }
  t += dampingKeys(k);
  t += "phase = " + tomlReal(k.initial_phase) + "  # mesh phase at t = 0 [mesh periods]\n";
  t += errorKeys(config, k);
  t += contactKeys(config, k, tables);
  t += tables;
  const double speed_rpm = 60.0 * k.mesh_frequency / z_a;
  t += fmt::format(
      "\n[operating_point]\ninput = \"pinion_shaft\"\noutput = \"gear_shaft\"\n"
      "speed_rpm = {}  # f_m = {} Hz{}\ntorque = {}  # [N m]: F = {} N on r_b = {} m\n",
      tomlReal(speed_rpm), tomlReal(k.mesh_frequency),
      k.mesh_frequency == 0.0 ? " (the file leaves the speed to the analysis)" : "",
      tomlReal(k.mean_force * r_a), tomlReal(k.mean_force), tomlReal(r_a));
  return t;
}

std::string gearPairGearbox(const Config& config) {
  if (config.resolved().contains("stats") && config.string("stats.source") != "model") {
    throw InputError("stats.source", quoted(config.string("stats.source")),
                     "\"model\" for --print-gearbox: only a [model] describes a gear pair");
  }
  const GearPairKeys keys = readGearPairKeys(config, false);
  if (!keys.extra_forces.empty()) {
    throw InputError("model.extra_force_amplitudes", "(given)",
                     "no gearbox translation for --print-gearbox yet: the gearbox has no extra "
                     "harmonic force (the gear-pair commands add them to the reduced model)");
  }
  return gearPairGearboxToml(config, keys);
}

GearPairModelSpec gearPairFromGearbox(const std::string& toml, const std::string& source,
                                      std::vector<std::string>* warnings) {
  const Config gearbox = parseConfig(toml, source, gearboxSchema());
  std::vector<std::string> notes;
  GearPairModelSpec s = sdofReduction(GearTrainModel(gearTrainFromConfig(gearbox, notes)));
  if (warnings) {
    // The stiffness models' warnings are about the user's gears; the gears' plausibility and
    // the speed notes are said in the file's terms by the reading (or are about the nominal
    // pair of a file without gears).
    for (auto& note : notes) {
      if (note.rfind("gears.", 0) != 0 && note.rfind("operating_point.", 0) != 0) {
        warnings->push_back(std::move(note));
      }
    }
  }
  return s;
}

}  // namespace geardyn::config

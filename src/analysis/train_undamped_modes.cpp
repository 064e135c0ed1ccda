/// The warning about a train's undamped modes (see train_undamped_modes.h).

#include "train_undamped_modes.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

namespace geardyn::analysis::detail {

namespace {

bool endsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

}  // namespace

std::string dampingKeyOf(const GearTrainModel& model, const std::string& element) {
  const std::string base = element.substr(0, element.find('.'));
  const std::string part = element.size() > base.size() ? element.substr(base.size() + 1) : "";
  const GearTrainSpec& spec = model.spec();
  for (const TrainBearingSpec& b : spec.bearings) {
    if (b.name != base) continue;
    if (part == "axial") return "bearings." + base + ".c_axial";
    if (part == "tilt_y" || part == "tilt_z") return "bearings." + base + ".c_tilt";
    if (part == "torsion") return "bearings." + base + ".c_torsion";
    return "bearings." + base + ".cyy/czz";
  }
  for (const TrainShaftSpec& s : spec.shafts) {
    if (s.name == base && part.rfind("beam", 0) == 0)
      return "shafts." + base + ".stiffness_proportional_damping";
  }
  for (const TrainCouplingSpec& c : spec.couplings) {
    if (c.name == base)
      return "couplings." + base + (part == "lateral" ? ".c_lateral" : ".c_torsion");
  }
  if (endsWith(element, ".pin") || element.find(".pin_") != std::string::npos) {
    return "planetary." + base + ".pin_damping";  // planets are named <stage>.planet<n>
  }
  return element;
}

std::vector<std::string> dampingKeysOf(const GearTrainModel& model, const TrainUndampedMode& mode) {
  std::vector<std::string> keys;
  for (const std::string& m : mode.meshes) {
    // A planetary stage's meshes are <stage>.sun_planet<n> / <stage>.ring_planet<n>.
    std::string key = "meshes." + m + ".damping_ratio";
    for (const PlanetaryStageSpec& st : model.spec().stages) {
      for (const char* kind : {"sun_planet", "ring_planet"}) {
        if (m.rfind(st.name + "." + kind, 0) == 0) {
          key = "planetary." + st.name + "." + kind + ".damping_ratio";
        }
      }
    }
    if (std::find(keys.begin(), keys.end(), key) == keys.end()) keys.push_back(key);
  }
  for (const std::string& e : mode.elements) {
    const std::string key = dampingKeyOf(model, e);
    if (std::find(keys.begin(), keys.end(), key) == keys.end()) keys.push_back(key);
  }
  return keys;
}

std::string forcingOf(const GearTrainModel& model) {
  std::vector<std::string> sources;
  if (!model.meshes().empty()) sources.push_back("the meshes");
  for (const TrainExcitationTerm& term : model.excitations()) {
    const std::string section = term.name.substr(0, term.name.find('.'));
    if (std::find(sources.begin(), sources.end(), section) == sources.end())
      sources.push_back(section);
  }
  std::string text;
  for (std::size_t i = 0; i < sources.size(); ++i) {
    text += (i == 0 ? "" : " and ") + std::string(sources[i] == "the meshes" ? "" : "the ") +
            sources[i];
  }
  return text;
}

std::string undampedModesWarning(const GearTrainModel& model,
                                 const std::vector<TrainUndampedMode>& modes, double speed_rpm) {
  if (modes.empty()) return "";
  constexpr std::size_t kListed = 6;  // frequencies named; the modes table has them all
  std::vector<std::string> listed, keys;
  bool any_excited = false;
  for (const TrainUndampedMode& m : modes) {
    any_excited = any_excited || m.excited;
    for (const std::string& key : dampingKeysOf(model, m)) {
      if (std::find(keys.begin(), keys.end(), key) == keys.end()) keys.push_back(key);
    }
    if (listed.size() < kListed) {
      listed.push_back(fmt::format("{:.1f} Hz{}", m.frequency, m.excited ? " (excited)" : ""));
    }
  }
  if (modes.size() > kListed) listed.push_back(fmt::format("{} more", modes.size() - kListed));
  keys.push_back("gearbox.mass_proportional_damping");
  const std::string forcing = forcingOf(model);
  std::string consequence;
  if (any_excited)
    consequence =
        fmt::format("a time run cannot reach a steady state while {} excite one", forcing);
  else if (forcing.empty())
    consequence =
        "nothing forces them (a time run does not wait for them), but a shock would "
        "ring forever";
  else
    consequence = fmt::format(
        "{} do not excite them (a time run does not wait for them), but "
        "any other excitation (a shock) would ring forever",
        forcing);
  return fmt::format("{} mode(s) at {:.1f} rpm have no damping: {}; {}; damp them with {}",
                     modes.size(), speed_rpm, fmt::join(listed, ", "), consequence,
                     fmt::join(keys, ", "));
}

}  // namespace geardyn::analysis::detail

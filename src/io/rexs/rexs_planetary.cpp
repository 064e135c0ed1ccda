/// REXS planetary stages → [planetary.*] (rexs_mapping.h). REXS lists every planet with its
/// own shaft, gear, pin, bearings and two cylindrical stages; geardyn's stage generates N
/// planets from one planet gear. The carrier's members (carrier shafts, side plates, pins and
/// what is rigidly coupled to them) become one body: the first carrier shaft, with the others'
/// mass and inertia (parallel-axis terms for the pins) added.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geardyn/error.h"
#include "geardyn/io/rexs/rexs_gearbox.h"
#include "rexs_mapping.h"

namespace geardyn::io::rexs::detail {
namespace {

std::vector<int> stageMembers(const Model& model, int stage, const std::string& relation) {
  std::vector<int> out;
  for (const auto* r : model.relations(relation))
    if (r->ref("planetary_stage") == stage)
      if (auto s = r->ref("shaft")) out.push_back(*s);
  return out;
}

/// (y, z) of a component's support vector [m], or (0, 0).
std::pair<double, double> centre(Model& model, int id) {
  const auto v = model.read.vector(model.component(id), "support_vector");
  return v ? std::make_pair((*v)[1], (*v)[2]) : std::make_pair(0.0, 0.0);
}

/// The stage's sun, ring and planet gears, found through its cylindrical stages (absorbed).
struct StageGears {
  int sun = -1, ring = -1;
  std::vector<int> planets;
};

StageGears stageGears(Model& model, const Component& stage, const std::vector<int>& planet_shafts,
                      PlanetaryMapping& pm) {
  std::optional<int> sun, ring;
  std::vector<int> planet_gears;
  std::set<int> on_planets(planet_shafts.begin(), planet_shafts.end());
  for (int part : model.parts(stage.id)) {
    if (model.component(part).type != "cylindrical_stage") continue;
    pm.absorbed.insert(part);
    for (const auto* r : model.relations("stage")) {
      if (r->ref("stage") != part) continue;
      for (const char* role : {"gear_1", "gear_2"}) {
        const auto g = r->ref(role);
        if (!g) continue;
        const auto shaft = model.assemblyOf(*g, {"shaft"});
        if (model.component(*g).type == "ring_gear")
          ring = *g;
        else if (shaft && on_planets.count(*shaft)) {
          if (std::find(planet_gears.begin(), planet_gears.end(), *g) == planet_gears.end())
            planet_gears.push_back(*g);
        } else
          sun = *g;
      }
    }
  }
  if (!sun || !ring || planet_gears.empty())
    io::rexs::throwAttributeError(
        stage, "(cylindrical stages)",
        fmt::format("sun {}, ring {}, {} planet gears", sun ? "found" : "missing",
                    ring ? "found" : "missing", planet_gears.size()),
        "a sun, a ring gear and planet gears on the planet shafts");
  return {*sun, *ring, planet_gears};
}

/// The carrier body's components: its shafts, pins, the planet carrier's parts, and what rigid
/// couplings join to them (absorbed, with those couplings).
std::set<int> carrierMembers(Model& model, const Component& stage, const std::vector<int>& carriers,
                             const std::vector<int>& pins, PlanetaryMapping& pm) {
  std::set<int> members(carriers.begin(), carriers.end());
  members.insert(pins.begin(), pins.end());
  for (const Component* pc : model.ofType({"planet_carrier"})) {
    if (!model.assemblyOf(pc->id, {"planetary_stage"}) ||
        *model.assemblyOf(pc->id, {"planetary_stage"}) != stage.id)
      continue;
    pm.absorbed.insert(pc->id);
    for (int part : model.parts(pc->id)) members.insert(part);
  }
  for (bool grew = true; grew;) {
    grew = false;
    for (const auto* r : model.relations("side")) {
      const auto a = r->ref("assembly"), in = r->ref("inner_part"), out = r->ref("outer_part");
      if (!a || !in || !out || model.component(*a).type.find("coupling") == std::string::npos)
        continue;
      // No stiffness given: a rigid connection (a warning says so where it is mapped).
      const bool rigid = model.read.real(model.component(*a), "rotational_stiffness", 1e300) >=
                         model.rotational_cap;
      if (!rigid || model.isCasing(*in) || model.isCasing(*out)) continue;
      if (members.count(*in) != members.count(*out)) {
        members.insert(*in), members.insert(*out);
        grew = true;
      }
      if (members.count(*in) && members.count(*out)) pm.absorbed.insert(*a);
    }
  }
  return members;
}

/// Merges the carrier's members into its body: their mass, and their inertia about the carrier's
/// axis (a member shaft off the axis by its parallel-axis term).
void mergeCarrier(Model& model, const std::set<int>& members, int carrier, PlanetaryMapping& pm) {
  MassProperties extra;
  const auto [cy, cz] = centre(model, carrier);
  std::string merged;
  for (int m : members) {
    pm.body_of[m] = carrier;
    if (m == carrier) continue;
    pm.absorbed.insert(m);
    merged += (merged.empty() ? "" : ", ") + std::to_string(m);
    const Component& c = model.component(m);
    MassProperties p;
    if (c.type == "shaft") {
      p = model.sections(m).massProperties(model.density(m));
    } else if (c.type == "side_plate") {
      ShaftSections plate;
      plate.lengths = {model.read.requiredReal(c, "length")};
      plate.outer = {model.read.requiredReal(c, "outer_diameter")};
      plate.inner = {model.read.real(c, "inner_diameter", 0.0)};
      p = plate.massProperties(model.density(m));
    }
    const auto [y, z] = centre(model, m);
    const double r2 = c.type == "shaft" ? (y - cy) * (y - cy) + (z - cz) * (z - cz) : 0.0;
    extra.mass += p.mass;
    extra.inertia += p.inertia + p.mass * r2;
  }
  pm.extra[carrier] = extra;
  pm.extra_comment[carrier] = "carrier members merged into this body (components " + merged + ")";
}

/// The planets' angles about the carrier [deg, sorted], whether equally spaced, and the radial
/// stiffness of the first planet's bearings on its pin [N/m] (0: none given); the planet shafts,
/// gears and bearings are absorbed.
struct PlanetLayout {
  std::vector<double> angles;
  bool equal = true;
  double pin_stiffness = 0.0;
};

PlanetLayout planetLayout(Model& model, const std::vector<int>& planet_shafts,
                          const std::vector<int>& planet_gears, int carrier, PlanetaryMapping& pm) {
  PlanetLayout out;
  const auto [cy, cz] = centre(model, carrier);
  for (int ps : planet_shafts) {
    pm.absorbed.insert(ps);
    const auto [y, z] = centre(model, ps);
    double psi = std::atan2(z - cz, y - cy) * 180 / std::numbers::pi;
    if (psi < -1e-9) psi += 360;
    out.angles.push_back(std::abs(psi) < 1e-9 ? 0.0 : psi);
    for (const auto* r : model.relations("side")) {
      const auto a = r->ref("assembly");
      if (!a || (r->ref("inner_part") != ps && r->ref("outer_part") != ps)) continue;
      pm.absorbed.insert(*a);
      if (ps == planet_shafts.front())
        out.pin_stiffness += model.read.real(model.component(*a), "radial_stiffness", 0.0);
    }
  }
  for (int g : planet_gears) pm.absorbed.insert(g);
  std::sort(out.angles.begin(), out.angles.end());
  const int n = static_cast<int>(out.angles.size());
  for (int i = 0; i < n; ++i) {
    const double next = i + 1 < n ? out.angles[i + 1] : out.angles[0] + 360;
    if (std::abs(next - out.angles[i] - 360.0 / n) > 1e-6) out.equal = false;
  }
  return out;
}

/// The gearbox sections of one stage: planetary.<name> (members, layout, planet mass, pin
/// stiffness), its planet gear, and its sun-planet and ring-planet mesh models.
void addStageSections(Model& model, const Component& stage, const StageGears& gears, int carrier,
                      const std::vector<int>& planet_shafts, const PlanetLayout& layout,
                      PlanetaryMapping& pm) {
  auto& read = model.read;
  const std::string where = stage.label();
  const std::vector<double>& angles = layout.angles;
  const int n = static_cast<int>(angles.size());
  const std::string name = model.name(stage.id);
  TomlSection t{"planetary." + name, where, {}};
  t.add("sun", tomlString(model.name(gears.sun)), fmt::format("gear component {}", gears.sun));
  t.add("ring", tomlString(model.name(gears.ring)),
        fmt::format("ring_gear component {}", gears.ring));
  t.add("carrier", tomlString(model.name(carrier)),
        fmt::format("planet_carrier_shaft {}", carrier));
  std::string shafts_list;
  for (int ps : planet_shafts)
    shafts_list += (shafts_list.empty() ? "" : ", ") + std::to_string(ps);
  t.add("planets", std::to_string(n), "planet_shaft components " + shafts_list);
  std::string angle_text;
  for (double a : angles) angle_text += fmt::format("{}{:.6g}", angle_text.empty() ? "" : ", ", a);
  if (layout.equal && std::abs(angles.front()) < 1e-6) {
    t.add("planet_angles_deg", "[]", "equally spaced: " + angle_text + " deg");
  } else {
    std::vector<double> rounded;
    for (double a : angles) rounded.push_back(std::round(a * 1e9) / 1e9);
    t.add("planet_angles_deg", tomlReals(rounded),
          layout.equal ? "equally spaced, first planet not at 0 deg" : "unequally spaced");
  }
  const Component& first_shaft = model.component(planet_shafts.front());
  const MassProperties planet =
      model.sections(first_shaft.id).massProperties(model.density(first_shaft.id));
  t.add("planet_mass", tomlReal(planet.mass),
        fmt::format("planet shaft {} sections", first_shaft.id));
  t.add("planet_inertia", tomlReal(planet.inertia));
  const double pin_k = layout.pin_stiffness;
  double k = pin_k > 0 ? model.capped(pin_k, false, stage, "planet bearing radial_stiffness")
                       : kRexsDefaultBearingStiffness;
  if (pin_k <= 0)
    read.warn(
        fmt::format("{}: planet bearings without a radial stiffness get {:.3g} N/m", where, k));
  t.add("pin_radial_stiffness", tomlReal(k), "planet bearings on the pin (sum)");
  t.add("pin_tangential_stiffness", tomlReal(k));
  t.add("carrier_frame_terms", "true", "Lin & Parker 1999 carrier frame");
  pm.sections.push_back(std::move(t));
  const Component& planet_gear_component = model.component(gears.planets.front());
  TomlSection planet_gear{"planetary." + name + ".planet", planet_gear_component.label(), {}};
  const GearSpec planet_spec = addGearKeys(model, planet_gear_component, planet_gear);
  const double u = read.real(planet_gear_component, "u_coordinate_on_shaft", 0.0);
  addGearBody(planet_spec, model.sections(first_shaft.id).outerDiameterAt(u), planet_gear);
  for (std::size_t i = 0; i < planet_gear.lines.size(); ++i) {
    if (planet_gear.lines[i].key != "body") continue;
    pm.sections.back().add("planet_body", "false", planet_gear.lines[i].comment);
    planet_gear.lines.erase(planet_gear.lines.begin() + static_cast<long>(i));
  }
  pm.sections.push_back(std::move(planet_gear));
  TomlSection sp{"planetary." + name + ".sun_planet", "", {}};
  sp.add("stiffness", tomlString("potential_energy"), "from the tooth geometry");
  pm.sections.push_back(std::move(sp));
  TomlSection rp{"planetary." + name + ".ring_planet", "", {}};
  rp.add("stiffness", tomlString("api"), "ring mesh: API estimate (geometry only)");
  pm.sections.push_back(std::move(rp));
}

}  // namespace

PlanetaryMapping mapPlanetaryStages(Model& model) {
  PlanetaryMapping pm;
  for (const Component* stage : model.ofType({"planetary_stage"})) {
    ++pm.stages;
    const std::vector<int> planet_shafts = stageMembers(model, stage->id, "planet_shaft");
    const std::vector<int> carriers = stageMembers(model, stage->id, "planet_carrier_shaft");
    const std::vector<int> pins = stageMembers(model, stage->id, "planet_pin");
    if (planet_shafts.empty() || carriers.empty())
      io::rexs::throwAttributeError(
          *stage, "(planet_shaft / planet_carrier_shaft relations)", "",
          "a planetary stage needs its planet shafts and a carrier shaft");
    const int carrier = carriers.front();
    const StageGears gears = stageGears(model, *stage, planet_shafts, pm);
    mergeCarrier(model, carrierMembers(model, *stage, carriers, pins, pm), carrier, pm);
    const PlanetLayout layout = planetLayout(model, planet_shafts, gears.planets, carrier, pm);
    addStageSections(model, *stage, gears, carrier, planet_shafts, layout, pm);
  }
  return pm;
}

}  // namespace geardyn::io::rexs::detail

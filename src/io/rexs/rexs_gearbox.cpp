/// REXS → gearbox description (rexs_gearbox.h): shafts, gears, parallel stages, bearings,
/// couplings and the operating point; planetary stages in rexs_planetary.cpp.

#include "geardyn/io/rexs/rexs_gearbox.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "geardyn/config/gearbox_config.h"
#include "geardyn/error.h"
#include "geardyn/geometry/gear_pair.h"
#include "geardyn/io/rexs/rexs_reader.h"
#include "geardyn/system/gear_train_model.h"
#include "rexs_mapping.h"

namespace geardyn::io::rexs {
namespace {

using namespace detail;

const std::set<std::string> kShaftTypes = {"shaft"};
const std::set<std::string> kGearTypes = {"cylindrical_gear", "ring_gear"};
const std::set<std::string> kBearingTypes = {
    "concept_bearing", "rolling_bearing_with_catalog_geometry",
    "rolling_bearing_with_detailed_geometry", "fluid_bearing"};
const std::set<std::string> kCouplingTypes = {"coupling", "switchable_coupling"};
/// Types the mapping reads (directly or as data of another component).
const std::set<std::string> kUnderstood = {"gear_unit",
                                           "gear_casing",
                                           "shaft",
                                           "shaft_section",
                                           "cylindrical_gear",
                                           "ring_gear",
                                           "cylindrical_stage",
                                           "planetary_stage",
                                           "planet_carrier",
                                           "side_plate",
                                           "cylindrical_gear_flank",
                                           "cylindrical_stage_gear_data",
                                           "material",
                                           "external_load",
                                           "concept_bearing",
                                           "rolling_bearing_with_catalog_geometry",
                                           "rolling_bearing_with_detailed_geometry",
                                           "coupling",
                                           "switchable_coupling",
                                           "additional_mass"};

/// "worm_stage (1), lubricant (1)": components geardyn does not model.
std::string notModelled(const Document& doc) {
  std::map<std::string, int> count;
  for (const auto& c : doc.components)
    if (!kUnderstood.count(c.type)) ++count[c.type];
  std::string out;
  for (const auto& [type, n] : count)
    out += fmt::format("{}{} ({})", out.empty() ? "" : ", ", type, n);
  return out;
}

/// The attributes of component `id` in a load case over its base attributes.
const Component* inLoadCase(const io::rexs::LoadCase* lc, int id) {
  if (lc)
    for (const auto& c : lc->components)
      if (c.id == id) return &c;
  return nullptr;
}

struct Operating {
  int input = 0, output = 0;
  /// The shaft whose external load defines the torque (0: none); cases[].torque is that load's
  /// torque until it is carried over to the input (torqueOnInput).
  int torque_shaft = 0;
  std::vector<RexsLoadCaseSummary> cases;
};

/// Input shaft (defines_speed), output shaft (another torque-transmitting load), speed and
/// torque of each load case.
Operating operatingPoints(Model& model, const std::set<int>& shafts, const PlanetaryMapping& pm) {
  auto& read = model.read;
  Operating op;
  int torque_load = 0, torque_shaft = 0;
  for (const Component* s : model.ofType(kShaftTypes))
    if (read.boolean(*s, "defines_speed").value_or(false) && !op.input) op.input = s->id;
  auto bodyOf = [&](int id) { return pm.body_of.count(id) ? pm.body_of.at(id) : id; };
  std::vector<std::pair<int, int>> loads;  // (load, shaft)
  for (const Component* l : model.ofType({"external_load"})) {
    const auto shaft = model.assemblyOf(l->id, kShaftTypes);
    if (!shaft) continue;
    loads.emplace_back(l->id, bodyOf(*shaft));
    if (read.boolean(*l, "defines_torque").value_or(false) && !torque_load)
      torque_load = l->id, torque_shaft = bodyOf(*shaft);
  }
  const int speed_shaft = op.input;  // the component whose attributes give the speed
  if (op.input) op.input = bodyOf(op.input);
  if (!op.input) op.input = torque_shaft;
  if (!op.input && !shafts.empty()) op.input = *shafts.begin();
  for (const auto& [load, shaft] : loads) {
    if (shaft != op.input && !op.output &&
        read.boolean(model.component(load), "transmits_torque").value_or(false))
      op.output = shaft;
  }
  if (!op.output) {
    for (int s : shafts)
      if (s != op.input) op.output = s;
    read.warn(fmt::format("no external load marks the output shaft; {} takes the load torque",
                          op.output ? model.name(op.output) : "the input"));
  }
  if (!op.output) op.output = op.input;
  op.torque_shaft = torque_shaft;
  std::vector<const io::rexs::LoadCase*> cases;
  for (const auto& lc : model.doc.load_cases) cases.push_back(&lc);
  if (cases.empty()) cases.push_back(nullptr);
  for (const auto* lc : cases) {
    RexsLoadCaseSummary s;
    s.id = lc ? lc->id : 0;
    const Component& in = model.component(speed_shaft ? speed_shaft : op.input);
    const Component* in_lc = inLoadCase(lc, in.id);
    s.speed_rpm = (in_lc ? read.real(*in_lc, "rotational_speed") : std::nullopt)
                      .value_or(read.real(in, "rotational_speed", 0.0));
    if (torque_load) {
      const Component* l_lc = inLoadCase(lc, torque_load);
      s.torque =
          (l_lc ? read.real(*l_lc, "torque_around_u_axis") : std::nullopt)
              .value_or(read.real(model.component(torque_load), "torque_around_u_axis", 0.0));
    }
    for (const auto& u : model.doc.components)
      if (u.type == "gear_unit")
        if (const Component* g = inLoadCase(lc, u.id))
          s.time_fraction = read.real(*g, "operating_time_fraction", 0.0);
    op.cases.push_back(s);
  }
  return op;
}

/// Direction [deg] from shaft a's centre to shaft b's in the (y, z) plane, from +y to +z.
std::optional<double> directionBetween(Model& model, int shaft_a, int shaft_b) {
  const auto a = model.read.vector(model.component(shaft_a), "support_vector");
  const auto b = model.read.vector(model.component(shaft_b), "support_vector");
  if (!a || !b) return std::nullopt;
  const double dy = (*b)[1] - (*a)[1], dz = (*b)[2] - (*a)[2];
  if (std::hypot(dy, dz) < 1e-9) return std::nullopt;
  return std::atan2(dz, dy) * 180.0 / std::numbers::pi;
}

std::string renderToml(const std::vector<TomlSection>& sections, const std::string& header) {
  std::string out = header;
  for (const auto& s : sections) {
    out += "\n";
    if (!s.comment.empty()) out += "# " + s.comment + "\n";
    out += "[" + s.header + "]\n";
    for (const auto& l : s.lines) {
      std::string line = l.key + " = " + l.value;
      if (!l.comment.empty())
        line += std::string(std::max<int>(1, 40 - int(line.size())), ' ') + "# " + l.comment;
      out += line + "\n";
    }
  }
  return out;
}

}  // namespace

RexsImport importRexsGearbox(const Document& doc, const RexsImportOptions& options) {
  io::rexs::checkReferences(doc);  // documents built in code have not been through the reader
  RexsImport result;
  Model model(doc, result.warnings);
  auto& read = model.read;
  if (const std::string skipped = notModelled(doc); !skipped.empty())
    result.warnings.push_back(doc.source +
                              ": components geardyn does not model, left out: " + skipped);
  for (const auto& c : doc.components) {
    if (c.type == "worm_stage")
      result.warnings.push_back(fmt::format(
          "{}: worm stages are not modelled ({}); its shafts, bearings and loads are kept",
          doc.source, c.label()));
  }
  result.rexs_shafts = static_cast<int>(model.ofType(kShaftTypes).size());
  result.rexs_gears = static_cast<int>(model.ofType(kGearTypes).size());
  result.rexs_stages = static_cast<int>(model.ofType({"cylindrical_stage"}).size());
  result.rexs_planetary_stages = static_cast<int>(model.ofType({"planetary_stage"}).size());
  result.rexs_bearings = static_cast<int>(model.ofType(kBearingTypes).size());
  result.rexs_couplings = static_cast<int>(model.ofType(kCouplingTypes).size());

  PlanetaryMapping pm = mapPlanetaryStages(model);
  auto bodyOf = [&](int id) { return pm.body_of.count(id) ? pm.body_of.at(id) : id; };
  std::vector<TomlSection> sections;

  // Shafts.
  std::set<int> shafts;
  for (const Component* s : model.ofType(kShaftTypes)) {
    if (pm.absorbed.count(s->id)) continue;
    shafts.insert(s->id);
    TomlSection t{"shafts." + model.name(s->id), s->label(), {}};
    if (auto axis = read.vector(*s, "u_axis_vector")) {
      const auto& u = *axis;
      if (std::abs(u[1]) > 1e-9 || std::abs(u[2]) > 1e-9 || u[0] <= 0)
        read.warn(
            fmt::format("{}: axis ({}, {}, {}) is not the gear unit's +x; geardyn's "
                        "shafts all turn about +x (its position and orientation are "
                        "not used)",
                        s->label(), u[0], u[1], u[2]));
    }
    const ShaftSections sec = model.sections(s->id);
    if (!sec.lengths.empty()) {
      t.add("section_lengths", tomlReals(sec.lengths),
            fmt::format("shaft_section components {} … {}", sec.ids.front(), sec.ids.back()));
      t.add("outer_diameters", tomlReals(sec.outer));
      t.add("inner_diameters", tomlReals(sec.inner));
    }
    if (const Component* m = model.material(s->id)) {
      const std::string note = fmt::format("material component {}", m->id);
      if (auto rho = read.real(*m, "density")) t.add("density", tomlReal(*rho), note);
      if (auto e = read.real(*m, "elastic_modulus")) t.add("youngs_modulus", tomlReal(*e), note);
      if (auto nu = read.real(*m, "poisson_ratio")) t.add("poisson_ratio", tomlReal(*nu), note);
    }
    if (pm.extra.count(s->id)) {
      t.add("mass", tomlReal(pm.extra.at(s->id).mass), pm.extra_comment.at(s->id));
      t.add("polar_inertia", tomlReal(pm.extra.at(s->id).inertia), "about this shaft's axis");
    }
    const auto at = read.vector(*s, "support_vector");
    t.add("axial_offset", tomlReal(at ? (*at)[0] : 0.0), "support_vector x");
    t.add("flexible", "false", "rigid body; true needs dofs = \"full\"");
    sections.push_back(std::move(t));
  }
  // Gears on the shafts (planet gears belong to their stage).
  std::map<int, GearSpec> gear_specs;
  for (const Component* g : model.ofType(kGearTypes)) {
    if (pm.absorbed.count(g->id)) continue;
    const auto shaft = model.assemblyOf(g->id, kShaftTypes);
    if (!shaft)
      io::rexs::throwAttributeError(*g, "(assembly relation)", "",
                                    "a gear must be a part of a shaft");
    TomlSection t{"gears." + model.name(g->id), g->label(), {}};
    t.add("shaft", tomlString(model.name(bodyOf(*shaft))),
          fmt::format("shaft component {}", *shaft));
    gear_specs[g->id] = addGearKeys(model, *g, t);
    const double u = read.real(*g, "u_coordinate_on_shaft", 0.0);
    t.add("position", tomlReal(u), "u_coordinate_on_shaft");
    if (g->type == "ring_gear") {
      t.add("internal", "true", "ring_gear");
    } else {
      addGearBody(gear_specs[g->id], model.sections(*shaft).outerDiameterAt(u), t);
    }
    sections.push_back(std::move(t));
  }
  // Parallel stages.
  for (const Component* st : model.ofType({"cylindrical_stage"})) {
    if (pm.absorbed.count(st->id)) continue;
    const Relation* rel = nullptr;
    for (const auto* r : model.relations("stage"))
      if (r->ref("stage") == st->id) rel = r;
    if (!rel || !rel->ref("gear_1") || !rel->ref("gear_2"))
      io::rexs::throwAttributeError(*st, "(stage relation)", "",
                                    "a cylindrical stage needs a stage relation with gear_1 and "
                                    "gear_2");
    const int g1 = *rel->ref("gear_1"), g2 = *rel->ref("gear_2");
    TomlSection t{"meshes." + model.name(st->id), st->label(), {}};
    t.add("gears", tomlStrings({model.name(g1), model.name(g2)}),
          fmt::format("stage relation {}: gear_1 {}, gear_2 {}", rel->id, g1, g2));
    const auto s1 = model.assemblyOf(g1, kShaftTypes), s2 = model.assemblyOf(g2, kShaftTypes);
    std::optional<double> angle;
    if (s1 && s2) angle = directionBetween(model, *s1, *s2);
    const auto theta = read.real(*st, "rotating_angle_around_neg_u_axis");
    if (angle) {
      t.add("position_angle_deg", tomlReal(*angle), "from the shafts' support_vector");
    } else if (theta) {
      // The mesh direction is +w turned about −u by θ: (y, z) = (sin θ, cos θ).
      const double r = *theta * std::numbers::pi / 180;
      t.add("position_angle_deg",
            tomlReal(std::atan2(std::cos(r), std::sin(r)) * 180 / std::numbers::pi),
            "rotating_angle_around_neg_u_axis");
    }
    const bool ring =
        model.component(g1).type == "ring_gear" || model.component(g2).type == "ring_gear";
    if (auto a = read.real(*st, "center_distance")) {
      // A centre distance within 1 µm of the zero-backlash one is that one (files round it;
      // geardyn refuses a distance below it, where the teeth would overlap).
      // Both ends must be gears on shafts (a fuzzed file named another component: map::at
      // threw std::out_of_range, an exit 1 instead of 2).
      const auto gearOf = [&](const char* role, int g) -> const GearSpec& {
        const auto found = gear_specs.find(g);
        if (found == gear_specs.end())
          io::rexs::throwAttributeError(*st, "(stage relation)",
                                        fmt::format("{} = {}", role, model.component(g).label()),
                                        "a cylindrical_gear or ring_gear on a shaft");
        return found->second;
      };
      GearPairSpec pair;
      pair.pinion = gearOf("gear_1", g1);
      pair.gear = gearOf("gear_2", g2);
      const double tight = ring ? *a : GearPair(pair).centreDistance();
      if (!ring && *a < tight && tight - *a <= 1e-6) {
        t.add("# centre_distance", tomlReal(*a),
              "center_distance < the zero-backlash distance by < 1 um: taken as it (the default)");
      } else {
        t.add("centre_distance", tomlReal(*a), "center_distance");
      }
    }
    if (const auto k = read.array(*st, "meshing_stiffness_characteristic")) {
      // REXS ≥ 1.5: k at each mesh position. The gearbox file's tabulated forms are shared by
      // all meshes ([mesh_stiffness.*]), so a mesh takes the characteristic's mean.
      double mean = 0.0, lo = (*k)[0], hi = (*k)[0];
      for (double v : *k)
        mean += v / static_cast<double>(k->size()), lo = std::min(lo, v), hi = std::max(hi, v);
      if (!(lo > 0))
        io::rexs::throwAttributeError(*st, "meshing_stiffness_characteristic",
                                      tomlReal(lo) + " N/m", "positive stiffnesses");
      t.add("stiffness", tomlString("constant"), "meshing_stiffness_characteristic");
      t.add("stiffness_value", tomlReal(mean), fmt::format("mean of its {} positions", k->size()));
      if (hi > lo)
        read.warn(fmt::format(
            "{}: meshing_stiffness_characteristic varies {:.3g} ... {:.3g} N/m over the "
            "mesh; its mean is used (a per-mesh k(phi) table is not in the gearbox file)",
            st->label(), lo, hi));
    } else {
      t.add("stiffness", tomlString(ring ? "api" : "potential_energy"),
            ring ? "ring mesh: API estimate (geometry only)" : "from the tooth geometry");
    }
    sections.push_back(std::move(t));
  }
  for (auto& s : pm.sections) sections.push_back(std::move(s));
  // Additional masses on shafts → rigid disks.
  for (const Component* m : model.ofType({"additional_mass"})) {
    const auto shaft = model.assemblyOf(m->id, kShaftTypes);
    if (!shaft) {
      read.warn(fmt::format("{} is on no shaft: left out", m->label()));
      continue;
    }
    TomlSection t{"disks." + model.name(m->id), m->label(), {}};
    t.add("shaft", tomlString(model.name(bodyOf(*shaft))),
          fmt::format("shaft component {}", *shaft));
    t.add("position", tomlReal(read.real(*m, "u_coordinate_on_shaft", 0.0)),
          "u_coordinate_on_shaft");
    t.add("mass", tomlReal(read.real(*m, "mass_of_component", 0.0)), "mass_of_component");
    t.add("polar_inertia", tomlReal(read.real(*m, "moment_of_inertia_u_axis", 0.0)),
          "moment_of_inertia_u_axis");
    t.add("diametral_inertia", tomlReal(read.real(*m, "moment_of_inertia_v_axis", 0.0)),
          "moment_of_inertia_v_axis");
    sections.push_back(std::move(t));
  }

  // Bearings (side relations) and couplings.
  std::vector<std::string> defaulted;
  const double k_default = options.bearing_stiffness.value_or(kRexsDefaultBearingStiffness);
  for (const auto* r : model.relations("side")) {
    const auto a = r->ref("assembly"), in = r->ref("inner_part"), out = r->ref("outer_part");
    if (!a || !in || !out) continue;
    const Component& c = model.component(*a);
    if (pm.absorbed.count(c.id)) continue;
    const bool bearing = kBearingTypes.count(c.type) > 0,
               coupling = kCouplingTypes.count(c.type) > 0;
    if (!bearing && !coupling) continue;
    if (coupling && !read.boolean(c, "is_engaged").value_or(true)) {
      read.warn(fmt::format("{} is not engaged: left out", c.label()));
      continue;
    }
    int inner = bodyOf(*in), outer = bodyOf(*out);
    if (model.isCasing(inner)) std::swap(inner, outer);
    if (!shafts.count(inner) || (!model.isCasing(outer) && !shafts.count(outer))) {
      read.warn(fmt::format("{}: connects {} and {}, not shafts or the casing; left out", c.label(),
                            model.component(*in).label(), model.component(*out).label()));
      continue;
    }
    if (inner == outer) continue;
    const bool to_housing = model.isCasing(outer);
    if (coupling && !to_housing) {
      TomlSection t{"couplings." + model.name(c.id), c.label(), {}};
      t.add("shafts", tomlStrings({model.name(inner), model.name(outer)}));
      const auto kt = read.real(c, "rotational_stiffness");
      if (kt && *kt <= 0)
        io::rexs::throwAttributeError(c, "rotational_stiffness", tomlReal(*kt),
                                      "a positive torsional stiffness of the coupling");
      if (!kt)
        read.warn(fmt::format("{} gives no rotational_stiffness: taken as rigid", c.label()));
      t.add("k_torsion",
            tomlReal(
                model.capped(kt.value_or(model.rotational_cap), true, c, "rotational_stiffness")),
            kt ? "rotational_stiffness" : "rigid (no stiffness in the file)");
      t.add("k_lateral",
            tomlReal(
                model.capped(read.real(c, "radial_stiffness", 0.0), false, c, "radial_stiffness")),
            "radial_stiffness");
      sections.push_back(std::move(t));
      continue;
    }
    TomlSection t{"bearings." + model.name(c.id), c.label(), {}};
    t.add("shaft", tomlString(model.name(inner)), fmt::format("side relation {}", r->id));
    if (!to_housing) t.add("other_shaft", tomlString(model.name(outer)));
    const bool inner_first = inner == bodyOf(*in);
    const char* pos_in = "u_coordinate_on_shaft_inner_side";
    const char* pos_out = "u_coordinate_on_shaft_outer_side";
    t.add("position", tomlReal(read.real(c, inner_first ? pos_in : pos_out, 0.0)),
          inner_first ? pos_in : pos_out);
    if (!to_housing)
      t.add("other_position", tomlReal(read.real(c, inner_first ? pos_out : pos_in, 0.0)));
    const auto kr = read.real(c, "radial_stiffness");
    double k = 0.0;
    std::string note = "radial_stiffness";
    if (!read.boolean(c, "radial_force_absorption").value_or(true)) {
      note = "radial_force_absorption = false";
    } else if (kr && *kr > 0) {
      k = model.capped(*kr, false, c, "radial_stiffness");
    } else {
      k = k_default;
      note = "NOT IN THE FILE: default, replace with the bearing's stiffness";
      defaulted.push_back(model.name(c.id) + fmt::format(" (component {})", c.id));
    }
    t.add("kyy", tomlReal(k), note);
    t.add("kzz", tomlReal(k));
    if (coupling) {
      t.add("k_torsion",
            tomlReal(model.capped(read.real(c, "rotational_stiffness", 0.0), true, c,
                                  "rotational_stiffness")),
            "rotational_stiffness: holds the shaft");
    }
    if (auto ka = read.real(c, "axial_stiffness"))
      t.add("k_axial", tomlReal(model.capped(*ka, false, c, "axial_stiffness")),
            "axial_stiffness (dofs = \"full\")");
    if (auto kb = read.real(c, "bending_stiffness"))
      t.add("k_tilt", tomlReal(model.capped(*kb, true, c, "bending_stiffness")),
            "bending_stiffness (dofs = \"full\")");
    sections.push_back(std::move(t));
  }
  if (!defaulted.empty()) {
    std::string list;
    for (const auto& d : defaulted) list += (list.empty() ? "" : ", ") + d;
    result.warnings.push_back(fmt::format(
        "{} bearing(s) without a radial stiffness in the REXS file get kyy = kzz = {:.3g} N/m "
        "(geardyn import --bearing-stiffness; docs/guide/rexs.md): {}",
        defaulted.size(), k_default, list));
  }

  // Operating point from the chosen load case.
  Operating op = operatingPoints(model, shafts, pm);
  std::string torque_note = "external_load torque_around_u_axis";
  if (op.torque_shaft && op.torque_shaft != op.input) {
    // The torque is given on another shaft (e.g. the output): carried over to the input by the
    // power balance of the lossless train, T_in = −T_B ω_B / ω_in, with ω_B / ω_in from the
    // kinematics of the description being written.
    std::optional<double> ratio;
    try {
      TomlSection probe{"operating_point", "", {}};
      probe.add("input", tomlString(model.name(op.input)));
      probe.add("output", tomlString(model.name(op.output)));
      std::vector<TomlSection> all = sections;
      all.push_back(probe);
      const config::Config c =
          config::parseConfig(renderToml(all, ""), doc.source, config::gearboxSchema());
      std::vector<std::string> ignored;
      const GearTrainModel m(gearTrainFromConfig(c, ignored));
      ratio = m.bodies()[m.bodyIndex(model.name(op.torque_shaft))].speed_ratio;
    } catch (const InputError& e) {
      read.warn(
          fmt::format("the torque is defined on shaft {} but the speed on {}, and the "
                      "speed ratio between them is not known ({}): the operating torque "
                      "is written as 0 (set operating_point.torque)",
                      model.name(op.torque_shaft), model.name(op.input), e.what()));
    }
    for (auto& c : op.cases) c.torque = ratio ? -c.torque * *ratio : 0.0;
    torque_note = ratio ? fmt::format(
                              "-T x {:.6g}: the torque on {} carried to the input "
                              "(lossless power balance)",
                              *ratio, model.name(op.torque_shaft))
                        : "not known (see the warnings)";
  }
  for (const auto& c : op.cases)
    if (c.id != 0 || !doc.load_cases.empty()) result.load_cases.push_back(c);
  std::size_t chosen = 0;
  if (options.load_case) {
    chosen = op.cases.size();
    for (std::size_t i = 0; i < op.cases.size(); ++i)
      if (op.cases[i].id == *options.load_case) chosen = i;
    if (chosen == op.cases.size()) {
      std::string ids;
      for (const auto& c : op.cases) ids += (ids.empty() ? "" : ", ") + std::to_string(c.id);
      throw InputError("load_case", std::to_string(*options.load_case),
                       ids.empty() || ids == "0" ? "the file has no load spectrum"
                                                 : "one of the file's load cases: " + ids);
    }
  }
  const RexsLoadCaseSummary& lc = op.cases[chosen];
  result.load_case = lc.id;
  TomlSection opt{"operating_point",
                  lc.id ? fmt::format("load case {} of the load spectrum", lc.id)
                        : std::string("component attributes (no load spectrum)"),
                  {}};
  opt.add("input", tomlString(model.name(op.input)),
          fmt::format("shaft component {} (defines_speed)", op.input));
  opt.add("speed_rpm", tomlReal(lc.speed_rpm), "rotational_speed");
  opt.add("torque", tomlReal(lc.torque), torque_note);
  opt.add("output", tomlString(model.name(op.output)),
          fmt::format("shaft component {}", op.output));
  sections.push_back(std::move(opt));
  if (op.cases.size() > 1)
    result.warnings.push_back(fmt::format(
        "{}: {} load cases; the operating point is load case {} (geardyn import --load-case ID, "
        "or [gearbox] load_case = ID in an analysis file)",
        doc.source, op.cases.size(), lc.id));

  std::string header = fmt::format(
      "# Gearbox description imported by geardyn from REXS {} ({}, written by {}).\n"
      "# Every value names the REXS component it comes from; docs/guide/rexs.md says what is\n"
      "# mapped, what is not and the defaults.\n",
      doc.version, doc.source, doc.application);
  if (doc.load_cases.empty())
    header += "# no load spectrum: speed and torque from the components' attributes\n";
  for (const auto& c : result.load_cases)
    header +=
        fmt::format("# load case {}: input {:g} rpm, {:g} N m, operating time fraction {:g}\n",
                    c.id, c.speed_rpm, c.torque, c.time_fraction);
  std::vector<TomlSection> all;
  TomlSection gb{"gearbox", "", {}};
  std::string unit_name;
  for (const Component* u : model.ofType({"gear_unit"})) unit_name = u->name;
  gb.add(
      "name",
      tomlString(unit_name.empty() ? std::filesystem::path(doc.source).stem().string() : unit_name),
      unit_name.empty() ? "the file name" : "the gear unit's name");
  gb.add("dofs", tomlString("planar"),
         "rigid shafts; \"full\" with flexible = true shafts gives FE shafts (E, ν, sections)");
  all.push_back(std::move(gb));
  for (auto& s : sections) all.push_back(std::move(s));
  result.toml = renderToml(all, header);
  return result;
}

RexsImport importRexsFile(const std::filesystem::path& file, const RexsImportOptions& options) {
  std::vector<std::string> warnings;
  const io::rexs::Document doc = io::rexs::readRexsFile(file, warnings);
  RexsImport result = importRexsGearbox(doc, options);
  result.warnings.insert(result.warnings.begin(), warnings.begin(), warnings.end());
  return result;
}

config::Config loadGearboxConfig(const std::filesystem::path& file,
                                 const std::vector<std::string>& overrides,
                                 std::optional<int> load_case, std::vector<std::string>& warnings) {
  if (!io::rexs::isRexsPath(file)) {
    if (load_case)
      throw InputError("gearbox.load_case", std::to_string(*load_case),
                       "only with a REXS gearbox file (.rexs, .rexsj, .rexsz); " + file.string() +
                           " is a gearbox TOML file");
    return config::loadConfigFile(file, config::gearboxSchema(), overrides);
  }
  RexsImportOptions options;
  options.load_case = load_case;
  RexsImport imported;
  try {
    imported = importRexsFile(file, options);
  } catch (const InputError& e) {
    // The load case is the analysis file's key (and a sweep's parameter): named as such.
    if (e.key() != "load_case") throw;
    throw InputError("gearbox.load_case", e.value(), e.allowed());
  }
  warnings.insert(warnings.end(), imported.warnings.begin(), imported.warnings.end());
  return config::parseConfig(imported.toml, file.string(), config::gearboxSchema(), overrides);
}

}  // namespace geardyn::io::rexs

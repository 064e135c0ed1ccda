/// The components of a REXS model as gearbox sections (rexs_mapping.h): shafts, gears, parallel
/// stages, additional masses, bearings and couplings. Planetary stages: rexs_planetary.cpp;
/// the operating point and the file: rexs_gearbox.cpp.

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "geardyn/error.h"
#include "geardyn/geometry/gear_pair.h"
#include "geardyn/io/rexs/rexs_reader.h"
#include "rexs_mapping.h"

namespace geardyn::io::rexs::detail {
namespace {

/// Direction [deg] from shaft a's centre to shaft b's in the (y, z) plane, from +y to +z.
std::optional<double> directionBetween(Model& model, int shaft_a, int shaft_b) {
  const auto a = model.read.vector(model.component(shaft_a), "support_vector");
  const auto b = model.read.vector(model.component(shaft_b), "support_vector");
  if (!a || !b) return std::nullopt;
  const double dy = (*b)[1] - (*a)[1], dz = (*b)[2] - (*a)[2];
  if (std::hypot(dy, dz) < 1e-9) return std::nullopt;
  return std::atan2(dz, dy) * 180.0 / std::numbers::pi;
}

}  // namespace

/// One rigid shaft per REXS shaft not taken over by a planetary stage.
void addShafts(GearboxSections& out) {
  Model& model = out.model;
  auto& read = model.read;
  for (const Component* s : model.ofType(kShaftTypes)) {
    if (out.pm.absorbed.count(s->id)) continue;
    out.shafts.insert(s->id);
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
    if (out.pm.extra.count(s->id)) {
      t.add("mass", tomlReal(out.pm.extra.at(s->id).mass), out.pm.extra_comment.at(s->id));
      t.add("polar_inertia", tomlReal(out.pm.extra.at(s->id).inertia), "about this shaft's axis");
    }
    const auto at = read.vector(*s, "support_vector");
    t.add("axial_offset", tomlReal(at ? (*at)[0] : 0.0), "support_vector x");
    t.add("flexible", "false", "rigid body; true needs dofs = \"full\"");
    out.sections.push_back(std::move(t));
  }
}

/// The gears on the shafts (planet gears belong to their stage).
void addGears(GearboxSections& out) {
  Model& model = out.model;
  auto& read = model.read;
  for (const Component* gear : model.ofType(kGearTypes)) {
    if (out.pm.absorbed.count(gear->id)) continue;
    const auto shaft = model.assemblyOf(gear->id, kShaftTypes);
    if (!shaft)
      io::rexs::throwAttributeError(*gear, "(assembly relation)", "",
                                    "a gear must be a part of a shaft");
    TomlSection t{"gears." + model.name(gear->id), gear->label(), {}};
    t.add("shaft", tomlString(model.name(out.bodyOf(*shaft))),
          fmt::format("shaft component {}", *shaft));
    out.gear_specs[gear->id] = addGearKeys(model, *gear, t);
    const double u = read.real(*gear, "u_coordinate_on_shaft", 0.0);
    t.add("position", tomlReal(u), "u_coordinate_on_shaft");
    if (gear->type == "ring_gear") {
      t.add("internal", "true", "ring_gear");
    } else {
      addGearBody(out.gear_specs[gear->id], model.sections(*shaft).outerDiameterAt(u), t);
    }
    out.sections.push_back(std::move(t));
  }
}

/// One mesh per cylindrical stage: gears, position angle, centre distance, stiffness.
void addParallelStages(GearboxSections& out) {
  Model& model = out.model;
  auto& read = model.read;
  for (const Component* st : model.ofType({"cylindrical_stage"})) {
    if (out.pm.absorbed.count(st->id)) continue;
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
        const auto found = out.gear_specs.find(g);
        if (found == out.gear_specs.end())
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
    out.sections.push_back(std::move(t));
  }
}

/// Additional masses on shafts as rigid disks.
void addDisks(GearboxSections& out) {
  Model& model = out.model;
  auto& read = model.read;
  for (const Component* m : model.ofType({"additional_mass"})) {
    const auto shaft = model.assemblyOf(m->id, kShaftTypes);
    if (!shaft) {
      read.warn(fmt::format("{} is on no shaft: left out", m->label()));
      continue;
    }
    TomlSection t{"disks." + model.name(m->id), m->label(), {}};
    t.add("shaft", tomlString(model.name(out.bodyOf(*shaft))),
          fmt::format("shaft component {}", *shaft));
    t.add("position", tomlReal(read.real(*m, "u_coordinate_on_shaft", 0.0)),
          "u_coordinate_on_shaft");
    t.add("mass", tomlReal(read.real(*m, "mass_of_component", 0.0)), "mass_of_component");
    t.add("polar_inertia", tomlReal(read.real(*m, "moment_of_inertia_u_axis", 0.0)),
          "moment_of_inertia_u_axis");
    t.add("diametral_inertia", tomlReal(read.real(*m, "moment_of_inertia_v_axis", 0.0)),
          "moment_of_inertia_v_axis");
    out.sections.push_back(std::move(t));
  }
}

/// Bearings and couplings from the side relations; a bearing without a radial stiffness
/// gets `default_stiffness` [N/m], named in one warning.
void addBearingsAndCouplings(GearboxSections& out, double default_stiffness,
                             std::vector<std::string>& warnings) {
  Model& model = out.model;
  auto& read = model.read;
  std::vector<std::string> defaulted;
  for (const auto* r : model.relations("side")) {
    const auto a = r->ref("assembly"), in = r->ref("inner_part"), outer_part = r->ref("outer_part");
    if (!a || !in || !outer_part) continue;
    const Component& c = model.component(*a);
    if (out.pm.absorbed.count(c.id)) continue;
    const bool bearing = kBearingTypes.count(c.type) > 0,
               coupling = kCouplingTypes.count(c.type) > 0;
    if (!bearing && !coupling) continue;
    if (coupling && !read.boolean(c, "is_engaged").value_or(true)) {
      read.warn(fmt::format("{} is not engaged: left out", c.label()));
      continue;
    }
    int inner = out.bodyOf(*in), outer = out.bodyOf(*outer_part);
    if (model.isCasing(inner)) std::swap(inner, outer);
    if (!out.shafts.count(inner) || (!model.isCasing(outer) && !out.shafts.count(outer))) {
      read.warn(fmt::format("{}: connects {} and {}, not shafts or the casing; left out", c.label(),
                            model.component(*in).label(), model.component(*outer_part).label()));
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
      out.sections.push_back(std::move(t));
      continue;
    }
    TomlSection t{"bearings." + model.name(c.id), c.label(), {}};
    t.add("shaft", tomlString(model.name(inner)), fmt::format("side relation {}", r->id));
    if (!to_housing) t.add("other_shaft", tomlString(model.name(outer)));
    const bool inner_first = inner == out.bodyOf(*in);
    const char* pos_in = "u_coordinate_on_shaft_inner_side";
    const char* pos_out = "u_coordinate_on_shaft_outer_side";
    t.add("position", tomlReal(read.real(c, inner_first ? pos_in : pos_out, 0.0)),
          inner_first ? pos_in : pos_out);
    if (!to_housing)
      t.add("other_position", tomlReal(read.real(c, inner_first ? pos_out : pos_in, 0.0)));
    // A rolling bearing whose file gives its inner geometry: its load-dependent, coupled
    // stiffness (rexs_bearings.cpp) instead of the stiffness keys.
    if (bearing && read.boolean(c, "radial_force_absorption").value_or(true) &&
        addRollingBearingGeometry(model, c, t)) {
      out.sections.push_back(std::move(t));
      continue;
    }
    const auto kr = read.real(c, "radial_stiffness");
    double k = 0.0;
    std::string note = "radial_stiffness";
    if (!read.boolean(c, "radial_force_absorption").value_or(true)) {
      note = "radial_force_absorption = false";
    } else if (kr && *kr > 0) {
      k = model.capped(*kr, false, c, "radial_stiffness");
    } else {
      k = default_stiffness;
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
    out.sections.push_back(std::move(t));
  }
  if (!defaulted.empty()) {
    std::string list;
    for (const auto& d : defaulted) list += (list.empty() ? "" : ", ") + d;
    warnings.push_back(fmt::format(
        "{} bearing(s) without a radial stiffness in the REXS file get kyy = kzz = {:.3g} N/m "
        "(geardyn import --bearing-stiffness; docs/guide/rexs.md): {}",
        defaulted.size(), default_stiffness, list));
  }
}

}  // namespace geardyn::io::rexs::detail

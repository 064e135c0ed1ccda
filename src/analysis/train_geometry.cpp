/// The `geometry` block of `geardyn train`'s summary.json: the parts of the train with the
/// bodies they move with, for drawing (python/geardyn/view3d.py).

#include "train_geometry.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "geardyn/system/detail/train_building.h"

namespace geardyn::analysis::detail {
namespace {

using Json = nlohmann::ordered_json;
constexpr double kDeg = 180.0 / std::numbers::pi;

/// Reference, tip and root radii [m] of a gear cut by its basic rack (ISO 21771:2007 eq. (5),
/// (36), (38); the internal gear's tip and root lie inside and outside its reference circle, as
/// in geometry/internal_gear_pair.cpp): r = z m_n / (2 cos β), r_a = r ± ((h_a* + x) m_n + Δr_a),
/// r_f = r ∓ (h_f* − x) m_n.
Json gearCircles(const GearSpec& g, bool internal) {
  const double r = 0.5 * g.teeth * g.normal_module / std::cos(g.helix_angle);
  const double sign = internal ? -1.0 : 1.0;
  const double tip = r + sign * ((g.addendum_coefficient + g.profile_shift) * g.normal_module +
                                 g.tip_radius_modification);
  const double root = r - sign * (g.dedendum_coefficient - g.profile_shift) * g.normal_module;
  const char* hand = g.helix_angle > 0.0 ? "right" : (g.helix_angle < 0.0 ? "left" : "spur");
  return {{"teeth", g.teeth},
          {"internal", internal},
          {"pitch_radius_m", r},
          {"tip_radius_m", tip},
          {"root_radius_m", root},
          {"bore_radius_m", 0.5 * g.bore_diameter},
          {"face_width_m", g.face_width},
          {"helix_angle_deg", g.helix_angle * kDeg},
          {"hand", hand}};
}

Json shafts(const GearTrainModel& model) {
  Json out = Json::array();
  const auto& spec = model.spec();
  for (std::size_t s = 0; s < spec.shafts.size(); ++s) {
    const TrainShaftSpec& shaft = spec.shafts[s];
    Json sections = Json::array();
    for (const geardyn::detail::ShaftSection& c : geardyn::detail::shaftSections(shaft)) {
      sections.push_back({{"start_x_m", shaft.axial_offset + c.start},
                          {"length_m", c.length},
                          {"outer_radius_m", c.outer_radius},
                          {"inner_radius_m", c.inner_radius}});
    }
    Json nodes = Json::array();
    for (int b : model.shaftNodes(static_cast<int>(s))) nodes.push_back(model.bodies()[b].name);
    out.push_back({{"shaft", shaft.name},
                   {"flexible", shaft.flexible},
                   {"mass_kg", shaft.mass},
                   {"polar_inertia_kg_m2", shaft.polar_inertia},
                   {"sections", sections},
                   {"bodies", nodes}});
  }
  return out;
}

Json gears(const GearTrainModel& model) {
  Json out = Json::array();
  for (const TrainGearSpec& g : model.spec().gears) {
    const int body = geardyn::detail::bodyAtOf(model, g.shaft, "gears." + g.name + ".shaft",
                                               g.position, "gears." + g.name + ".position");
    const int s = geardyn::detail::shaftIndexOf(model.spec(), g.shaft, "gears." + g.name);
    Json j = {{"gear", g.name},
              {"shaft", g.shaft},
              {"body", model.bodies()[body].name},
              {"axial_x_m", model.spec().shafts[s].axial_offset + g.position}};
    j.update(gearCircles(g.gear, g.internal));
    out.push_back(j);
  }
  return out;
}

/// Planets (one gear each, in the sun's mid-face plane) and carriers of the planetary stages.
void planetary(const GearTrainModel& model, Json& planets, Json& carriers) {
  const auto& spec = model.spec();
  for (std::size_t st = 0; st < spec.stages.size(); ++st) {
    const int carrier = geardyn::detail::carrierBody(model, static_cast<int>(st));
    double orbit = 0.0;
    for (const TrainBody& b : model.bodies()) {
      if (b.stage != static_cast<int>(st) || b.planet < 0) continue;
      orbit = std::max(orbit, (b.centre - model.bodies()[carrier].centre).norm());
      Json j = {{"planet", b.name},
                {"stage", spec.stages[st].name},
                {"body", b.name},
                {"carrier_body", model.bodies()[carrier].name},
                {"axial_x_m", b.axial}};
      j.update(gearCircles(spec.stages[st].planet, false));
      planets.push_back(j);
    }
    carriers.push_back({{"stage", spec.stages[st].name},
                        {"body", model.bodies()[carrier].name},
                        {"shaft", spec.stages[st].carrier},
                        {"orbit_radius_m", orbit}});
  }
}

Json bearings(const GearTrainModel& model) {
  Json out = Json::array();
  const auto& spec = model.spec();
  for (const TrainBearingSpec& b : spec.bearings) {
    const std::string key = "bearings." + b.name;
    const int s = geardyn::detail::shaftIndexOf(spec, b.shaft, key + ".shaft");
    const int body = model.bodyAt(s, b.position, key + ".position");
    std::string other;
    if (!b.other_shaft.empty()) {
      other = model
                  .bodies()[geardyn::detail::bodyAtOf(model, b.other_shaft, key + ".other_shaft",
                                                      b.other_position, key + ".other_position")]
                  .name;
    }
    out.push_back({{"bearing", b.name},
                   {"body", model.bodies()[body].name},
                   {"other_body", other},
                   {"axial_x_m", spec.shafts[s].axial_offset + b.position},
                   {"type", b.rolling ? "rolling" : "stiffness"}});
  }
  return out;
}

}  // namespace

nlohmann::ordered_json trainGeometry(const GearTrainModel& model) {
  Json planets = Json::array(), carriers = Json::array();
  planetary(model, planets, carriers);
  Json couplings = Json::array();
  for (const TrainCouplingSpec& c : model.spec().couplings) {
    const auto [a, b] = geardyn::detail::couplingBodies(model, c);
    couplings.push_back({{"coupling", c.name},
                         {"body_a", model.bodies()[a].name},
                         {"body_b", model.bodies()[b].name}});
  }
  Json disks = Json::array();
  for (const TrainDiskSpec& d : model.spec().disks) {
    const int s = geardyn::detail::shaftIndexOf(model.spec(), d.shaft, "disks." + d.name);
    disks.push_back({{"disk", d.name},
                     {"body", model.bodies()[model.bodyAt(s, d.position, "disks." + d.name)].name},
                     {"axial_x_m", model.spec().shafts[s].axial_offset + d.position},
                     {"mass_kg", d.mass},
                     {"polar_inertia_kg_m2", d.polar_inertia}});
  }
  return {{"frame", "x along the shafts, (y, z) across, gravity along -z; lengths in m"},
          {"dofs", toString(model.spec().dofs)},
          {"shafts", shafts(model)},
          {"gears", gears(model)},
          {"planets", planets},
          {"carriers", carriers},
          {"bearings", bearings(model)},
          {"couplings", couplings},
          {"disks", disks}};
}

}  // namespace geardyn::analysis::detail

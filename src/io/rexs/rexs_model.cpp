/// The indexed REXS model and TOML text helpers of the gearbox mapping (rexs_mapping.h).

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>

#include "geardyn/error.h"
#include "geardyn/geometry/gear_mounting.h"
#include "geardyn/io/rexs/rexs_gearbox.h"
#include "geardyn/stiffness/api_stiffness.h"
#include "geardyn/units.h"
#include "rexs_mapping.h"

namespace geardyn::io::rexs::detail {

std::string tomlReal(double v) {
  std::string s = fmt::format("{}", v);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

std::string tomlString(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

std::string tomlReals(const std::vector<double>& v) {
  std::string out = "[";
  for (std::size_t i = 0; i < v.size(); ++i) out += (i ? ", " : "") + tomlReal(v[i]);
  return out + "]";
}

std::string tomlStrings(const std::vector<std::string>& v) {
  std::string out = "[";
  for (std::size_t i = 0; i < v.size(); ++i) out += (i ? ", " : "") + tomlString(v[i]);
  return out + "]";
}

MassProperties ShaftSections::massProperties(double density) const {
  MassProperties p;
  for (std::size_t i = 0; i < lengths.size(); ++i) {
    const double ro = outer[i] / 2, ri = inner[i] / 2;
    const double m = density * std::numbers::pi * (ro * ro - ri * ri) * lengths[i];
    p.mass += m;
    p.inertia += 0.5 * m * (ro * ro + ri * ri);
  }
  return p;
}

double ShaftSections::outerDiameterAt(double u) const {
  for (std::size_t i = 0; i < lengths.size(); ++i)
    if (u >= starts[i] - 1e-9 && u <= starts[i] + lengths[i] + 1e-9) return outer[i];
  return 0.0;
}

namespace {

/// "Cylindrical gear [27]" → "cylindrical_gear_27".
std::string keyOf(const std::string& name) {
  std::string out;
  for (unsigned char ch : name) {
    if (std::isalnum(ch) && ch < 128) {
      out += static_cast<char>(std::tolower(ch));
    } else if (!out.empty() && out.back() != '_') {
      out += '_';
    }
  }
  while (!out.empty() && out.back() == '_') out.pop_back();
  return out;
}

}  // namespace

Model::Model(const Document& d, std::vector<std::string>& w)
    : doc(d), read(w, d.versionNumber()), warnings(w) {
  std::map<std::string, int> used;
  for (const auto& c : doc.components) by_id_[c.id] = &c;
  for (const auto& c : doc.components) {
    std::string key = keyOf(c.name);
    if (key.empty()) key = fmt::format("{}_{}", c.type, c.id);
    if (used.count(key)) key = fmt::format("{}_id{}", key, c.id);
    used[key] = c.id;
    names_[c.id] = key;
  }
  // Caps from the meshes: the stiffest mesh's API estimate (geometry only) and the largest
  // reference radius.
  double k_mesh = 0.0, radius = 0.0;
  for (const Component* g : ofType({"cylindrical_gear", "ring_gear"})) {
    const auto z = read.integer(*g, "number_of_teeth");
    const auto m = read.real(*g, "normal_module");
    const double beta = read.real(*g, "helix_angle_reference_diameter", 0.0);
    const auto b = read.real(*g, "face_width");
    if (z && m) radius = std::max(radius, *m * *z / (2 * std::cos(beta * std::numbers::pi / 180)));
    if (b && *b > 0) k_mesh = std::max(k_mesh, apiMeshStiffness(*b, beta * std::numbers::pi / 180));
  }
  meshes_cap_ = k_mesh > 0;
  if (k_mesh > 0) translational_cap = kRexsRigidToMeshRatio * k_mesh;
  if (radius > 0) rotational_cap = translational_cap * radius * radius;
}

const Component& Model::component(int id) const {
  const auto it = by_id_.find(id);
  if (it == by_id_.end())
    throw InputError(doc.source + ": REXS component id", std::to_string(id),
                     "refers to a component that is not in the model");
  return *it->second;
}

std::vector<const Component*> Model::ofType(const std::set<std::string>& types) const {
  std::vector<const Component*> out;
  for (const auto& c : doc.components)
    if (types.count(c.type)) out.push_back(&c);
  return out;
}

std::vector<const Relation*> Model::relations(const std::string& type) const {
  std::vector<const Relation*> out;
  for (const auto& r : doc.relations)
    if (r.type == type) out.push_back(&r);
  return out;
}

std::vector<int> Model::parts(int id) const {
  std::vector<std::pair<int, int>> found;  // (order, id)
  for (const auto* r : relations("assembly")) {
    if (r->ref("assembly") == id) {
      if (auto part = r->ref("part")) found.emplace_back(r->order.value_or(0), *part);
    }
  }
  std::stable_sort(found.begin(), found.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<int> out;
  for (const auto& f : found) out.push_back(f.second);
  return out;
}

std::optional<int> Model::assemblyOf(int id, const std::set<std::string>& types) const {
  for (const auto* r : relations("assembly")) {
    const auto a = r->ref("assembly");
    if (r->ref("part") == id && a && types.count(component(*a).type)) return a;
  }
  return std::nullopt;
}

const Component* Model::material(int id) const {
  for (const auto* r : relations("reference")) {
    const auto m = r->ref("referenced");
    if (r->ref("origin") == id && m && component(*m).type == "material") return &component(*m);
  }
  return nullptr;
}

double Model::density(int id) {
  const Component* m = material(id);
  if (m && read.has(*m, "density")) return read.requiredReal(*m, "density");
  return 7850.0;
}

ShaftSections Model::sections(int shaft_id) {
  struct Item {
    double u, length, outer, inner;
    int id;
  };
  std::vector<Item> items;
  double next = 0.0;
  for (int id : parts(shaft_id)) {
    const Component& s = component(id);
    if (s.type != "shaft_section") continue;
    if (s.attributes.empty()) {
      read.warn(fmt::format("{} has no attributes: left out of shaft {}", s.label(), shaft_id));
      continue;
    }
    const double length = read.requiredReal(s, "length");
    const double d1 = read.requiredReal(s, "outer_diameter_begin");
    const double d2 = read.real(s, "outer_diameter_end", d1);
    const double i1 = read.real(s, "inner_diameter_begin", 0.0);
    const double i2 = read.real(s, "inner_diameter_end", i1);
    if (!(length > 0) || !(d1 > 0) || !(d2 > 0) || i1 >= d1 || i2 >= d2)
      io::rexs::throwAttributeError(
          s, "length/outer_diameter_begin",
          fmt::format("length {} m, outer {} … {} m, inner {} … {} m", length, d1, d2, i1, i2),
          "a section with positive length and outer diameters above the inner ones");
    // A cone becomes the cylinder of the same volume: d² = (d1² + d1 d2 + d2²) / 3.
    auto equivalent = [](double a, double b) {
      return a == b ? a : std::sqrt((a * a + a * b + b * b) / 3.0);
    };
    items.push_back({read.real(s, "u_coordinate_on_shaft", next), length, equivalent(d1, d2),
                     equivalent(i1, i2), id});
    next = items.back().u + length;
  }
  std::stable_sort(items.begin(), items.end(),
                   [](const Item& a, const Item& b) { return a.u < b.u; });
  ShaftSections out;
  for (const auto& it : items) {
    out.starts.push_back(it.u);
    out.lengths.push_back(it.length);
    out.outer.push_back(it.outer);
    out.inner.push_back(it.inner);
    out.ids.push_back(it.id);
  }
  for (std::size_t i = 1; i < items.size(); ++i) {
    const double gap = items[i].u - (items[i - 1].u + items[i - 1].length);
    if (std::abs(gap) > 1e-6)
      read.warn(
          fmt::format("shaft {}: sections {} and {} {} by {:.4g} mm; the gearbox file "
                      "lays sections end to end (positions along the shaft shift)",
                      component(shaft_id).label(), items[i - 1].id, items[i].id,
                      gap > 0 ? "leave a gap" : "overlap", std::abs(gap) * 1e3));
  }
  return out;
}

double Model::capped(double value, bool rotational, const Component& c, const std::string& what) {
  const double cap = rotational ? rotational_cap : translational_cap;
  if (value <= cap) return value;
  // "<component>: ..." so that one line per kind names every capped component
  // (analysis/warning_groups.h).
  const std::string basis =
      meshes_cap_
          ? fmt::format("= {} x the stiffest mesh{}", kRexsRigidToMeshRatio,
                        rotational ? " x the largest gear radius²" : "")
          : std::string("the default rigid value: the model has no cylindrical gear to scale it");
  read.warn(
      fmt::format("{}: {} {:.3g} {} treated as rigid: written as {:.3g} ({}; "
                  "docs/guide/rexs.md)",
                  c.label(), what, value, rotational ? "N m/rad" : "N/m", cap, basis));
  return cap;
}

GearSpec addGearKeys(Model& model, const Component& gear, TomlSection& s) {
  GearSpec spec;
  constexpr double kDeg = geardyn::units::kDegree;
  auto& read = model.read;
  const auto teeth = read.integer(gear, "number_of_teeth");
  if (!teeth || *teeth < 3)
    io::rexs::throwAttributeError(gear, "number_of_teeth",
                                  teeth ? std::to_string(*teeth) : std::string(),
                                  teeth ? "at least 3 teeth" : "missing: every gear needs teeth");
  spec.teeth = static_cast<int>(*teeth);
  spec.normal_module = read.requiredReal(gear, "normal_module");
  spec.helix_angle = read.real(gear, "helix_angle_reference_diameter", 0.0);
  spec.face_width = read.requiredReal(gear, "face_width");
  s.add("teeth", std::to_string(spec.teeth));
  s.add("module", tomlReal(spec.normal_module), "normal_module");
  s.add("helix_angle_deg", tomlReal(spec.helix_angle),
        "helix_angle_reference_diameter (> 0 right hand)");
  s.add("face_width", tomlReal(spec.face_width));
  spec.helix_angle *= kDeg;
  // Flank data: the `flank` relation's left and right flanks (1.4+: cylindrical_gear_flank),
  // or the gear itself in old files.
  std::optional<double> alpha = read.real(gear, "normal_pressure_angle");
  std::optional<double> shift = read.real(gear, "addendum_modification_coefficient");
  std::vector<int> flanks;
  for (const auto* r : model.relations("flank")) {
    if (r->ref("gear") != gear.id) continue;
    for (const char* role : {"left", "right"})
      if (auto f = r->ref(role)) flanks.push_back(*f);
  }
  for (int f : flanks) {
    const Component& flank = model.component(f);
    const auto a = read.real(flank, "normal_pressure_angle");
    const auto x = read.real(flank, "addendum_modification_coefficient");
    if (a && alpha && std::abs(*a - *alpha) > 1e-9)
      read.warn(
          fmt::format("{}: flanks with different pressure angles ({} and {} deg); the "
                      "first is used",
                      gear.label(), *alpha, *a));
    if (x && shift && std::abs(*x - *shift) > 1e-9)
      read.warn(
          fmt::format("{}: flanks with different profile shifts ({} and {}); the first "
                      "is used",
                      gear.label(), *shift, *x));
    if (!alpha) alpha = a;
    if (!shift) shift = x;
  }
  const std::string flank_note =
      flanks.empty() ? "" : fmt::format(" (flank component {})", flanks.front());
  s.add("pressure_angle_deg", tomlReal(alpha.value_or(20.0)),
        alpha ? "normal_pressure_angle" + flank_note : "not in the file: 20 deg");
  s.add("profile_shift", tomlReal(shift.value_or(0.0)),
        shift ? "addendum_modification_coefficient" + flank_note : "not in the file: 0");
  spec.normal_pressure_angle = alpha.value_or(20.0) * kDeg;
  spec.profile_shift = shift.value_or(0.0);
  if (const Component* m = model.material(gear.id)) {
    const std::string note = fmt::format("material component {}", m->id);
    if (auto e = read.real(*m, "elastic_modulus")) s.add("youngs_modulus", tomlReal(*e), note);
    if (auto nu = read.real(*m, "poisson_ratio")) s.add("poisson_ratio", tomlReal(*nu), note);
    if (auto rho = read.real(*m, "density")) s.add("density", tomlReal(*rho), note);
  }
  return spec;
}

void addGearBody(const GearSpec& gear, double shaft_diameter, TomlSection& s) {
  const double root = rootDiameter(gear);  // the imported gears keep the standard h_f* = 1.25
  if (shaft_diameter <= 0) {
    s.add("bore_diameter", tomlReal(0.5 * root),
          "no shaft section under the gear: half the root diameter");
    return;
  }
  if (shaft_diameter < root) {
    s.add("bore_diameter", tomlReal(shaft_diameter),
          "the shaft section's outer diameter under the gear");
  } else {
    // A pinion cut into its shaft: the section carries its mass; the tooth model's hub radius
    // (Sainsot 2004 fillet foundation, needs r_int < r_f) is taken at half the root radius.
    s.add("body", "false",
          "pinion shaft: the section (>= the root circle) carries the gear's mass");
    s.add("bore_diameter", tomlReal(0.5 * root), "half the root diameter: hub of the tooth model");
  }
}

}  // namespace geardyn::io::rexs::detail

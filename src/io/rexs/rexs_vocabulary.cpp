/// The attribute ids, aliases and units geardyn reads from REXS (rexs_vocabulary.h).

#include "geardyn/io/rexs/rexs_vocabulary.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <numbers>

#include "geardyn/error.h"

namespace geardyn::io::rexs {
namespace {

using D = Dimension;

/// The attribute ids read by the gearbox mapping (config/rexs_gearbox.cpp). `since` from the
/// REXS attribute database of each version (rexs-api-cpp resources/rexs-dbmodel-*.xml).
const std::vector<AttributeSpec>& attributeTable() {
  static const std::vector<AttributeSpec> table = {
      {"support_vector", D::kLength, 100},
      {"u_axis_vector", D::kNone, 100},
      {"w_axis_vector", D::kNone, 100},
      {"defines_speed", D::kNone, 100},
      {"rotational_speed", D::kSpeed, 100},
      {"u_coordinate_on_shaft", D::kLength, 100},
      {"length", D::kLength, 100},
      {"outer_diameter_begin", D::kLength, 100},
      {"outer_diameter_end", D::kLength, 100},
      {"inner_diameter_begin", D::kLength, 100},
      {"inner_diameter_end", D::kLength, 100},
      {"inner_diameter", D::kLength, 100},
      {"outer_diameter", D::kLength, 100},
      {"number_of_teeth", D::kNone, 100},
      {"normal_module", D::kLength, 100},
      {"helix_angle_reference_diameter", D::kAngle, 100},
      {"face_width", D::kLength, 100},
      {"normal_pressure_angle", D::kAngle, 100},
      {"addendum_modification_coefficient", D::kNone, 100},
      {"center_distance", D::kLength, 100},
      {"rotating_angle_around_neg_u_axis", D::kAngle, 100},
      {"u_coordinate_on_shaft_inner_side", D::kLength, 100},
      {"u_coordinate_on_shaft_outer_side", D::kLength, 100},
      {"radial_stiffness", D::kStiffness, 100},
      {"axial_stiffness", D::kStiffness, 100},
      {"bending_stiffness", D::kTorsionalStiffness, 100},
      {"rotational_stiffness", D::kTorsionalStiffness, 100},
      {"radial_force_absorption", D::kNone, 100},
      {"is_engaged", D::kNone, 100},
      {"elastic_modulus", D::kModulus, 100},
      {"poisson_ratio", D::kNone, 100},
      {"density", D::kDensity, 100},
      {"torque_around_u_axis", D::kTorque, 100},
      {"defines_torque", D::kNone, 100},
      {"transmits_torque", D::kNone, 100},
      {"operating_time_fraction", D::kFraction, 104},
      {"mass_of_component", D::kMass, 100},
      {"moment_of_inertia_u_axis", D::kInertia, 100},
      {"moment_of_inertia_v_axis", D::kInertia, 100},
      {"meshing_stiffness_characteristic", D::kStiffness, 105},
      // Rolling bearings' inner geometry (rexs_bearings.cpp).
      {"bearing_type", D::kNone, 100},
      {"number_of_bearing_rows", D::kNone, 100},
      {"distance_between_bearing_rows", D::kLength, 100},
      {"number_of_rolling_elements", D::kNone, 100},
      {"pressure_angle", D::kAngle, 100},
      {"axial_force_absorption_of_row", D::kNone, 101},
      {"raceway_radius_of_inner_ring", D::kLength, 101},
      {"raceway_radius_of_outer_ring", D::kLength, 101},
      {"reference_diameter", D::kLength, 100},
      {"reference_diameter_rolling_bearing", D::kLength, 200},
      {"diameter_of_rolling_element", D::kLength, 100},
      {"length_of_rolling_element", D::kLength, 100},
      {"roller_crowning_radius", D::kLength, 101},
      {"operating_radial_bearing_clearance", D::kLength, 101},
      {"mounted_radial_bearing_clearance", D::kLength, 101},
      {"radial_bearing_clearance", D::kLength, 101},
      {"radial_backlash", D::kLength, 100},
      {"radial_dynamic_load_rating", D::kForce, 101},
      {"dynamic_capacity", D::kForce, 100},
  };
  return table;
}

/// A unit: value_in_file_unit = value * mul / div (a divisor keeps mm → m exact: 50 / 1000).
struct UnitFactor {
  D dimension;
  double mul, div;
};

const std::map<std::string, std::vector<UnitFactor>>& unitTable() {
  constexpr double pi = std::numbers::pi;
  static const std::map<std::string, std::vector<UnitFactor>> table = {
      {"m", {{D::kLength, 1, 1}}},
      {"mm", {{D::kLength, 1, 1000}}},
      {"mum", {{D::kLength, 1, 1e6}}},
      {"µm", {{D::kLength, 1, 1e6}}},
      {"deg", {{D::kAngle, 1, 1}}},
      {"°", {{D::kAngle, 1, 1}}},
      {"rad", {{D::kAngle, 180, pi}}},
      {"1/min", {{D::kSpeed, 1, 1}}},
      {"rpm", {{D::kSpeed, 1, 1}}},
      {"1/s", {{D::kSpeed, 60, 1}}},
      {"rad/s", {{D::kSpeed, 30, pi}}},
      {"Nm", {{D::kTorque, 1, 1}}},
      {"Nmm", {{D::kTorque, 1, 1000}}},
      {"kNm", {{D::kTorque, 1000, 1}}},
      {"N", {{D::kForce, 1, 1}}},
      {"kN", {{D::kForce, 1000, 1}}},
      {"N/m", {{D::kStiffness, 1, 1}}},
      {"N/mm", {{D::kStiffness, 1000, 1}}},
      {"N/mum", {{D::kStiffness, 1e6, 1}}},
      {"kN/mm", {{D::kStiffness, 1e6, 1}}},
      {"Nm/rad", {{D::kTorsionalStiffness, 1, 1}}},
      {"Nmm/rad", {{D::kTorsionalStiffness, 1, 1000}}},
      {"Nm/deg", {{D::kTorsionalStiffness, 180, pi}}},
      {"kg/m^3", {{D::kDensity, 1, 1}}},
      {"kg/dm^3", {{D::kDensity, 1000, 1}}},
      {"g/cm^3", {{D::kDensity, 1000, 1}}},
      {"Pa", {{D::kModulus, 1, 1}}},
      {"N/m^2", {{D::kModulus, 1, 1}}},
      {"N/mm^2", {{D::kModulus, 1e6, 1}}},
      {"MPa", {{D::kModulus, 1e6, 1}}},
      {"GPa", {{D::kModulus, 1e9, 1}}},
      {"%", {{D::kFraction, 1, 100}}},
      {"kg", {{D::kMass, 1, 1}}},
      {"g", {{D::kMass, 1, 1000}}},
      {"kgm^2", {{D::kInertia, 1, 1}}},
      {"kgmm^2", {{D::kInertia, 1, 1e6}}},
  };
  return table;
}

std::string compact(const std::string& unit) {
  std::string out;
  for (char c : unit)
    if (c != ' ' && c != '\t') out += c;
  return out;
}

bool isDimensionless(const std::string& compact_unit) {
  return compact_unit.empty() || compact_unit == "none" || compact_unit == "-";
}

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\r\n");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t\r\n") - a + 1);
}

/// Strict number from text: the whole text must be a number.
std::optional<double> parseNumber(const std::string& raw) {
  const std::string s = trim(raw);
  if (s.empty()) return std::nullopt;
  double v = 0.0;
  const char* first = s.data() + (s[0] == '+' ? 1 : 0);
  const auto [ptr, ec] = std::from_chars(first, s.data() + s.size(), v);
  if (ec != std::errc() || ptr != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

const char* kindName(ValueKind kind) {
  switch (kind) {
    case ValueKind::kText:
      return "text";
    case ValueKind::kReal:
      return "floating_point";
    case ValueKind::kInteger:
      return "integer";
    case ValueKind::kBoolean:
      return "boolean";
    case ValueKind::kReference:
      return "reference_component";
    case ValueKind::kArray:
      return "array";
    case ValueKind::kMatrix:
      return "matrix";
    case ValueKind::kTextArray:
      return "string_array";
  }
  return "?";
}

}  // namespace

const AttributeSpec* attributeSpec(const std::string& id) {
  for (const auto& spec : attributeTable())
    if (id == spec.id) return &spec;
  return nullptr;
}

std::optional<double> toFileUnit(double value, const std::string& unit, Dimension dimension) {
  const std::string u = compact(unit);
  if (dimension == D::kNone) return value;
  if (dimension == D::kFraction && isDimensionless(u)) return value;
  const auto it = unitTable().find(u);
  if (it == unitTable().end()) return std::nullopt;
  for (const auto& f : it->second)
    if (f.dimension == dimension) return value * f.mul / f.div;
  return std::nullopt;
}

void normalize(Document& document, std::vector<std::string>& warnings) {
  const int version = document.versionNumber();
  struct Rename {
    const char* old_name;
    const char* new_name;
    int renamed_in;
  };
  static const Rename kTypes[] = {{"flank_geometry", "cylindrical_gear_flank", 104},
                                  {"stage_gear_data", "cylindrical_stage_gear_data", 104}};
  static const Rename kAttributes[] = {{"load_duration_fraction", "operating_time_fraction", 104}};
  static const Rename kUnits[] = {{"°", "deg", 104}, {"N / mm^2", "MPa", 200}};
  std::set<std::string> warned;
  int custom = 0;
  auto note = [&](const Rename& r, const char* what, int id) {
    if (version < r.renamed_in) return;  // the old name is right for this version
    if (warned.insert(std::string(what) + r.old_name).second)
      warnings.push_back(fmt::format(
          "{}: {} \"{}\" (first at component {}) is the name before REXS {}.{}; read as \"{}\"",
          document.source, what, r.old_name, id, r.renamed_in / 100, r.renamed_in % 100,
          r.new_name));
  };
  auto fixComponent = [&](Component& c) {
    for (const auto& r : kTypes)
      if (c.type == r.old_name) note(r, "component type", c.id), c.type = r.new_name;
    for (auto& a : c.attributes) {
      if (a.id.rfind("custom_", 0) == 0) ++custom;
      for (const auto& r : kAttributes)
        if (a.id == r.old_name) note(r, "attribute", c.id), a.id = r.new_name;
      for (const auto& r : kUnits)
        if (compact(a.unit) == compact(r.old_name)) note(r, "unit", c.id), a.unit = r.new_name;
    }
  };
  for (auto& c : document.components) fixComponent(c);
  for (auto& lc : document.load_cases)
    for (auto& c : lc.components) fixComponent(c);
  if (custom > 0)
    warnings.push_back(
        fmt::format("{}: {} vendor attribute(s) custom_* ignored (not part of the REXS standard)",
                    document.source, custom));
}

void throwAttributeError(const Component& c, const std::string& attribute, const std::string& value,
                         const std::string& allowed) {
  throw InputError("REXS " + c.label() + " attribute " + attribute, value, allowed);
}

void AttributeReader::warn(const std::string& text, const std::string& key) {
  if (warned_.insert(key.empty() ? text : key).second) warnings_.push_back(text);
}

double AttributeReader::convert(const Component& c, const Attribute& a, double value) {
  const AttributeSpec* spec = attributeSpec(a.id);
  const Dimension dim = spec ? spec->dimension : D::kNone;
  if (spec && version_ > 0 && version_ < spec->since)
    warn(fmt::format("attribute {} is part of REXS from {}.{} on, the file is REXS {}.{} (first at "
                     "{}): read anyway",
                     a.id, spec->since / 100, spec->since % 100, version_ / 100, version_ % 100,
                     c.label()),
         "newer attribute " + a.id);
  const auto v = toFileUnit(value, a.unit, dim);
  if (!v) {
    throwAttributeError(c, a.id, fmt::format("{:g} \"{}\"", value, a.unit),
                        "a unit string this attribute can have (e.g. mm, deg, N / m, 1 / min, "
                        "N m, N / mm^2, kg / dm^3; docs/guide/rexs.md lists them)");
  }
  return *v;
}

std::optional<double> AttributeReader::real(const Component& c, const std::string& id) {
  const Attribute* a = c.find(id);
  if (!a) return std::nullopt;
  double value = 0.0;
  switch (a->kind) {
    case ValueKind::kReal:
    case ValueKind::kInteger:
      value = a->number;
      break;
    case ValueKind::kText: {
      const auto v = parseNumber(a->text);
      if (!v) throwAttributeError(c, id, "\"" + a->text + "\"", "a number");
      value = *v;
      break;
    }
    default:
      throwAttributeError(c, id, std::string("a value of kind ") + kindName(a->kind), "a number");
  }
  return convert(c, *a, value);
}

double AttributeReader::real(const Component& c, const std::string& id, double fallback) {
  return real(c, id).value_or(fallback);
}

double AttributeReader::requiredReal(const Component& c, const std::string& id) {
  const auto v = real(c, id);
  if (!v) throwAttributeError(c, id, "", "missing: geardyn needs it to build the gearbox");
  return *v;
}

std::optional<long long> AttributeReader::integer(const Component& c, const std::string& id) {
  const Attribute* a = c.find(id);
  if (!a) return std::nullopt;
  if (a->kind == ValueKind::kInteger || a->kind == ValueKind::kReference)
    return static_cast<long long>(a->number);
  double v = 0.0;
  if (a->kind == ValueKind::kReal) {
    v = a->number;
  } else if (a->kind == ValueKind::kText) {
    const auto parsed = parseNumber(a->text);
    if (!parsed) throwAttributeError(c, id, "\"" + a->text + "\"", "an integer");
    v = *parsed;
    if (a->text.find_first_of(".eE") == std::string::npos) return static_cast<long long>(v);
  } else {
    throwAttributeError(c, id, std::string("a value of kind ") + kindName(a->kind), "an integer");
  }
  if (v != std::round(v) || std::abs(v) > 1e15)
    throwAttributeError(c, id, fmt::format("{}", v), "an integer");
  warn(fmt::format("integer attribute {} written as a floating-point number ({}; first at "
                   "{}): read as {}",
                   id, v, c.label(), static_cast<long long>(v)),
       "integer as float " + id);
  return static_cast<long long>(v);
}

std::optional<bool> AttributeReader::boolean(const Component& c, const std::string& id) {
  const Attribute* a = c.find(id);
  if (!a) return std::nullopt;
  if (a->kind == ValueKind::kBoolean) return a->number != 0.0;
  if (a->kind == ValueKind::kArray && a->array.size() == 1) {
    warn(fmt::format("boolean attribute {} written as a one-element array (first at {})", id,
                     c.label()),
         "boolean as array " + id);
    return a->array[0] != 0.0;
  }
  const std::string t = trim(a->text);
  if (a->kind == ValueKind::kText && (t == "true" || t == "false")) return t == "true";
  if (a->kind == ValueKind::kText && (t == "1" || t == "0")) {
    warn(fmt::format("boolean attribute {} written as {} (first at {})", id, t, c.label()),
         "boolean as number " + id);
    return t == "1";
  }
  throwAttributeError(c, id, a->kind == ValueKind::kText ? "\"" + t + "\"" : kindName(a->kind),
                      "true or false");
}

std::optional<std::string> AttributeReader::text(const Component& c, const std::string& id) {
  const Attribute* a = c.find(id);
  if (!a) return std::nullopt;
  if (a->kind == ValueKind::kText) return trim(a->text);
  if (a->kind == ValueKind::kBoolean) {
    warn(fmt::format("attribute {} is a boolean where a text or enum is expected (first at {})", id,
                     c.label()),
         "boolean as text " + id);
    return a->number != 0.0 ? "true" : "false";
  }
  return fmt::format("{}", a->number);
}

std::optional<std::vector<double>> AttributeReader::array(const Component& c,
                                                          const std::string& id) {
  const Attribute* a = c.find(id);
  if (!a) return std::nullopt;
  if (a->kind != ValueKind::kArray || a->array.empty())
    throwAttributeError(c, id, std::string("a value of kind ") + kindName(a->kind),
                        "an array of numbers");
  std::vector<double> out;
  for (double v : a->array) out.push_back(convert(c, *a, v));
  return out;
}

std::optional<std::vector<double>> AttributeReader::vector(const Component& c,
                                                           const std::string& id) {
  const Attribute* a = c.find(id);
  if (!a) return std::nullopt;
  if (a->kind != ValueKind::kArray || a->array.size() != 3)
    throwAttributeError(c, id, std::string("a value of kind ") + kindName(a->kind),
                        "an array of 3 numbers");
  std::vector<double> out;
  for (double v : a->array) out.push_back(convert(c, *a, v));
  return out;
}

}  // namespace geardyn::io::rexs

#pragma once
/// \file
/// What geardyn understands of REXS: the attribute ids it reads with their physical dimension
/// and the version they appeared in, the renames across versions (aliases), the unit strings
/// and their conversion to the units of the gearbox file (m, deg, rpm, N m, N/m, N m/rad,
/// kg/m³, Pa, fractions), and typed access to attribute values that names the component id,
/// type and attribute in every error. Renames (REXS release notes, rexs-api-cpp's
/// resources): 1.3 → 1.4 `flank_geometry` → `cylindrical_gear_flank`, `stage_gear_data` →
/// `cylindrical_stage_gear_data`, `load_duration_fraction` → `operating_time_fraction`, unit
/// `°` → `deg`; 2.0.0 `N / mm^2` → `MPa`.

#include <optional>
#include <set>
#include <string>
#include <vector>

#include "geardyn/io/rexs/rexs_document.h"

namespace geardyn::io::rexs {

/// Physical dimension of an attribute; each converts to one unit of the gearbox file.
enum class Dimension {
  kNone,                ///< numbers without unit, enums, booleans, texts, references
  kLength,              ///< → m
  kAngle,               ///< → deg
  kSpeed,               ///< → rpm
  kTorque,              ///< → N m
  kForce,               ///< → N
  kStiffness,           ///< → N/m
  kTorsionalStiffness,  ///< → N m/rad (also bending stiffness)
  kDensity,             ///< → kg/m³
  kModulus,             ///< → Pa
  kFraction,            ///< → [-] (percent / 100)
  kMass,                ///< → kg
  kInertia,             ///< → kg m²
};

/// An attribute id geardyn reads.
struct AttributeSpec {
  const char* id;
  Dimension dimension;
  int since;  ///< first REXS version (major * 100 + minor) with this id
};

/// The table of attribute ids geardyn reads (null when it reads no attribute of this id).
const AttributeSpec* attributeSpec(const std::string& id);

/// Value of `value` written in `unit`, in the gearbox file's unit of `dimension`; nullopt for
/// a unit string that is not known for this dimension.
std::optional<double> toFileUnit(double value, const std::string& unit, Dimension dimension);

/// Applies the renames of the alias table (component types, attribute ids, unit strings) so
/// that the mapping sees the newest names; an old name inside a file of a version that
/// already had the new one gets one warning per name. Vendor `custom_*` attributes are counted
/// in one warning.
void normalize(Document& document, std::vector<std::string>& warnings);

/// Typed, unit-converted access to attribute values. Oddities that can be understood (an
/// integer written as 17.0, a boolean written as text) are accepted with one warning each;
/// what cannot be understood is an InputError naming the component id, type and attribute.
class AttributeReader {
 public:
  /// `version`: the file's REXS version (Document::versionNumber); an attribute read from a
  /// file older than the version that introduced it gets a warning (read anyway).
  explicit AttributeReader(std::vector<std::string>& warnings, int version = 0)
      : warnings_(warnings), version_(version) {}

  bool has(const Component& c, const std::string& id) const { return c.find(id) != nullptr; }
  /// Real value in the gearbox file's unit of the attribute's dimension (attributeSpec).
  std::optional<double> real(const Component& c, const std::string& id);
  double real(const Component& c, const std::string& id, double fallback);
  double requiredReal(const Component& c, const std::string& id);
  std::optional<long long> integer(const Component& c, const std::string& id);
  std::optional<bool> boolean(const Component& c, const std::string& id);
  std::optional<std::string> text(const Component& c, const std::string& id);
  /// An array of numbers in the gearbox file's unit (e.g. meshing_stiffness_characteristic).
  std::optional<std::vector<double>> array(const Component& c, const std::string& id);
  /// A 3-vector in the gearbox file's unit (support_vector, u_axis_vector, ...).
  std::optional<std::vector<double>> vector(const Component& c, const std::string& id);
  /// Warns once per distinct `key` (default: the text itself).
  void warn(const std::string& text, const std::string& key = "");

 private:
  double convert(const Component& c, const Attribute& a, double value);
  std::vector<std::string>& warnings_;
  int version_ = 0;
  std::set<std::string> warned_;
};

/// InputError naming the component (id, type, name) and attribute.
[[noreturn]] void throwAttributeError(const Component& c, const std::string& attribute,
                                      const std::string& value, const std::string& allowed);

}  // namespace geardyn::io::rexs

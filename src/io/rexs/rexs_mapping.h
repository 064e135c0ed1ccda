#pragma once
/// What the REXS → gearbox mapping's parts share (rexs_gearbox.cpp, rexs_planetary.cpp): the
/// index of the model, the TOML sections being written and the caps for "rigid" values.

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "geardyn/geometry/gear.h"
#include "geardyn/io/rexs/rexs_document.h"
#include "geardyn/io/rexs/rexs_vocabulary.h"

namespace geardyn::io::rexs::detail {

using io::rexs::Component;
using io::rexs::Document;
using io::rexs::Relation;

struct TomlLine {
  std::string key, value, comment;
};

/// One [section] of the gearbox file, with its comment (the REXS component it comes from).
struct TomlSection {
  std::string header, comment;
  std::vector<TomlLine> lines;
  void add(const std::string& key, const std::string& value, const std::string& comment = "") {
    lines.push_back({key, value, comment});
  }
};

std::string tomlReal(double v);
std::string tomlString(const std::string& s);
std::string tomlReals(const std::vector<double>& v);
std::string tomlStrings(const std::vector<std::string>& v);

/// Mass [kg] and polar inertia [kg m²] of a body about its own axis.
struct MassProperties {
  double mass = 0.0, inertia = 0.0;
};

/// The sections of a shaft in the gearbox file's form.
struct ShaftSections {
  std::vector<double> lengths, outer, inner;  ///< [m]
  std::vector<double> starts;                 ///< u of each section's start [m]
  std::vector<int> ids;                       ///< REXS component ids
  MassProperties massProperties(double density) const;
  /// Outer diameter of the section at u (0 when u is outside every section).
  double outerDiameterAt(double u) const;
};

/// The model with look-ups by relation, the names given to components, and the warnings.
class Model {
 public:
  Model(const Document& doc, std::vector<std::string>& warnings);

  const Document& doc;
  io::rexs::AttributeReader read;
  std::vector<std::string>& warnings;

  const Component& component(int id) const;
  std::vector<const Component*> ofType(const std::set<std::string>& types) const;
  std::vector<const Relation*> relations(const std::string& type) const;
  /// Parts of an assembly relation whose assembly is `id` (in relation order).
  std::vector<int> parts(int id) const;
  /// The assembly (e.g. the shaft) that holds part `id`, among components of `types`.
  std::optional<int> assemblyOf(int id, const std::set<std::string>& types) const;
  /// The material a component refers to (reference relation), or null.
  const Component* material(int id) const;
  /// The gearbox-file name of a component: its REXS name made a TOML key, unique.
  const std::string& name(int id) const { return names_.at(id); }
  bool isShaft(int id) const { return component(id).type == "shaft"; }
  bool isCasing(int id) const { return component(id).type == "gear_casing"; }

  ShaftSections sections(int shaft_id);
  /// Density [kg/m³] (and E [Pa], ν) of a component's material; steel when none.
  double density(int id);

  /// Stiffness caps (kRexsRigidToMeshRatio × the stiffest mesh, and that × the largest gear
  /// radius squared for rotational stiffness).
  double translational_cap = 1e11, rotational_cap = 1e9;
  /// A stiffness value [N/m or N m/rad] capped at the rigid value, with a warning.
  double capped(double value, bool rotational, const Component& c, const std::string& what);

 private:
  std::map<int, std::string> names_;
  std::map<int, const Component*> by_id_;
  bool meshes_cap_ = false;  ///< the caps scale with the model's gears (else the defaults)
};

/// What the planetary stages take over from the general mapping.
struct PlanetaryMapping {
  std::set<int> absorbed;               ///< shafts, gears, stages, bearings, couplings, plates
  std::map<int, int> body_of;           ///< carrier member → the carrier shaft that stands for it
  std::map<int, MassProperties> extra;  ///< carrier shaft → merged members' mass and inertia
  std::map<int, std::string> extra_comment;
  std::vector<TomlSection> sections;
  int stages = 0;
};

PlanetaryMapping mapPlanetaryStages(Model& model);

/// Writes the gear keys (teeth, module, angles, face width, shift, material) of a REXS gear and
/// returns them as a GearSpec.
GearSpec addGearKeys(Model& model, const Component& gear, TomlSection& section);

/// Writes bore_diameter (the shaft section's outer diameter under the gear) or, when that
/// section reaches the gear's root circle (a pinion cut into its shaft), body = false: the
/// section already carries the gear's mass.
void addGearBody(const GearSpec& gear, double shaft_diameter, TomlSection& section);

/// Writes a rolling bearing's inner geometry (its rows and rolling elements: type, elements,
/// diameters, contact angle, raceway radii, roller length, clearance, C) as the gearbox file's
/// geometry keys and returns true; false when the file does not give it — a catalogue bearing
/// by its designation only, a type geardyn has no model of, or rows that lack an attribute (a
/// warning names it) —, and the caller writes the stiffness keys (rexs_bearings.cpp).
bool addRollingBearingGeometry(Model& model, const Component& bearing, TomlSection& section);

/// The REXS component types the mapping writes as shafts, gears, bearings and couplings.
inline const std::set<std::string> kShaftTypes = {"shaft"};
inline const std::set<std::string> kGearTypes = {"cylindrical_gear", "ring_gear"};
inline const std::set<std::string> kBearingTypes = {
    "concept_bearing", "rolling_bearing_with_catalog_geometry",
    "rolling_bearing_with_detailed_geometry", "fluid_bearing"};
inline const std::set<std::string> kCouplingTypes = {"coupling", "switchable_coupling"};

/// The gearbox sections being written and what the steps of the mapping hand on
/// (rexs_components.cpp, rexs_gearbox.cpp).
struct GearboxSections {
  Model& model;
  PlanetaryMapping pm;
  std::vector<TomlSection> sections;
  std::set<int> shafts;                ///< shaft components written as shafts
  std::map<int, GearSpec> gear_specs;  ///< gear component → its geometry
  /// The shaft that stands for component `id` (a carrier member → its carrier shaft).
  int bodyOf(int id) const { return pm.body_of.count(id) ? pm.body_of.at(id) : id; }
};
void addShafts(GearboxSections& out);
void addGears(GearboxSections& out);
void addParallelStages(GearboxSections& out);
void addDisks(GearboxSections& out);
void addBearingsAndCouplings(GearboxSections& out, double default_stiffness,
                             std::vector<std::string>& warnings);

}  // namespace geardyn::io::rexs::detail

#pragma once
/// \file
/// A REXS model (Reusable Engineering EXchange Standard, FVA; https://www.rexs.info) as read from
/// a file, before any meaning is given to it: components (id, type, name, attributes), relations
/// (type, roles and the components they refer to) and the load spectrum's load cases. The XML
/// (.rexs), JSON (.rexsj) and zipped (.rexsz) readers (rexs_reader.h) all produce this; the
/// gearbox mapping (config/rexs_gearbox.h) reads only this. Format reference: the REXS
/// specification and fva-net/rexs-api-cpp (read, not used).

#include <optional>
#include <string>
#include <vector>

namespace geardyn::io::rexs {

/// How an attribute's value was written. XML gives every scalar as text (kText, parsed when it
/// is read); JSON names the kind.
enum class ValueKind {
  kText,       ///< XML scalar, JSON "string"/"enum"/"date_time"/"file_reference"
  kReal,       ///< JSON "floating_point"
  kInteger,    ///< JSON "integer"
  kBoolean,    ///< JSON "boolean"
  kReference,  ///< JSON "reference_component"
  kArray,      ///< numbers: XML <array>, JSON "*_array" (also coded arrays)
  kMatrix,     ///< rows of numbers: XML <matrix>, JSON "*_matrix", "array_of_integer_arrays"
  kTextArray,  ///< JSON "string_array", "enum_array", "boolean_array" written as text
};

struct Component;

/// One attribute of a component. The value accessors convert and check it and throw an
/// InputError naming the component id, type and attribute when it cannot be understood.
struct Attribute {
  std::string id;
  std::string unit;  ///< as written ("mm", "N / mm^2", "none", ...); "" when absent
  ValueKind kind = ValueKind::kText;
  std::string text;                         ///< kText, kTextArray (joined)
  double number = 0.0;                      ///< kReal, kInteger, kBoolean (0/1), kReference
  std::vector<double> array;                ///< kArray
  std::vector<std::vector<double>> matrix;  ///< kMatrix
};

/// A component: a gear, a shaft, a bearing, a material ...
struct Component {
  int id = 0;
  std::string type;
  std::string name;
  std::vector<Attribute> attributes;

  /// The attribute with this id, or null.
  const Attribute* find(const std::string& attribute_id) const;
  /// "component 24 (rolling_bearing_with_catalog_geometry \"6210-2Z\")": how errors name it.
  std::string label() const;
};

/// One end of a relation: the component it refers to and its role in the relation.
struct Ref {
  int id = 0;
  std::string role;
  std::string hint;  ///< the referred component's type, as the writer noted it (may be empty)
};

/// A relation between components (assembly, side, stage, stage_gear_data, flank, reference, ...).
struct Relation {
  int id = 0;
  std::string type;
  std::optional<int> order;
  std::vector<Ref> refs;

  /// The component id in `role`, or nullopt.
  std::optional<int> ref(const std::string& role) const;
};

/// A load case of the load spectrum: per component, the attributes that hold in this case
/// (speeds, torques, the operating time fraction).
struct LoadCase {
  int id = 0;
  std::vector<Component> components;
};

struct Document {
  std::string version;      ///< "1.0" ... "1.7", "2.0.0"
  std::string application;  ///< applicationId and applicationVersion
  std::string source;       ///< file name, for messages
  std::vector<Component> components;
  std::vector<Relation> relations;
  std::vector<LoadCase> load_cases;

  /// The component with this id, or null.
  const Component* component(int id) const;
  /// Version as a comparable number: major * 100 + minor (1.4 → 104, 2.0.0 → 200).
  int versionNumber() const;
};

/// Checks that every relation refers to components that exist (InputError naming the relation
/// and the missing id otherwise) and that ids are unique.
void checkReferences(const Document& document);

}  // namespace geardyn::io::rexs

/// REXS JSON (.rexsj) with nlohmann-json (rexs_reader.h).

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "geardyn/error.h"
#include "geardyn/io/rexs/rexs_reader.h"
#include "rexs_coded_array.h"

namespace geardyn::io::rexs {
namespace {

using Json = nlohmann::json;

int jsonIdOf(const Json& node, const char* key, const std::string& where) {
  if (!node.is_object() || !node.contains(key) || !node.at(key).is_number()) {
    throw InputError(
        where + " key " + key,
        node.is_object() && node.contains(key) ? node.at(key).dump() : std::string("missing"),
        "an integer id");
  }
  const double v = node.at(key).get<double>();
  if (v != static_cast<int>(v))
    throw InputError(where + " key " + key, node.at(key).dump(), "an integer id");
  return static_cast<int>(v);
}

std::string stringOf(const Json& node, const char* key) {
  return node.contains(key) && node.at(key).is_string() ? node.at(key).get<std::string>() : "";
}

std::vector<double> numbers(const Json& array, const Component& c, const std::string& id) {
  if (array.is_object() && array.contains("code") && array.contains("value")) {
    const auto values = detail::decodeCodedArray(stringOf(array, "code"), stringOf(array, "value"));
    if (!values)
      throw InputError("REXS " + c.label() + " attribute " + id, array.dump(),
                       "a coded array: int32, float32 or float64, base64");
    return *values;
  }
  std::vector<double> out;
  if (!array.is_array())
    throw InputError("REXS " + c.label() + " attribute " + id, array.dump(), "an array");
  for (const auto& v : array) {
    if (v.is_number())
      out.push_back(v.get<double>());
    else if (v.is_boolean())
      out.push_back(v.get<bool>() ? 1.0 : 0.0);
    else
      throw InputError("REXS " + c.label() + " attribute " + id, v.dump(), "a number");
  }
  return out;
}

Attribute attributeOf(const Json& a, const Component& c) {
  Attribute at;
  at.id = stringOf(a, "id");
  at.unit = stringOf(a, "unit");
  for (const auto& [key, value] : a.items()) {
    if (key == "id" || key == "unit") continue;
    if (key == "floating_point" || key == "integer" || key == "reference_component") {
      if (!value.is_number())
        throw InputError("REXS " + c.label() + " attribute " + at.id, value.dump(), "a number");
      at.kind = key == "floating_point" ? ValueKind::kReal
                : key == "integer"      ? ValueKind::kInteger
                                        : ValueKind::kReference;
      at.number = value.get<double>();
    } else if (key == "boolean") {
      at.kind = ValueKind::kBoolean;
      if (!value.is_boolean())
        throw InputError("REXS " + c.label() + " attribute " + at.id, value.dump(), "a boolean");
      at.number = value.get<bool>() ? 1.0 : 0.0;
    } else if (key == "string" || key == "enum" || key == "date_time" || key == "file_reference") {
      at.kind = ValueKind::kText;
      at.text = value.is_string() ? value.get<std::string>() : value.dump();
    } else if (key.size() > 6 && key.compare(key.size() - 6, 6, "_array") == 0 &&
               key != "string_array" && key != "enum_array") {
      at.kind = ValueKind::kArray;
      at.array = numbers(value, c, at.id);
    } else if (key == "string_array" || key == "enum_array") {
      at.kind = ValueKind::kTextArray;
      at.text = value.dump();
    } else if ((key.size() > 7 && key.compare(key.size() - 7, 7, "_matrix") == 0) ||
               key == "array_of_integer_arrays") {
      at.kind = ValueKind::kMatrix;
      if (!value.is_array())
        throw InputError("REXS " + c.label() + " attribute " + at.id, value.dump(), "rows");
      for (const auto& row : value) at.matrix.push_back(numbers(row, c, at.id));
    } else {
      throw InputError("REXS " + c.label() + " attribute " + at.id, "value key \"" + key + "\"",
                       "one of floating_point, integer, boolean, string, enum, "
                       "reference_component, *_array, *_matrix");
    }
  }
  return at;
}

Component jsonComponentOf(const Json& node, const std::string& where) {
  Component c;
  c.id = jsonIdOf(node, "id", where);
  c.type = stringOf(node, "type");
  c.name = stringOf(node, "name");
  if (node.contains("attributes")) {
    for (const auto& a : node.at("attributes")) c.attributes.push_back(attributeOf(a, c));
  }
  return c;
}

/// Deepest nesting of objects and arrays accepted. A REXS model nests 7 levels ({"model":
/// {"components": [{"attributes": [{"floating_point_matrix": [[…]]}]}]}}); 64 leaves room for
/// extensions. Deeper input is refused before it is parsed: nlohmann-json's dump(), used in the
/// error messages, recurses once per level (a 10^5-deep array would overflow the stack).
constexpr int kMaxJsonDepth = 64;

void requireJsonDepth(std::string_view text, const std::string& source) {
  int depth = 0;
  bool in_string = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\')
        ++i;
      else if (c == '"')
        in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxJsonDepth)
        throw InputError(fmt::format("{}: JSON at byte {}", source, i),
                         fmt::format("arrays and objects nested deeper than {}", kMaxJsonDepth),
                         fmt::format("at most {} levels of nesting", kMaxJsonDepth));
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
}

}  // namespace

Document parseRexsJson(std::string_view text, const std::string& source) {
  requireJsonDepth(text, source);
  Json json;
  try {
    json = Json::parse(text.begin(), text.end());
  } catch (const Json::parse_error& e) {
    throw InputError(fmt::format("{}: JSON at byte {}", source, e.byte), e.what(),
                     "a well-formed REXS JSON file (truncated or not JSON?)");
  } catch (const Json::exception& e) {
    // The parser's other refusals, e.g. a number beyond double's range (out_of_range.406,
    // "9E37066399828104": found by fuzz/rexs_fuzzer.cpp, it escaped as an internal error).
    throw InputError(source + ": JSON", e.what(), "a REXS JSON file whose numbers are doubles");
  }
  if (!json.is_object() || !json.contains("model") || !json.at("model").is_object())
    throw InputError(source, "no \"model\" object", "a REXS JSON file has {\"model\": {…}}");
  const Json& model = json.at("model");
  Document d;
  d.source = source;
  d.version = stringOf(model, "version");
  d.application =
      fmt::format("{} {}", stringOf(model, "applicationId"), stringOf(model, "applicationVersion"));
  if (d.version.empty())
    throw InputError(source + ": model.version", "", "the REXS version, e.g. 1.6");
  try {
    if (model.contains("relations")) {
      for (const auto& r : model.at("relations")) {
        Relation rel;
        const std::string where = source + ": relation";
        rel.id = jsonIdOf(r, "id", where);
        rel.type = stringOf(r, "type");
        if (r.contains("order") && r.at("order").is_number()) rel.order = r.at("order").get<int>();
        for (const auto& ref : r.at("refs"))
          rel.refs.push_back({jsonIdOf(ref, "id", fmt::format("{} {}", where, rel.id)),
                              stringOf(ref, "role"), stringOf(ref, "hint")});
        d.relations.push_back(std::move(rel));
      }
    }
    if (model.contains("components")) {
      for (const auto& c : model.at("components"))
        d.components.push_back(jsonComponentOf(c, source + ": component"));
    }
    if (model.contains("load_spectrum")) {
      for (const auto& lc : model.at("load_spectrum").value("load_cases", Json::array())) {
        LoadCase load_case;
        load_case.id = jsonIdOf(lc, "id", source + ": load case");
        for (const auto& c : lc.value("components", Json::array()))
          load_case.components.push_back(jsonComponentOf(c, source + ": load case component"));
        d.load_cases.push_back(std::move(load_case));
      }
    }
  } catch (const Json::exception& e) {
    throw InputError(source, e.what(), "the structure of a REXS JSON model");
  }
  return d;
}

}  // namespace geardyn::io::rexs

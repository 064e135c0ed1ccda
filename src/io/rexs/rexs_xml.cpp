/// REXS XML (.rexs) with pugixml (rexs_reader.h).

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <optional>
#include <pugixml.hpp>

#include "geardyn/error.h"
#include "geardyn/io/rexs/rexs_reader.h"
#include "rexs_coded_array.h"

namespace geardyn::io::rexs {
namespace {

int idOf(const pugi::xml_node& node, const char* attribute, const std::string& source) {
  const std::string text = node.attribute(attribute).value();
  int id = 0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), id);
  if (text.empty() || ec != std::errc() || ptr != text.data() + text.size()) {
    throw InputError(fmt::format("{}: <{}> at offset {} attribute {}", source, node.name(),
                                 node.offset_debug(), attribute),
                     "\"" + text + "\"", "an integer id");
  }
  return id;
}

/// The numbers of an array's <c> elements ("true"/"false" as 1/0), or nullopt when one is not
/// a number (a string or enum array: kept as text, an error only if geardyn reads it).
std::optional<std::vector<double>> numbersOf(const pugi::xml_node& parent, const char* element) {
  std::vector<double> out;
  for (const auto& c : parent.children(element)) {
    const std::string text = c.text().get();
    if (text == "true" || text == "false") {
      out.push_back(text == "true" ? 1.0 : 0.0);
      continue;
    }
    double v = 0.0;
    const char* first = text.data();
    while (*first == ' ') ++first;
    const auto [ptr, ec] = std::from_chars(first, text.data() + text.size(), v);
    if (ec != std::errc() || !std::isfinite(v)) return std::nullopt;
    out.push_back(v);
  }
  return out;
}

/// Rows of a <matrix> (<r> of <c>) or <array_of_arrays> (<array> of <c>).
void readRows(const pugi::xml_node& node, const char* row, Attribute& at) {
  at.kind = ValueKind::kMatrix;
  for (const auto& r : node.children(row)) {
    auto values = numbersOf(r, "c");
    if (!values) {
      at.kind = ValueKind::kTextArray;
      at.matrix.clear();
      return;
    }
    at.matrix.push_back(std::move(*values));
  }
}

Component componentOf(const pugi::xml_node& node, const std::string& source) {
  Component c;
  c.id = idOf(node, "id", source);
  c.type = node.attribute("type").value();
  c.name = node.attribute("name").value();
  for (const auto& a : node.children("attribute")) {
    Attribute at;
    at.id = a.attribute("id").value();
    at.unit = a.attribute("unit").value();
    if (const auto array = a.child("array")) {
      at.kind = ValueKind::kArray;
      if (const auto code = array.attribute("code")) {
        const auto values = detail::decodeCodedArray(code.value(), array.text().get());
        if (!values)
          throw InputError("REXS " + c.label() + " attribute " + at.id,
                           std::string("code \"") + code.value() + "\"",
                           "a coded array: int32, float32 or float64, base64");
        at.array = *values;
      } else if (auto values = numbersOf(array, "c")) {
        at.array = std::move(*values);
      } else {
        at.kind = ValueKind::kTextArray;
      }
    } else if (const auto matrix = a.child("matrix")) {
      readRows(matrix, "r", at);
    } else if (const auto arrays = a.child("array_of_arrays")) {
      readRows(arrays, "array", at);
    } else {
      at.kind = ValueKind::kText;
      at.text = a.text().get();
    }
    c.attributes.push_back(std::move(at));
  }
  return c;
}

}  // namespace

Document parseRexsXml(std::string_view text, const std::string& source) {
  pugi::xml_document xml;
  const pugi::xml_parse_result parsed = xml.load_buffer(text.data(), text.size());
  if (!parsed) {
    throw InputError(fmt::format("{}: XML at offset {}", source, parsed.offset),
                     parsed.description(), "a well-formed REXS XML file (truncated or not XML?)");
  }
  const pugi::xml_node model = xml.child("model");
  if (!model)
    throw InputError(source, "no <model> element", "a REXS XML file has <model version=\"…\">");
  Document d;
  d.source = source;
  d.version = model.attribute("version").value();
  d.application = fmt::format("{} {}", model.attribute("applicationId").value(),
                              model.attribute("applicationVersion").value());
  if (d.version.empty())
    throw InputError(source + ": <model> attribute version", "", "the REXS version, e.g. 1.6");
  for (const auto& r : model.child("relations").children("relation")) {
    Relation rel;
    rel.id = idOf(r, "id", source);
    rel.type = r.attribute("type").value();
    if (r.attribute("order")) rel.order = idOf(r, "order", source);
    for (const auto& ref : r.children("ref"))
      rel.refs.push_back(
          {idOf(ref, "id", source), ref.attribute("role").value(), ref.attribute("hint").value()});
    d.relations.push_back(std::move(rel));
  }
  for (const auto& c : model.child("components").children("component"))
    d.components.push_back(componentOf(c, source));
  for (const auto& spectrum : model.children("load_spectrum")) {
    for (const auto& lc : spectrum.children("load_case")) {
      LoadCase load_case;
      load_case.id = idOf(lc, "id", source);
      for (const auto& c : lc.children("component"))
        load_case.components.push_back(componentOf(c, source));
      d.load_cases.push_back(std::move(load_case));
    }
  }
  return d;
}

}  // namespace geardyn::io::rexs

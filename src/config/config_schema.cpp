#include "geardyn/config/config_schema.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <numbers>

#include "geardyn/config/renamed_keys.h"
#include "geardyn/error.h"

namespace geardyn::config {
namespace {

constexpr double kDegPerRad = 180.0 / std::numbers::pi;

struct ConvertedRename {
  std::string_view from, to;
  ValueConversion conversion;
};

/// Every rename whose value converts (issue #31); the schemas declare the renames themselves.
constexpr std::array kConvertedRenames{
    ConvertedRename{"model.backlash",
                    "model.normal_backlash",
                    {2.0, "× 2: model.backlash was the half clearance b, the new key is j = 2b"}},
    ConvertedRename{"model.transmission_error.phases",
                    "model.transmission_error.phases_deg",
                    {kDegPerRad, "× 180/π: the old key was in radians"}},
    ConvertedRename{"model.extra_force_phases",
                    "model.extra_force_phases_deg",
                    {kDegPerRad, "× 180/π: the old key was in radians"}},
    ConvertedRename{"mesh.te_x_phase",
                    "mesh.te_x_phase_deg",
                    {kDegPerRad, "× 180/π: the old key was in radians"}},
    ConvertedRename{"mesh.te_y_phase",
                    "mesh.te_y_phase_deg",
                    {kDegPerRad, "× 180/π: the old key was in radians"}},
    ConvertedRename{"mesh.line_of_action_angle",
                    "mesh.line_of_action_angle_deg",
                    {kDegPerRad, "× 180/π: the old key was in radians"}},
    ConvertedRename{"runout.pinion_phase",
                    "runout.pinion_phase_deg",
                    {kDegPerRad, "× 180/π: the old key was in radians"}},
    ConvertedRename{"runout.gear_phase",
                    "runout.gear_phase_deg",
                    {kDegPerRad, "× 180/π: the old key was in radians"}},
};

std::string kindName(ValueKind kind) {
  switch (kind) {
    case ValueKind::kInteger:
      return "integer";
    case ValueKind::kReal:
      return "number";
    case ValueKind::kBoolean:
      return "boolean";
    case ValueKind::kString:
      return "string";
    case ValueKind::kRealList:
      return "list of numbers";
    case ValueKind::kStringList:
      return "list of strings";
  }
  return "?";
}

std::string article(ValueKind kind) {
  switch (kind) {
    case ValueKind::kInteger:
      return "an integer";
    case ValueKind::kReal:
      return "a number";
    case ValueKind::kBoolean:
      return "true or false";
    case ValueKind::kString:
      return "a string";
    case ValueKind::kRealList:
      return "a list of numbers";
    case ValueKind::kStringList:
      return "a list of strings";
  }
  return "?";
}

std::string parentOf(const std::string& path) {
  const auto dot = path.rfind('.');
  return dot == std::string::npos ? std::string() : path.substr(0, dot);
}

}  // namespace

std::string KeySpec::section() const {
  return parentOf(path);
}

std::string KeySpec::name() const {
  const auto dot = path.rfind('.');
  return dot == std::string::npos ? path : path.substr(dot + 1);
}

std::string KeySpec::allowedText() const {
  std::string text = article(kind);
  if (kind == ValueKind::kRealList) text += " each";
  if (minimum && maximum) {
    text += fmt::format(" in {}{:g}, {:g}{}", minimum_exclusive ? "(" : "[", *minimum, *maximum,
                        maximum_exclusive ? ")" : "]");
  } else if (minimum) {
    text += fmt::format(" {} {:g}", minimum_exclusive ? ">" : ">=", *minimum);
  } else if (maximum) {
    text += fmt::format(" {} {:g}", maximum_exclusive ? "<" : "<=", *maximum);
  }
  if (!choices.empty()) {
    text = kind == ValueKind::kStringList ? "a list of" : "one of";
    for (std::size_t i = 0; i < choices.size(); ++i) {
      text += fmt::format("{} \"{}\"", i ? "," : "", choices[i]);
    }
  }
  if (kind == ValueKind::kReal || kind == ValueKind::kRealList) {
    if (!unit.empty() && unit != "-") text += " [" + unit + "]";
  }
  return text;
}

KeyBuilder& KeyBuilder::unit(std::string unit) {
  spec_->unit = std::move(unit);
  return *this;
}
KeyBuilder& KeyBuilder::doc(std::string description) {
  spec_->description = std::move(description);
  return *this;
}
KeyBuilder& KeyBuilder::required() {
  spec_->required = true;
  spec_->default_value = nullptr;
  return *this;
}
KeyBuilder& KeyBuilder::optional() {
  spec_->required = false;
  spec_->default_value = nullptr;
  return *this;
}
KeyBuilder& KeyBuilder::defaultValue(nlohmann::ordered_json value) {
  spec_->required = false;
  spec_->default_value = std::move(value);
  return *this;
}
KeyBuilder& KeyBuilder::min(double value) {
  spec_->minimum = value;
  spec_->minimum_exclusive = false;
  return *this;
}
KeyBuilder& KeyBuilder::greaterThan(double value) {
  spec_->minimum = value;
  spec_->minimum_exclusive = true;
  return *this;
}
KeyBuilder& KeyBuilder::max(double value) {
  spec_->maximum = value;
  spec_->maximum_exclusive = false;
  return *this;
}
KeyBuilder& KeyBuilder::lessThan(double value) {
  spec_->maximum = value;
  spec_->maximum_exclusive = true;
  return *this;
}
KeyBuilder& KeyBuilder::choices(std::vector<std::string> allowed) {
  spec_->choices = std::move(allowed);
  return *this;
}

ConfigSchema::ConfigSchema(std::string command, std::string description)
    : command_(std::move(command)), description_(std::move(description)) {}

void ConfigSchema::section(std::string path, std::string description) {
  const std::string parent = parentOf(path);
  if (!parent.empty() && !findSection(parent)) {
    throw std::logic_error("schema: section " + path + " declared before its parent");
  }
  sections_.push_back({std::move(path), std::move(description)});
}

KeyBuilder ConfigSchema::add(const std::string& path, ValueKind kind) {
  const std::string parent = parentOf(path);
  if (!parent.empty() && !findSection(parent)) {
    throw std::logic_error("schema: key " + path + " in undeclared section " + parent);
  }
  if (findKey(path)) throw std::logic_error("schema: key " + path + " declared twice");
  KeySpec& spec = keys_.emplace_back();
  spec.path = path;
  spec.kind = kind;
  return KeyBuilder(spec);
}

KeyBuilder ConfigSchema::integer(const std::string& path) {
  return add(path, ValueKind::kInteger);
}
KeyBuilder ConfigSchema::real(const std::string& path) {
  return add(path, ValueKind::kReal);
}
KeyBuilder ConfigSchema::boolean(const std::string& path) {
  return add(path, ValueKind::kBoolean);
}
KeyBuilder ConfigSchema::string(const std::string& path) {
  return add(path, ValueKind::kString);
}
KeyBuilder ConfigSchema::realList(const std::string& path) {
  return add(path, ValueKind::kRealList);
}
KeyBuilder ConfigSchema::stringList(const std::string& path) {
  return add(path, ValueKind::kStringList);
}

void ConfigSchema::collection(const std::string& path, std::string description) {
  section(path, std::move(description));
  collections_.push_back(path);
}

bool ConfigSchema::isCollection(const std::string& path) const {
  return std::find(collections_.begin(), collections_.end(), path) != collections_.end();
}

std::string ConfigSchema::patternOf(const std::string& path) const {
  if (collections_.empty()) return path;
  std::string pattern, rest = path;
  while (!rest.empty()) {
    const auto dot = rest.find('.');
    const std::string part = rest.substr(0, dot);
    rest = dot == std::string::npos ? std::string() : rest.substr(dot + 1);
    pattern += (pattern.empty() ? "" : ".") + part;
    if (isCollection(pattern) && !rest.empty()) {
      const auto next = rest.find('.');
      pattern += ".*";
      rest = next == std::string::npos ? std::string() : rest.substr(next + 1);
    }
  }
  return pattern;
}

const KeySpec* ConfigSchema::findKey(const std::string& path) const {
  const std::string pattern = patternOf(path);
  for (const KeySpec& key : keys_) {
    if (key.path == pattern) return &key;
  }
  return nullptr;
}

const SectionSpec* ConfigSchema::findSection(const std::string& path) const {
  const std::string pattern = patternOf(path);
  for (const SectionSpec& section : sections_) {
    if (section.path == pattern) return &section;
  }
  return nullptr;
}

std::vector<std::string> ConfigSchema::keyNamesIn(const std::string& section) const {
  const std::string pattern = patternOf(section);
  std::vector<std::string> names;
  for (const KeySpec& key : keys_) {
    if (key.section() == pattern) names.push_back(key.path);
  }
  return names;
}

void ConfigSchema::alias(std::string old_path, std::string new_path) {
  if (!findKey(new_path)) throw std::logic_error("schema: alias to undeclared key " + new_path);
  if (findKey(old_path)) throw std::logic_error("schema: alias of a declared key " + old_path);
  aliases_.emplace_back(std::move(old_path), std::move(new_path));
}

const ValueConversion* renameConversion(std::string_view old_path, std::string_view new_path) {
  for (const ConvertedRename& r : kConvertedRenames)
    if (r.from == old_path && r.to == new_path) return &r.conversion;
  return nullptr;
}

const std::string* ConfigSchema::aliasTarget(const std::string& old_path) const {
  for (const auto& [from, to] : aliases_)
    if (from == old_path) return &to;
  return nullptr;
}

void ConfigSchema::addForeignSchema(ConfigSchema other) {
  other.foreign_.clear();  // one level: a foreign schema's own foreigners are not ours
  foreign_.push_back(std::move(other));
}

std::vector<const ConfigSchema*> ConfigSchema::foreignDeclaring(const std::string& path,
                                                                bool section) const {
  std::vector<const ConfigSchema*> found;
  for (const ConfigSchema& other : foreign_) {
    if (section ? other.findSection(path) != nullptr
                : other.findKey(path) != nullptr || other.aliasTarget(path) != nullptr)
      found.push_back(&other);
  }
  return found;
}

std::string ConfigSchema::referenceMarkdown() const {
  std::string out = fmt::format(
      "# {}\n\n{}\n\n", title_.empty() ? "`geardyn " + command_ + "` configuration" : title_,
      description_);
  out += "Generated by `geardyn schema " + (printed_by_.empty() ? command_ : printed_by_) +
         "` from the schema in the source; do not edit by hand.\n"
         "Units are SI unless the key's name says otherwise (`_deg`, `_rpm`). Unknown keys are "
         "errors.\n";
  const auto table_for = [&](const std::string& section, const std::string& title,
                             const std::string& description) {
    std::string rows;
    for (const KeySpec& key : keys_) {
      if (key.section() != section) continue;
      const std::string default_text = key.required                  ? "required"
                                       : key.default_value.is_null() ? "(not set)"
                                                                     : key.default_value.dump();
      rows += fmt::format("| `{}` | {} | {} | {} | {} | {} |\n", key.name(), kindName(key.kind),
                          key.unit.empty() ? "-" : key.unit, default_text, key.allowedText(),
                          key.description);
    }
    if (rows.empty()) return;
    std::string shown = title;
    for (auto star = shown.find(".*"); star != std::string::npos; star = shown.find(".*"))
      shown.replace(star, 2, ".<name>");
    out += fmt::format("\n## {}\n\n", shown);
    if (!description.empty()) out += description + "\n\n";
    out += "| key | type | unit | default | allowed | description |\n";
    out += "|---|---|---|---|---|---|\n" + rows;
  };
  table_for("", "Top level", "");
  for (const SectionSpec& section : sections_) {
    table_for(section.path, "[" + section.path + "]", section.description);
  }
  if (!aliases_.empty()) {
    out +=
        "\n## Renamed keys\n\nThe old spelling is still read, with a warning naming the new "
        "one.\n\n| old key | new key |\n|---|---|\n";
    for (const auto& [from, to] : aliases_) {
      const ValueConversion* c = renameConversion(from, to);
      out += c ? fmt::format("| `{}` | `{}` (value {}) |\n", from, to, c->text)
               : fmt::format("| `{}` | `{}` |\n", from, to);
    }
  }
  return out;
}

}  // namespace geardyn::config

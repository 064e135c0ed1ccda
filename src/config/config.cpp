#include "geardyn/config/config.h"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <set>
#include <sstream>

#include "geardyn/config/did_you_mean.h"
#include "geardyn/config/renamed_keys.h"
#include "geardyn/config/toml_parse.h"
#include "geardyn/error.h"

namespace geardyn::config {
namespace {

std::vector<std::string> splitPath(const std::string& path) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const auto dot = path.find('.', start);
    parts.push_back(path.substr(start, dot - start));
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  return parts;
}

std::string parentPath(const std::string& path) {
  const auto dot = path.rfind('.');
  return dot == std::string::npos ? std::string() : path.substr(0, dot);
}

std::string joinPath(const std::string& prefix, std::string_view key) {
  return prefix.empty() ? std::string(key) : prefix + "." + std::string(key);
}

/// How the user wrote a value, for messages.
std::string describeNode(const toml::node& node) {
  if (const auto* s = node.as_string()) return "\"" + s->get() + "\"";
  if (const auto* f = node.as_floating_point()) return fmt::format("{}", f->get());
  if (node.is_table()) return "(a table)";
  std::ostringstream out;
  node.visit([&](const auto& value) { out << value; });
  return out.str();
}

/// A converting rename's words for the warning (", value × 2: ..."), empty for a plain rename.
std::string conversionText(const ValueConversion* conversion) {
  return conversion ? ", value " + std::string(conversion->text) : std::string();
}

/// Multiplies the number, or every number of the array, at `table[key]` by `scale` (integers
/// become reals); other values are left for the type check to reject.
void scaleNumbers(toml::table& table, const std::string& key, double scale) {
  if (scale == 1.0) return;
  toml::node* node = table.get(key);
  if (!node) return;
  if (const auto* i = node->as_integer()) {
    table.insert_or_assign(key, static_cast<double>(i->get()) * scale);
  } else if (auto* f = node->as_floating_point()) {
    f->get() *= scale;
  } else if (auto* array = node->as_array()) {
    for (std::size_t k = 0; k < array->size(); ++k) {
      if (const auto* ik = array->get(k)->as_integer()) {
        array->replace(array->cbegin() + static_cast<std::ptrdiff_t>(k),
                       static_cast<double>(ik->get()) * scale);
      } else if (auto* fk = array->get(k)->as_floating_point()) {
        fk->get() *= scale;
      }
    }
  }
}

/// Resolves values against the schema and remembers where each came from.
class Resolver {
 public:
  Resolver(const ConfigSchema& schema, std::string source)
      : schema_(schema), source_(std::move(source)) {}

  void applyOverride(toml::table& root, const std::string& assignment);
  /// Moves deprecated spellings to their new keys (a note each).
  void applyAliases(toml::table& root);
  /// Rejects keys no schema declares; drops (with a note) those only other commands declare.
  void rejectUnknown(toml::table& table, const std::string& prefix);
  const std::vector<std::string>& notes() const noexcept { return notes_; }
  nlohmann::ordered_json resolve(const toml::table& root) const;

 private:
  std::string where(const std::string& path, const toml::node& node) const;
  [[noreturn]] void throwUnknownKey(const std::string& path, const std::string& location) const;
  nlohmann::ordered_json convert(const KeySpec& spec, const toml::node& node) const;
  void checkRange(const KeySpec& spec, double value, const toml::node& node,
                  const std::string& shown) const;
  void checkChoice(const KeySpec& spec, const std::string& value, const toml::node& node,
                   const std::string& shown) const;

  /// Keys of a section only other commands declare: spell-checked against them.
  void checkForeign(const toml::table& table, const std::string& prefix,
                    const std::vector<const ConfigSchema*>& owners) const;

  const ConfigSchema& schema_;
  std::string source_;
  std::set<std::string> overridden_;
  std::vector<std::string> notes_;
};

std::string Resolver::where(const std::string& path, const toml::node& node) const {
  if (overridden_.count(path)) return "--set";
  const auto line = node.source().begin.line;
  return line > 0 ? fmt::format("{} line {}", source_, line) : source_;
}

void Resolver::throwUnknownKey(const std::string& path, const std::string& location) const {
  const auto parts = splitPath(path);
  const std::string leaf = parts.back();
  const std::string section = parentPath(path);
  std::vector<std::string> leaves;
  const auto siblings = schema_.keyNamesIn(section);
  for (const auto& key : siblings) leaves.push_back(splitPath(key).back());
  for (const auto& sub : schema_.sections()) {
    if (parentPath(sub.path) == schema_.patternOf(section) && splitPath(sub.path).back() != "*")
      leaves.push_back(splitPath(sub.path).back());
  }
  std::string hint;
  if (auto match = closestMatch(leaf, leaves)) {
    hint = fmt::format("; did you mean \"{}\"?", joinPath(section, *match));
  } else {
    // The key may belong to another section ("module" written under [pair]).
    std::vector<std::string> elsewhere;
    for (const KeySpec& key : schema_.keys()) {
      if (key.name() == leaf ||
          editDistance(key.name(), leaf) <= std::max<int>(1, leaf.size() / 3)) {
        elsewhere.push_back(key.path);
      }
    }
    if (!elsewhere.empty()) {
      hint = "; did you mean";
      for (std::size_t i = 0; i < elsewhere.size() && i < 4; ++i) {
        hint += fmt::format("{} \"{}\"", i ? " or" : "", elsewhere[i]);
      }
      hint += "?";
    }
  }
  std::string known;
  for (const auto& name : leaves) known += (known.empty() ? "" : ", ") + name;
  const std::string scope = section.empty() ? "at the top level" : "in [" + section + "]";
  throw InputError(path, "",
                   fmt::format("unknown key ({}){}; the keys {} are: {}", location, hint, scope,
                               known.empty() ? "(none)" : known));
}

void Resolver::applyOverride(toml::table& root, const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0) {
    throw InputError("--set", assignment, "expected section.key=value");
  }
  auto trim = [](std::string s) {
    const auto first = s.find_first_not_of(" \t");
    const auto last = s.find_last_not_of(" \t");
    return first == std::string::npos ? std::string() : s.substr(first, last - first + 1);
  };
  std::string path = trim(assignment.substr(0, eq));
  const std::string text = trim(assignment.substr(eq + 1));
  const ValueConversion* conversion = nullptr;
  if (const std::string* renamed = schema_.aliasTarget(path)) {
    conversion = renameConversion(path, *renamed);
    notes_.push_back(fmt::format("{} is deprecated: it now reads {} (--set{})", path, *renamed,
                                 conversionText(conversion)));
    path = *renamed;
  }
  if (!schema_.findKey(path)) throwUnknownKey(path, "--set");

  // The value is TOML (20, 1e-3, true, "x", [1, 2]); a bare word is taken as a string.
  toml::table parsed;
  try {
    const std::string document = "v = " + text;
    parsed = parseToml(document, "--set");
  } catch (const toml::parse_error&) {
    parsed = toml::table{};
    parsed.insert("v", text);
  }
  toml::table* table = &root;
  const auto parts = splitPath(path);
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    toml::node* child = table->get(parts[i]);
    if (!child) {
      table->insert(parts[i], toml::table{});
      child = table->get(parts[i]);
    }
    table = child->as_table();
    if (!table) {
      throw InputError(path, text, "cannot override: " + parts[i] + " is not a table in the file");
    }
  }
  if (conversion) scaleNumbers(parsed, "v", conversion->scale);
  parsed.get("v")->visit([&](auto&& value) { table->insert_or_assign(parts.back(), value); });
  overridden_.insert(path);
}

void Resolver::applyAliases(toml::table& root) {
  for (const auto& [from, to] : schema_.aliases()) {
    const ValueConversion* conversion = renameConversion(from, to);
    const toml::node* node = root.at_path(from).node();
    if (!node) continue;
    if (root.at_path(to).node()) {
      throw InputError(from, describeNode(*node),
                       fmt::format("is the deprecated spelling of {}, which is given too ({}): "
                                   "keep only {}",
                                   to, where(from, *node), to));
    }
    notes_.push_back(fmt::format("{} is deprecated: write {} ({}; read as {}{})", from, to,
                                 where(from, *node), to, conversionText(conversion)));
    const auto from_parts = splitPath(from), to_parts = splitPath(to);
    toml::table* target = &root;
    for (std::size_t i = 0; i + 1 < to_parts.size(); ++i) {
      if (!target->get(to_parts[i])) target->insert(to_parts[i], toml::table{});
      target = target->get(to_parts[i])->as_table();
      if (!target) throw InputError(to, "", to_parts[i] + " is not a table in the file");
    }
    toml::table* source = &root;
    for (std::size_t i = 0; i + 1 < from_parts.size(); ++i)
      source = source->get(from_parts[i])->as_table();
    source->get(from_parts.back())->visit([&](auto&& value) {
      target->insert_or_assign(to_parts.back(), value);
    });
    if (conversion) scaleNumbers(*target, to_parts.back(), conversion->scale);
    source->erase(from_parts.back());
  }
}

void Resolver::checkForeign(const toml::table& table, const std::string& prefix,
                            const std::vector<const ConfigSchema*>& owners) const {
  for (const auto& [key, node] : table) {
    const std::string path = joinPath(prefix, key.str());
    bool known = false;
    for (const ConfigSchema* owner : owners) {
      known = known || owner->findKey(path) || owner->aliasTarget(path) ||
              (node.is_table() && owner->findSection(path));
    }
    if (known && node.is_table()) {
      checkForeign(*node.as_table(), path, owners);
      continue;
    }
    if (known) continue;
    // The did-you-mean of the command owning the section.
    std::vector<std::string> names;
    for (const ConfigSchema* owner : owners)
      for (const auto& name : owner->keyNamesIn(prefix)) names.push_back(name);
    std::string hint;
    if (auto match = closestMatch(path, names))
      hint = fmt::format("; did you mean \"{}\"?", *match);
    throw InputError(
        path, "",
        fmt::format("unknown key ({}){}; [{}] belongs to `geardyn {}`, whose keys "
                    "there are checked even though `geardyn {}` ignores them",
                    where(path, node), hint, prefix, owners.front()->command(), schema_.command()));
  }
}

void Resolver::rejectUnknown(toml::table& table, const std::string& prefix) {
  std::vector<std::string> ignored;
  for (auto&& [key, node] : table) {
    const std::string path = joinPath(prefix, key.str());
    if (schema_.findKey(path)) continue;
    if (schema_.findSection(path)) {
      if (auto* sub = node.as_table()) {
        rejectUnknown(*sub, path);
        continue;
      }
      throw InputError(path, describeNode(node),
                       fmt::format("[{}] is a section (a TOML table), not a value ({})", path,
                                   where(path, node)));
    }
    // Another command's section or key: ignored here, with a note, but spell-checked.
    const auto owners = schema_.foreignDeclaring(path, node.is_table());
    if (!owners.empty() && !overridden_.count(path)) {
      if (node.is_table()) checkForeign(*node.as_table(), path, owners);
      std::vector<std::string> commands;
      for (const ConfigSchema* owner : owners) commands.push_back(owner->command());
      notes_.push_back(fmt::format("{} is for `geardyn {}`; `geardyn {}` ignores it ({})",
                                   node.is_table() ? "[" + path + "]" : path,
                                   fmt::format("{}", fmt::join(commands, "`, `geardyn ")),
                                   schema_.command(), where(path, node)));
      ignored.push_back(std::string(key.str()));
      continue;
    }
    if (node.is_table()) {
      std::vector<std::string> names;
      for (const auto& s : schema_.sections()) names.push_back(s.path);
      std::string hint;
      if (auto match = closestMatch(path, names))
        hint = fmt::format("; did you mean [{}]?", *match);
      std::string known;
      for (const auto& s : names) known += (known.empty() ? "[" : ", [") + s + "]";
      throw InputError("[" + path + "]", "",
                       fmt::format("unknown section ({}){}; the sections are: {}",
                                   where(path, node), hint, known));
    }
    throwUnknownKey(path, where(path, node));
  }
  for (const auto& key : ignored) table.erase(key);
}

void Resolver::checkRange(const KeySpec& spec, double value, const toml::node& node,
                          const std::string& shown) const {
  const bool below =
      spec.minimum && (spec.minimum_exclusive ? value <= *spec.minimum : value < *spec.minimum);
  const bool above =
      spec.maximum && (spec.maximum_exclusive ? value >= *spec.maximum : value > *spec.maximum);
  if (below || above) {
    throw InputError(spec.path, shown,
                     fmt::format("must be {} ({}; {})", spec.allowedText(), spec.description,
                                 where(spec.path, node)));
  }
}

void Resolver::checkChoice(const KeySpec& spec, const std::string& value, const toml::node& node,
                           const std::string& shown) const {
  if (spec.choices.empty() ||
      std::find(spec.choices.begin(), spec.choices.end(), value) != spec.choices.end()) {
    return;
  }
  std::string hint;
  if (auto match = closestMatch(value, spec.choices)) {
    hint = fmt::format("; did you mean \"{}\"?", *match);
  }
  throw InputError(spec.path, shown,
                   fmt::format("must be {} ({}; {}){}", spec.allowedText(), spec.description,
                               where(spec.path, node), hint));
}

nlohmann::ordered_json Resolver::convert(const KeySpec& spec, const toml::node& node) const {
  const std::string shown = describeNode(node);
  const auto wrong_type = [&]() {
    return InputError(spec.path, shown,
                      fmt::format("expected {} ({}; {})", spec.allowedText(), spec.description,
                                  where(spec.path, node)));
  };
  const auto real_of = [&](const toml::node& n, const std::string& text) {
    double value = 0.0;
    if (const auto* i = n.as_integer()) {
      value = static_cast<double>(i->get());
    } else if (const auto* f = n.as_floating_point()) {
      value = f->get();
    } else {
      throw wrong_type();
    }
    if (!std::isfinite(value)) {
      throw InputError(spec.path, text,
                       fmt::format("must be finite: nan and inf are not allowed ({}; {})",
                                   spec.description, where(spec.path, node)));
    }
    checkRange(spec, value, node, text);
    return value;
  };

  switch (spec.kind) {
    case ValueKind::kInteger: {
      long long value = 0;
      if (const auto* i = node.as_integer()) {
        value = i->get();
      } else if (const auto* f = node.as_floating_point(); f && std::isfinite(f->get()) &&
                                                           std::floor(f->get()) == f->get() &&
                                                           std::abs(f->get()) < 9.0e15) {
        value = static_cast<long long>(f->get());  // 25.0 is the integer 25
      } else {
        throw wrong_type();
      }
      checkRange(spec, static_cast<double>(value), node, shown);
      return value;
    }
    case ValueKind::kReal:
      return real_of(node, shown);
    case ValueKind::kBoolean:
      if (const auto* b = node.as_boolean()) return b->get();
      throw wrong_type();
    case ValueKind::kString: {
      const auto* s = node.as_string();
      if (!s) throw wrong_type();
      checkChoice(spec, s->get(), node, shown);
      return s->get();
    }
    case ValueKind::kStringList: {
      const auto* array = node.as_array();
      if (!array) throw wrong_type();
      nlohmann::ordered_json list = nlohmann::ordered_json::array();
      for (const toml::node& element : *array) {
        const auto* s = element.as_string();
        if (!s) throw wrong_type();
        checkChoice(spec, s->get(), node, "\"" + s->get() + "\"");
        list.push_back(s->get());
      }
      return list;
    }
    case ValueKind::kRealList: {
      const auto* array = node.as_array();
      if (!array) throw wrong_type();
      nlohmann::ordered_json list = nlohmann::ordered_json::array();
      for (const toml::node& element : *array) list.push_back(real_of(element, shown));
      return list;
    }
  }
  throw std::logic_error("unhandled value kind");
}

nlohmann::ordered_json Resolver::resolve(const toml::table& root) const {
  // Keys in schema order (sections appear where their first key is declared); sections with no
  // keys of their own still appear, as empty objects.
  nlohmann::ordered_json resolved = nlohmann::ordered_json::object();
  const auto in_collection = [](const std::string& path) {
    return path.find(".*") != std::string::npos;
  };
  // One key at a concrete path (`path` replaces the spec's pattern inside collections).
  const auto resolve_key = [&](const KeySpec& spec, const std::string& path) {
    nlohmann::ordered_json value;
    const toml::node* node = root.at_path(path).node();
    if (node) {
      if (path == spec.path) {
        value = convert(spec, *node);
      } else {  // an item of a collection: messages name its concrete path
        KeySpec concrete = spec;
        concrete.path = path;
        value = convert(concrete, *node);
      }
    } else if (spec.required) {
      const std::string section = parentPath(path);
      throw InputError(
          path, "",
          fmt::format("missing required key: {} ({}){}", spec.description, spec.allowedText(),
                      section.empty()
                          ? ""
                          : fmt::format("; add `{} = ...` under [{}]", spec.name(), section)));
    } else {
      value = spec.default_value;
    }
    nlohmann::ordered_json* target = &resolved;
    for (const auto& part : splitPath(path)) target = &(*target)[part];
    *target = std::move(value);
  };
  for (const KeySpec& spec : schema_.keys()) {
    if (!in_collection(spec.path)) resolve_key(spec, spec.path);
  }
  for (const SectionSpec& section : schema_.sections()) {
    if (in_collection(section.path)) continue;
    nlohmann::ordered_json* target = &resolved;
    for (const auto& part : splitPath(section.path)) target = &(*target)[part];
    if (target->is_null()) *target = nlohmann::ordered_json::object();
  }
  // Named tables of each collection, in the order of the file.
  for (const std::string& collection : schema_.collections()) {
    std::vector<std::pair<std::string, std::uint32_t>> instances;
    if (const toml::table* table = root.at_path(collection).as_table()) {
      for (const auto& [name, node] : *table) {
        instances.emplace_back(std::string(name.str()), node.source().begin.line);
      }
    }
    std::stable_sort(instances.begin(), instances.end(),
                     [](const auto& a, const auto& b) { return a.second < b.second; });
    const std::string prefix = collection + ".*";
    for (const auto& [name, line] : instances) {
      const std::string concrete = collection + "." + name;
      for (const SectionSpec& section : schema_.sections()) {
        if (section.path.rfind(prefix, 0) != 0) continue;
        nlohmann::ordered_json* target = &resolved;
        for (const auto& part : splitPath(concrete + section.path.substr(prefix.size())))
          target = &(*target)[part];
        if (target->is_null()) *target = nlohmann::ordered_json::object();
      }
      for (const KeySpec& spec : schema_.keys()) {
        if (spec.path.rfind(prefix + ".", 0) == 0) {
          resolve_key(spec, concrete + spec.path.substr(prefix.size()));
        }
      }
    }
  }
  return resolved;
}

}  // namespace

Config::Config(nlohmann::ordered_json resolved, std::string source)
    : resolved_(std::move(resolved)), source_(std::move(source)) {}

const nlohmann::ordered_json& Config::at(const std::string& path) const {
  const nlohmann::ordered_json* node = &resolved_;
  for (const auto& part : splitPath(path)) {
    if (!node->is_object() || !node->contains(part)) {
      throw std::logic_error("Config: no key " + path + " in the schema");
    }
    node = &(*node)[part];
  }
  return *node;
}

bool Config::has(const std::string& path) const {
  return !at(path).is_null();
}
double Config::real(const std::string& path) const {
  return at(path).get<double>();
}
long long Config::integer(const std::string& path) const {
  return at(path).get<long long>();
}
bool Config::boolean(const std::string& path) const {
  return at(path).get<bool>();
}
std::string Config::string(const std::string& path) const {
  return at(path).get<std::string>();
}
std::vector<double> Config::realList(const std::string& path) const {
  return at(path).get<std::vector<double>>();
}
std::vector<std::string> Config::stringList(const std::string& path) const {
  return at(path).get<std::vector<std::string>>();
}
std::vector<std::string> Config::names(const std::string& collection) const {
  std::vector<std::string> out;
  for (const auto& [name, value] : at(collection).items()) out.push_back(name);
  return out;
}

std::optional<double> Config::optionalReal(const std::string& path) const {
  const auto& value = at(path);
  if (value.is_null()) return std::nullopt;
  return value.get<double>();
}

Config parseConfig(std::string_view toml_text, const std::string& source_name,
                   const ConfigSchema& schema, const std::vector<std::string>& overrides) {
  toml::table root;
  try {
    root = parseToml(toml_text, source_name);
  } catch (const toml::parse_error& error) {
    throw InputError(
        "", "",
        fmt::format("{} line {}, column {}: not valid TOML: {}", source_name,
                    error.source().begin.line, error.source().begin.column, error.description()));
  }
  Resolver resolver(schema, source_name);
  resolver.applyAliases(root);
  for (const auto& assignment : overrides) resolver.applyOverride(root, assignment);
  resolver.rejectUnknown(root, "");
  Config config(resolver.resolve(root), source_name);
  for (const auto& note : resolver.notes()) config.addNote(note);
  return config;
}

void checkOverrideKeys(const ConfigSchema& schema, const std::vector<std::string>& overrides) {
  Resolver resolver(schema, "--set");
  toml::table scratch;
  for (const auto& assignment : overrides) resolver.applyOverride(scratch, assignment);
}

std::string readConfigFile(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) {
    throw InputError(
        "config", file.string(),
        std::filesystem::exists(file, ec) ? "is not a regular file" : "no such configuration file");
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError("config", file.string(), "cannot be opened for reading");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

Config loadConfigFile(const std::filesystem::path& file, const ConfigSchema& schema,
                      const std::vector<std::string>& overrides) {
  return parseConfig(readConfigFile(file), file.string(), schema, overrides);
}

}  // namespace geardyn::config

#pragma once
/// \file
/// The schema of one command's TOML configuration: every key with its type, SI unit, default,
/// allowed range or choices and a description. The loader (config.h) validates against it, the
/// CLI prints it (`geardyn schema COMMAND`), and docs/config/*.md is generated from it.

#include <deque>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace geardyn::config {

/// The TOML type a key takes.
enum class ValueKind { kInteger, kReal, kBoolean, kString, kRealList, kStringList };

/// One configuration key. `path` is dotted: "section.key" or "section.sub.key".
struct KeySpec {
  std::string path;
  ValueKind kind = ValueKind::kReal;
  std::string unit;         ///< SI unit ("m", "Pa", "kg/m^3") or the unit in the key's name ("deg")
  std::string description;  ///< one line, for messages and the reference
  nlohmann::ordered_json default_value;  ///< null when the key has no default
  bool required = false;  ///< absent and no default: an error when true, null when false
  std::optional<double> minimum;
  bool minimum_exclusive = false;
  std::optional<double> maximum;
  bool maximum_exclusive = false;
  std::vector<std::string> choices;  ///< allowed strings (kString, kStringList), empty: any

  /// What is allowed, in words: "an integer >= 3", "a number in (0, 45)", "one of "a", "b"".
  std::string allowedText() const;
  /// The section part of the path ("pinion" for "pinion.teeth"; "" for a top-level key).
  std::string section() const;
  /// The last component of the path ("teeth").
  std::string name() const;
};

/// Fluent setter for the KeySpec just added to a schema.
class KeyBuilder {
 public:
  explicit KeyBuilder(KeySpec& spec) : spec_(&spec) {}
  KeyBuilder& unit(std::string unit);
  KeyBuilder& doc(std::string description);
  KeyBuilder& required();
  KeyBuilder& optional();  ///< no default; absent means "not given" (null in the resolved config)
  KeyBuilder& defaultValue(nlohmann::ordered_json value);
  KeyBuilder& min(double value);          ///< value >= min
  KeyBuilder& greaterThan(double value);  ///< value > bound
  KeyBuilder& max(double value);          ///< value <= max
  KeyBuilder& lessThan(double value);     ///< value < bound
  KeyBuilder& positive() { return greaterThan(0.0); }
  KeyBuilder& choices(std::vector<std::string> allowed);

 private:
  KeySpec* spec_;
};

/// A section (TOML table) of the schema.
struct SectionSpec {
  std::string path;
  std::string description;
};

/// The configuration schema of one command.
class ConfigSchema {
 public:
  ConfigSchema(std::string command, std::string description);

  /// Declares a section; keys may only be added to declared sections (or the top level).
  void section(std::string path, std::string description);
  /// Declares a collection of named tables, `[path.<name>]` (e.g. `[shafts.input]`): declare
  /// the item next as the section "path.*", and its keys and sub-sections under it (e.g.
  /// "shafts.*.mass"); they apply to every instance, kept in the order of the file.
  void collection(const std::string& path, std::string description);
  /// Whether `path` is a declared collection.
  bool isCollection(const std::string& path) const;
  const std::vector<std::string>& collections() const noexcept { return collections_; }
  /// The declared pattern of a concrete path: "shafts.input.mass" → "shafts.*.mass" (the path
  /// itself when no collection is involved).
  std::string patternOf(const std::string& path) const;

  KeyBuilder integer(const std::string& path);
  KeyBuilder real(const std::string& path);
  KeyBuilder boolean(const std::string& path);
  KeyBuilder string(const std::string& path);
  KeyBuilder realList(const std::string& path);
  KeyBuilder stringList(const std::string& path);  ///< choices apply to every element

  const std::string& command() const noexcept { return command_; }
  /// The reference's heading (default: "`geardyn <command>` configuration"), for schemas of
  /// files that no command runs directly (a gearbox description).
  void setTitle(std::string title) { title_ = std::move(title); }
  /// The command whose `geardyn schema COMMAND` prints this reference (default: command()).
  void setPrintedBy(std::string command) { printed_by_ = std::move(command); }
  const std::string& description() const noexcept { return description_; }
  const std::deque<KeySpec>& keys() const noexcept { return keys_; }
  const std::vector<SectionSpec>& sections() const noexcept { return sections_; }
  /// The key or section at a path (concrete collection paths are matched to their pattern).
  const KeySpec* findKey(const std::string& path) const;
  const SectionSpec* findSection(const std::string& path) const;
  /// Full paths of the keys in a section (for suggestions).
  std::vector<std::string> keyNamesIn(const std::string& section) const;

  /// The configuration reference of this command as Markdown (one table per section).
  std::string referenceMarkdown() const;

  /// A deprecated spelling: a file (or --set) giving `old_path` is read as `new_path`, with a
  /// note naming the new key; giving both is an error. docs/config/renamed-keys.md lists them.
  void alias(std::string old_path, std::string new_path);
  const std::vector<std::pair<std::string, std::string>>& aliases() const noexcept {
    return aliases_;
  }
  /// The new spelling of a deprecated key, or nullptr.
  const std::string* aliasTarget(const std::string& old_path) const;

  /// Another command's schema: keys and sections it declares that this one does not are
  /// ignored with a note (so one file can drive several commands), but still spell-checked
  /// against it. Keys that no schema declares stay errors.
  void addForeignSchema(ConfigSchema other);
  /// The foreign schemas declaring `path` as a key (or a section when `section`).
  std::vector<const ConfigSchema*> foreignDeclaring(const std::string& path, bool section) const;

 private:
  KeyBuilder add(const std::string& path, ValueKind kind);

  std::string command_;
  std::string description_;
  std::string title_;
  std::string printed_by_;
  std::vector<SectionSpec> sections_;
  std::vector<std::string> collections_;
  std::deque<KeySpec> keys_;  // declaration order; a deque keeps KeyBuilder pointers valid
  std::vector<std::pair<std::string, std::string>> aliases_;  // (old, new)
  std::vector<ConfigSchema> foreign_;
};

}  // namespace geardyn::config

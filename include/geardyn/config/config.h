#pragma once
/// \file
/// Loading a TOML configuration against a ConfigSchema: parse (toml++), apply `--set`
/// overrides, reject unknown keys with a did-you-mean suggestion, check every value's type,
/// finiteness and range, fill defaults. The result is the fully resolved configuration that
/// every result file records.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "geardyn/config/config_schema.h"

namespace geardyn::config {

/// A validated configuration with every default filled in. Accessors take dotted paths of keys
/// declared in the schema; asking for an undeclared key or the wrong type is a programming
/// error (std::logic_error).
class Config {
 public:
  Config(nlohmann::ordered_json resolved, std::string source);

  /// Nested JSON object: sections as objects, keys in schema order, null for unset optionals.
  const nlohmann::ordered_json& resolved() const noexcept { return resolved_; }
  /// Where the configuration came from (file path or a name given to parseConfig).
  const std::string& source() const noexcept { return source_; }
  /// Notes for the user made while loading: deprecated spellings read under their new name,
  /// sections and keys of other commands that this one ignores.
  const std::vector<std::string>& notes() const noexcept { return notes_; }
  void addNote(std::string note) { notes_.push_back(std::move(note)); }

  bool has(const std::string& path) const;  ///< declared and not null
  double real(const std::string& path) const;
  long long integer(const std::string& path) const;
  bool boolean(const std::string& path) const;
  std::string string(const std::string& path) const;
  std::vector<double> realList(const std::string& path) const;
  std::vector<std::string> stringList(const std::string& path) const;
  std::optional<double> optionalReal(const std::string& path) const;
  /// The instance names of a collection (ConfigSchema::collection), in the file's order.
  std::vector<std::string> names(const std::string& collection) const;

 private:
  const nlohmann::ordered_json& at(const std::string& path) const;

  nlohmann::ordered_json resolved_;
  std::string source_;
  std::vector<std::string> notes_;
};

/// Parses TOML text and validates it against `schema`. `overrides` are "section.key=value"
/// strings (the CLI's --set), the value in TOML syntax (a bare word is taken as a string).
/// Throws InputError naming the key, the value and what is allowed (with the line number for
/// values from the text, and for TOML syntax errors).
Config parseConfig(std::string_view toml_text, const std::string& source_name,
                   const ConfigSchema& schema, const std::vector<std::string>& overrides = {});

/// Throws the InputError parseConfig would for the first override whose key `schema` does not
/// declare ("unknown key (--set)" with a did-you-mean); the values are not checked. For a
/// command whose overrides go to several files (`train`: the analysis file and its gearbox), so
/// that a misspelt key is named against every key it may take.
void checkOverrideKeys(const ConfigSchema& schema, const std::vector<std::string>& overrides);

/// The text of a configuration file. A missing or unreadable file is an InputError (key
/// `config`).
std::string readConfigFile(const std::filesystem::path& file);

/// As parseConfig, reading the file first. A missing or unreadable file is an InputError.
Config loadConfigFile(const std::filesystem::path& file, const ConfigSchema& schema,
                      const std::vector<std::string>& overrides = {});

}  // namespace geardyn::config

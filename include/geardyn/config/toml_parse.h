#pragma once
/// The one way geardyn parses TOML text: toml::parse after a check of where non-ASCII
/// characters stand.
///
/// TOML 1.0 allows characters outside ASCII only in strings and comments (bare keys are
/// A-Z a-z 0-9 _ -, whitespace is tab and space). Debian's toml++ 3.3.0 meets some of the others
/// (U+00A1..U+0499, e.g. '±', 'β', 'μ', and U+2BEE..U+2FE7) in
/// `impl::is_non_ascii_horizontal_whitespace`, whose switch ends in TOML_UNREACHABLE
/// (`__builtin_unreachable`): undefined behaviour on a third party's file, found by the gearbox
/// fuzzer (tests/fuzz). parseToml refuses such a character first, with its line and column, as
/// the toml::parse_error the callers already report.

#include <toml++/toml.h>

#include <filesystem>
#include <string_view>

namespace geardyn::config {

/// toml::parse(text, source) after checkTomlCharacters; throws toml::parse_error.
toml::table parseToml(std::string_view text, std::string_view source);

/// parseToml of a file's content (toml::parse_error naming the file when it cannot be read).
toml::table parseTomlFile(const std::filesystem::path& file);

/// Throws toml::parse_error at the first character outside ASCII that stands outside a string and
/// a comment (a UTF-8 byte-order mark at the start is allowed, as toml++ skips it).
void checkTomlCharacters(std::string_view text, std::string_view source);

}  // namespace geardyn::config

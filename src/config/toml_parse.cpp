#include "geardyn/config/toml_parse.h"

#include <fmt/format.h>

#include <fstream>
#include <memory>
#include <sstream>
#include <string>

namespace geardyn::config {
namespace {

/// The code point of the UTF-8 sequence at text[i] (the byte itself when the sequence is cut).
char32_t codePointAt(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(i);
  const int extra = lead >= 0xF0 ? 3 : lead >= 0xE0 ? 2 : lead >= 0xC0 ? 1 : 0;
  if (extra == 0 || i + extra >= text.size()) return lead;
  char32_t c = lead & (0x3F >> extra);
  for (int k = 1; k <= extra; ++k) c = (c << 6) | (byte(i + k) & 0x3F);
  return c;
}

[[noreturn]] void refuse(std::string_view text, std::size_t at, toml::source_position position,
                         std::string_view source) {
  const char32_t c = codePointAt(text, at);
  std::size_t end = at + 1;
  while (end < text.size() && (static_cast<unsigned char>(text[end]) & 0xC0) == 0x80) ++end;
  const std::string description = fmt::format(
      "'{}' (U+{:04X}) stands outside a string and a comment; TOML allows characters "
      "outside ASCII only there (a key with them is quoted: \"{}\" = ...)",
      std::string(text.substr(at, end - at)), static_cast<unsigned>(c),
      std::string(text.substr(at, end - at)));
  throw toml::parse_error(description.c_str(), position,
                          std::make_shared<const std::string>(source));
}

}  // namespace

void checkTomlCharacters(std::string_view text, std::string_view source) {
  enum class State { Code, Comment, Basic, Literal, MultiBasic, MultiLiteral };
  State state = State::Code;
  toml::source_position position{1, 1};
  std::size_t i = text.rfind("\xEF\xBB\xBF", 0) == 0 ? 3 : 0;
  const auto starts = [&](std::string_view token) {
    return text.compare(i, token.size(), token) == 0;
  };
  // Consumes a closing delimiter of a multi-line string and the up to two quotes TOML lets stand
  // right before it (""""" closes with two quotes of content).
  const auto closeMulti = [&](char quote) {
    i += 3;
    for (int k = 0; k < 2 && i < text.size() && text[i] == quote; ++k) ++i;
    position.column += 3;
    state = State::Code;
  };
  while (i < text.size()) {
    const char c = text[i];
    const bool ascii = (static_cast<unsigned char>(c) & 0x80) == 0;
    if (c == '\n') {
      ++position.line;
      position.column = 1;
      if (state == State::Comment || state == State::Basic || state == State::Literal)
        state = State::Code;  // an unterminated one-line string: toml++ reports it
      ++i;
      continue;
    }
    switch (state) {
      case State::Code:
        if (!ascii) refuse(text, i, position, source);
        if (c == '#')
          state = State::Comment;
        else if (starts("\"\"\"")) {
          i += 3;
          position.column += 3;
          state = State::MultiBasic;
          continue;
        } else if (starts("'''")) {
          i += 3;
          position.column += 3;
          state = State::MultiLiteral;
          continue;
        } else if (c == '"')
          state = State::Basic;
        else if (c == '\'')
          state = State::Literal;
        break;
      case State::Basic:
      case State::MultiBasic:
        if (c == '\\' && i + 1 < text.size() && text[i + 1] != '\n') {
          i += 2;  // an escape: the next character is not a delimiter
          position.column += 2;
          continue;
        }
        if (state == State::MultiBasic && starts("\"\"\"")) {
          closeMulti('"');
          continue;
        }
        if (state == State::Basic && c == '"') state = State::Code;
        break;
      case State::MultiLiteral:
        if (starts("'''")) {
          closeMulti('\'');
          continue;
        }
        break;
      case State::Literal:
        if (c == '\'') state = State::Code;
        break;
      case State::Comment:
        break;
    }
    ++i;
    if ((static_cast<unsigned char>(c) & 0xC0) != 0x80)
      ++position.column;  // columns count characters
  }
}

toml::table parseToml(std::string_view text, std::string_view source) {
  checkTomlCharacters(text, source);
  return toml::parse(text, source);
}

toml::table parseTomlFile(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in)
    throw toml::parse_error(fmt::format("cannot read {}", file.string()).c_str(),
                            toml::source_position{1, 1},
                            std::make_shared<const std::string>(file.string()));
  std::ostringstream text;
  text << in.rdbuf();
  return parseToml(text.str(), file.string());
}

}  // namespace geardyn::config

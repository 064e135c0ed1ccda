// config::parseToml: characters outside ASCII are refused where TOML forbids them (before Debian's
// toml++ 3.3.0 reaches TOML_UNREACHABLE on them) and accepted in strings and comments, where the
// result must equal toml::parse's.
#include "geardyn/config/toml_parse.h"

#include <gtest/gtest.h>

#include <string>

namespace geardyn::config {
namespace {

toml::parse_error refusal(const std::string& text) {
  try {
    parseToml(text, "test.toml");
  } catch (const toml::parse_error& error) {
    return error;
  }
  ADD_FAILURE() << "accepted: " << text;
  return toml::parse_error("accepted", toml::source_position{0, 0});
}

TEST(TomlParse, RefusesNonAsciiOutsideStringsAndCommentsWithItsPlace) {
  // The fuzzer's reproducer: '±' as a bare key on line 2.
  const auto error = refusal("x = 1\n\xC2\xB1 = 2\n");
  EXPECT_EQ(error.source().begin.line, 2u);
  EXPECT_EQ(error.source().begin.column, 1u);
  EXPECT_NE(std::string(error.description()).find("U+00B1"), std::string::npos)
      << error.description();
  EXPECT_EQ(*error.source().path, "test.toml");
  // A Greek key after ASCII on its line: the column counts characters, not bytes.
  const auto greek = refusal("# \xCE\xB2 in a comment\nangle_\xCE\xB2 = 20\n");
  EXPECT_EQ(greek.source().begin.line, 2u);
  EXPECT_EQ(greek.source().begin.column, 7u);
  // After a closed string on the same line, and after a multi-line string.
  EXPECT_EQ(refusal("a = \"\xCE\xBC\" \xCE\xBC\n").source().begin.column, 9u);
  EXPECT_EQ(refusal("a = \"\"\"x\n\"\"\"\xE2\x80\x83= 1\n").source().begin.line, 2u);
  // A one-line string left open ends at the line's end: the next line is code again.
  EXPECT_EQ(refusal("a = 'open\n\xCE\xB2 = 1\n").source().begin.line, 2u);
}

TEST(TomlParse, AcceptsNonAsciiInStringsAndCommentsAsTomlParseDoes) {
  const std::string documents[] = {
      "# \xC2\xB1 0.5 % (a comment)\nx = 1 # \xCE\xB2\n",
      "title = \"z 19/71 \xC2\xB1 \xCE\xBC\"\n",
      "title = 'literal \xCE\xB2'\n",
      "title = \"escaped \\\" quote \xCE\xB2\"\nnext = 2\n",
      "text = \"\"\"\nline \xCE\xB2 \"quoted\" \\\"\"\"\nstill \xCE\xB8\"\"\"\"\"\n",
      "text = '''\n\xCE\xB2 ''\n'''''\nk = 3\n",
      "\xEF\xBB\xBFx = 1\n",  // a UTF-8 byte-order mark
      "[\"\xCE\xB2 quoted key\"]\nv = 1\n",
  };
  for (const std::string& text : documents) {
    toml::table ours, theirs;
    ASSERT_NO_THROW(ours = parseToml(text, "doc")) << text;
    theirs = toml::parse(std::string_view(text), std::string_view("doc"));
    EXPECT_EQ(ours, theirs) << text;
  }
}

TEST(TomlParse, SyntaxErrorsAreStillToml) {
  // Without characters outside ASCII the check passes and toml++ reports the error itself.
  EXPECT_THROW(parseToml("x = = 1\n", "doc"), toml::parse_error);
  EXPECT_THROW(parseTomlFile("/nonexistent/geardyn.toml"), toml::parse_error);
}

}  // namespace
}  // namespace geardyn::config

// The one TOML/JSON string quoter (core/quote.hpp).  Closed-form answers:
//  - string_literal("a\"b\\c") is the 9 bytes  "a\"b\\c"  (quotes and backslash escaped);
//  - quoted of "\n", "\t", "\x01", "\x7f" is "\u000a", "\u0009", "\u0001", "\u007f";
//  - bytes >= 0x80 pass unchanged: string_literal("µ") is "\"µ\"";
//  - toml++ reads `k = <string_literal(s)>` back as exactly s for every s tried,
//    including all 128 ASCII bytes in one string.
#define BOOST_TEST_MODULE quote
#include <boost/test/unit_test.hpp>

#include <string>

#include "core/quote.hpp"
#include <toml++/toml.h>

using drawbend::string_literal;

BOOST_AUTO_TEST_CASE(escapes_quotes_backslashes_and_controls) {
  BOOST_TEST(string_literal("a\"b\\c") == "\"a\\\"b\\\\c\"");
  BOOST_TEST(string_literal("\n") == "\"\\u000a\"");
  BOOST_TEST(string_literal("\t") == "\"\\u0009\"");
  BOOST_TEST(string_literal(std::string(1, '\x01')) == "\"\\u0001\"");
  BOOST_TEST(string_literal(std::string(1, '\x7f')) == "\"\\u007f\"");
  BOOST_TEST(string_literal("\xC2\xB5") == "\"\xC2\xB5\"");
  BOOST_TEST(string_literal("") == "\"\"");
}

BOOST_AUTO_TEST_CASE(toml_reads_back_what_was_quoted) {
  std::string all;
  for (int c = 1; c < 128; ++c) all += static_cast<char>(c);
  for (const std::string& s : {std::string("plain"), std::string("C:\\data\\a \"b\".csv"), std::string("two\nlines"),
                              std::string("\xC2\xB5m"), all}) {
    const toml::table t = toml::parse("k = " + string_literal(s) + "\n");
    BOOST_TEST(t["k"].value<std::string>().value_or("<none>") == s);
  }
}

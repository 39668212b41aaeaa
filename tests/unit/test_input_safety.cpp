// Input safety: problems collected in one pass, CSV validation, provenance.
// Closed-form answers:
//  - parse_csv on a file with two ragged rows (lines 4 and 6) and a duplicate
//    column name throws one InputError naming all three problems, each with
//    file:line.
//  - parse_deck on a deck with a wrong type (dt_safety = "x"), a negative
//    thickness-like value (mesh n = -2), mu < 0 and an unknown key reports
//    "4 problems" with each line number and key.
//  - A deck whose [numerics] is not a table, or whose mesh breaks are not an
//    array, gives a located error instead of a crash (found by fuzzing).
//  - A table header with no name after '[' ("[\nx]", "[[[1]]]") is a located
//    TOML syntax error, not a toml++ assertion (found by fuzzing).
//  - stale_inputs is empty right after write_provenance, and names the file
//    once its contents change (FNV-1a 64 of "a" = af63dc4c8601ec8c).
#define BOOST_TEST_MODULE input_safety
#include <boost/test/unit_test.hpp>
#include <filesystem>

#include "core/csv.hpp"
#include "core/hash.hpp"
#include "core/provenance.hpp"
#include "io/deck.hpp"

using namespace drawbend;

namespace {
std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

BOOST_AUTO_TEST_CASE(csv_problems_collected) {
  const std::string text = "# comment\na,b,a\n1,2,3\n1,2\n4,5,6\n7\n";
  const std::string msg = message_of([&] { parse_csv(text, "t.csv"); });
  BOOST_TEST_MESSAGE(msg);
  BOOST_TEST(msg.find("3 problems in t.csv") != std::string::npos);
  BOOST_TEST(msg.find("t.csv:2: header cell 3: expected unique column names, found 'a' twice") != std::string::npos);
  BOOST_TEST(msg.find("t.csv:4: expected 3 cells (as in the header), found 2") != std::string::npos);
  BOOST_TEST(msg.find("t.csv:6: expected 3 cells (as in the header), found 1") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(deck_problems_collected) {
  const std::string deck = R"([mesh]
x = { from = 0.0, to = 1.0, n = -2 }
y = { from = 0.0, to = 1.0, n = 1 }
z = { from = 0.0, to = 1.0, n = 1 }
[material]
type = "elastic"
E = 70000.0
nu = 0.3
density = 2.7e-9
[numerics]
dt_safety = "x"
[[tool]]
name = "floor"
[[tool.surface]]
kind = "plane"
normal = [0.0, 0.0, 1.0]
[[contact]]
faces = "zmin"
tool = "floor"
friction = { law = "coulomb", mu = -0.2 }
[[step]]
duration = 1e-3
speed = 3.0
)";
  const std::string msg = message_of([&] { io::parse_deck(deck, "d.toml"); });
  BOOST_TEST_MESSAGE(msg);
  BOOST_TEST(msg.find("4 problems in d.toml") != std::string::npos);
  BOOST_TEST(msg.find("d.toml:2: mesh.x.n: expected a whole number >= 1") != std::string::npos);
  BOOST_TEST(msg.find("d.toml:11: numerics.dt_safety: expected a finite number, found the string \"x\"") != std::string::npos);
  BOOST_TEST(msg.find("d.toml:20: contact.friction.mu: expected a friction coefficient >= 0, found -0.2") != std::string::npos);
  BOOST_TEST(msg.find("d.toml:23: step 'step1'.speed: unknown key") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(wrong_shapes_are_located_not_crashes) {
  const std::string a = message_of([] { io::parse_deck("numerics = 3\n[mesh]\n", "a.toml"); });
  BOOST_TEST(a.find("a.toml:1: numerics: expected a table, found 3") != std::string::npos);
  const std::string b = message_of([] { io::parse_deck("[mesh]\nx = { breaks = 1, counts = [1] }\n", "b.toml"); });
  BOOST_TEST(b.find("b.toml:2: mesh.x: expected both 'breaks'") != std::string::npos);
  const std::string c = message_of([] { io::parse_deck("output = [1]\n", "c.toml"); });
  BOOST_TEST(c.find("c.toml:1: output: expected a table, found an array") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(bad_table_headers_are_syntax_errors) {
  const std::string a = message_of([] { io::parse_deck("x = 1\n[\nmaterial]\n", "h.toml"); });
  BOOST_TEST(a.find("h.toml:2:1: TOML syntax error: expected a table name after '['") != std::string::npos);
  const std::string b = message_of([] { io::parse_deck("[[[1]]]\n", "h.toml"); });
  BOOST_TEST(b.find("h.toml:1:1: TOML syntax error: expected a table name after '[['") != std::string::npos);
  const std::string d = message_of([] { io::parse_deck("fixed = [}}]\n", "h.toml"); });
  BOOST_TEST(d.find("h.toml:1:10: TOML syntax error: expected ']' to close the '[', found '}'") != std::string::npos);
  const std::string e = message_of([] { io::parse_deck("x = 0.\xd1\xb5\n", "h.toml"); });
  BOOST_TEST(e.find("h.toml:1:7: TOML syntax error: expected ASCII outside strings and comments, found the byte 0xd1") != std::string::npos);
  // A quote glued to a bare value is not a string to toml++, which tests
  // what follows against its whitespace table (undefined behaviour for
  // U+FEF8): refused before toml++ sees it (the fuzzer's fourth finding).
  const std::string q = message_of([] { io::parse_deck("kinr =0\"press\xef\xbb\xb8gth\n", "h.toml"); });
  BOOST_TEST(q.find("h.toml:1:14: TOML syntax error: expected ASCII outside strings and comments, found the byte 0xef") != std::string::npos);
  const std::string q2 = message_of([] { io::parse_deck("x = 1'\xc2\xa1'\n", "h.toml"); });
  BOOST_TEST(q2.find("h.toml:1:7: TOML syntax error: expected ASCII outside strings and comments") != std::string::npos);
  const std::string q3 = message_of([] { io::parse_deck("x = [1.\"\xc2\xa1\"]\n", "h.toml"); });
  BOOST_TEST(q3.find("h.toml:1:9: TOML syntax error: expected ASCII outside strings and comments") != std::string::npos);
  // A backslash before a non-ASCII character in a multi-line string: toml++
  // tests it against the same table (the fuzzer's fifth finding).
  const std::string b5 = message_of([] { io::parse_deck("x = \"\"\" \\\xcb\x8fi\n\"\"\"\n", "h.toml"); });
  BOOST_TEST(b5.find("h.toml:1:10: TOML syntax error: expected an escape sequence after '\\', found the byte 0xcb") != std::string::npos);
  // Line and column count the lines of multi-line strings and escaped newlines.
  const std::string lc = message_of([] { io::parse_deck("x = \"\"\"a\\\n b\nc\"\"\"\n  y = 1\xc2\xa1\n", "h.toml"); });
  BOOST_TEST(lc.find("h.toml:4:8: TOML syntax error: expected ASCII outside strings and comments") != std::string::npos);
  // A date's shape, a space, one digit and a terminator: toml++ asserts (the
  // fuzzer's sixth finding); in an array too.  A real date-time still parses.
  const std::string d6 = message_of([] { io::parse_deck("x = 1979-05-27 1\n", "h.toml"); });
  BOOST_TEST(d6.find("h.toml:1:5: TOML syntax error: expected a date, or a date-time such as 1979-05-27 07:32:00, found '1979-05-27 1'") != std::string::npos);
  const std::string d7 = message_of([] { io::parse_deck("x = [0\"----)-\"x 1]\n", "h.toml"); });
  BOOST_TEST(d7.find("h.toml:1:6: TOML syntax error: expected a date") != std::string::npos);
  const std::string d8 = message_of([] { io::parse_deck("x = 1979-05-27 07:32:00\ny = 1979-05-27\n", "h.toml"); });
  BOOST_TEST(d8.find("TOML syntax error") == std::string::npos);
  // A quote after an '=' glued to a value (the fuzzer's seventh finding).
  const std::string q7 = message_of([] { io::parse_deck("ka =5=\"pNNp\xce\xa9N\"\n", "h.toml"); });
  BOOST_TEST(q7.find("h.toml:1:12: TOML syntax error: expected ASCII outside strings and comments, found the byte 0xce") != std::string::npos);
  // A vertical tab or form feed in a value (both end a bare value for toml++):
  // the pre-check looped on them for ever (the suite's 5 s fuzz run, 2026-11-29).
  const std::string vt = message_of([] { io::parse_deck("x = \v1\ny = \f\n", "h.toml"); });
  BOOST_TEST(vt.find("h.toml:1:") != std::string::npos);
  // Quotes where TOML lets strings begin still open strings.
  const std::string s = message_of([] {
    io::parse_deck("a.\"\xce\xbc\" = 1\nb = [\"\xce\xbc\",\"\xce\xbc\"]\nc = {d=\"\xce\xbc\",e.\"\xce\xbc\"={}}\ne=\"\xce\xbc\"\n[[f.\"\xce\xbc\"]]\n[g.\"\xce\xbc\"]\n", "h.toml");
  });
  BOOST_TEST(s.find("TOML syntax error") == std::string::npos);
  const std::string g = message_of([] { io::parse_deck("[[tool\xd2\x88urface]]\n", "h.toml"); });
  BOOST_TEST(g.find("h.toml:1:7: TOML syntax error: expected ASCII outside strings and comments") != std::string::npos);
  // Non-ASCII text in comments and strings is fine.
  const std::string f = message_of([] { io::parse_deck("# \xce\xbc = 0.1\n[case]\nname = \"\xce\xbc\"\n", "h.toml"); });
  BOOST_TEST(f.find("TOML syntax error") == std::string::npos);
  // Arrays whose lines start with '[' are values, not headers.
  const std::string c = message_of([] { io::parse_deck("a = [\n[ ],\n[\n1]]\n", "h.toml"); });
  BOOST_TEST(c.find("TOML syntax error") == std::string::npos);
}

BOOST_AUTO_TEST_CASE(provenance_marks_changed_inputs) {
  BOOST_TEST(hex64(fnv1a64("a")) == "af63dc4c8601ec8c");
  const auto dir = std::filesystem::temp_directory_path() / "drawbend_provenance_test";
  std::filesystem::remove_all(dir);
  const std::string in = (dir / "input.csv").string(), prov = (dir / "provenance.csv").string();
  write_file_atomic(in, "x\n1\n");
  read_csv(in);
  write_provenance(prov, "test");
  BOOST_TEST(stale_inputs(prov).empty());
  write_file_atomic(in, "x\n2\n");
  const auto stale = stale_inputs(prov);
  BOOST_REQUIRE(stale.size() == 1u);
  BOOST_TEST(stale[0].find("input.csv has changed") != std::string::npos);
  std::filesystem::remove(in);
  BOOST_TEST(stale_inputs(prov)[0].find("input.csv is gone") != std::string::npos);
}

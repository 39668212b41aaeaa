// CSV reading/writing and the report's Markdown expansion.
// Closed-form answers:
//  - split_csv_line("a,\"b,c\",d") = {a, "b,c", d}.
//  - A ragged row is an InputError naming file:line; a non-number names file:line:column.
//  - Quotes (csv_quote_problem): "" for `"a ""b""",c`, ` "x" ,y` and `a,"b;c"`;
//    "cell 2: text after the cell's closing quote" for `1,"x"y`; "cell 2: ... unquoted
//    cell" for `2,5"6`; "never closed" for `1,"x`; with ';' as the separator
//    `"a";"b"` is fine.  read_csv of a file holding `1,"x"y` on line 3 is an
//    InputError naming ":3: cell 2" (a stray quote used to drop silently).
//  - a CsvWriter with a column named twice is refused (std::logic_error): the
//    readers refuse such a file, so a chapter must fail when it makes one;
//  - markdown_table escapes '|'; {{key}} expands to "value unit"; an unknown key
//    is an InputError naming the source line.
//  - Chapter::plot passes a variable to gnuplot unchanged, whatever it holds:
//    a gnuplot script that prints `label` to its outfile gets back exactly
//    "Hill'48 \"quoted\" $HOME `x` back\\slash" (quote, double quote, $, backtick,
//    backslash: once a bare "Hill'48" broke the command line).
#define BOOST_TEST_MODULE csv_and_report
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>

#include <fstream>
#include <sstream>

#include "core/csv.hpp"
#include "study/chapter.hpp"
#include "study/report_assembler.hpp"

using namespace drawbend;

static std::string tmpdir() {
  auto d = std::filesystem::temp_directory_path() / "drawbend_csv_test";
  std::filesystem::create_directories(d / "tables");
  return d.string();
}

BOOST_AUTO_TEST_CASE(split_and_read) {
  const auto v = split_csv_line("a,\"b,c\",d");
  BOOST_TEST(v.size() == 3u);
  BOOST_TEST(v[1] == "b,c");
  const std::string p = tmpdir() + "/t.csv";
  write_file_atomic(p, "# comment\nx,y\n1,2\n3,abc\n");
  const auto t = read_csv(p);
  BOOST_TEST(t.comments.size() == 1u);
  BOOST_TEST(t.number(t.rows[0], "y") == 2.0);
  try {
    t.number(t.rows[1], "y");
    BOOST_FAIL("expected InputError");
  } catch (const InputError& e) {
    BOOST_TEST(std::string(e.what()).find("t.csv:4: column 'y'") != std::string::npos);
  }
  BOOST_CHECK_THROW(t.column("z"), InputError);
  write_file_atomic(p, "x,y\n1,2,3\n");
  try {
    read_csv(p);
    BOOST_FAIL("expected InputError");
  } catch (const InputError& e) {
    BOOST_TEST(std::string(e.what()).find(":2:") != std::string::npos);
  }
}

BOOST_AUTO_TEST_CASE(stray_quotes_refused) {
  BOOST_TEST(csv_quote_problem("\"a \"\"b\"\"\",c") == "");
  BOOST_TEST(csv_quote_problem(" \"x\" ,y") == "");
  BOOST_TEST(csv_quote_problem("a,\"b;c\"") == "");
  BOOST_TEST(csv_quote_problem("\"a\";\"b\"", ';') == "");
  BOOST_TEST(csv_quote_problem("1,\"x\"y").find("cell 2: text after the cell's closing quote") == 0u);
  BOOST_TEST(csv_quote_problem("2,5\"6").find("cell 2: a quote inside an unquoted cell") == 0u);
  BOOST_TEST(csv_quote_problem("1,\"x").find("never closed") != std::string::npos);
  const std::string p = tmpdir() + "/q.csv";
  write_file_atomic(p, "x,y\n0,1\n1,\"x\"y\n");
  try {
    read_csv(p);
    BOOST_FAIL("expected InputError");
  } catch (const InputError& e) {
    BOOST_TEST(std::string(e.what()).find("q.csv:3: cell 2") != std::string::npos);
  }
}

BOOST_AUTO_TEST_CASE(writer_refuses_a_repeated_column) {
  BOOST_CHECK_THROW(CsvWriter({"angle_deg", "h_mm", "angle_deg"}), std::logic_error);
  BOOST_CHECK_NO_THROW(CsvWriter({"h_max_at_deg", "h_min_at_deg"}));
}

BOOST_AUTO_TEST_CASE(markdown_expansion) {
  const std::string d = tmpdir();
  write_file_atomic(d + "/values.csv", "key,value,unit\nmu,0.096,\nF,107,N\n");
  write_file_atomic(d + "/tables/a.csv", "# c\nh1,h2\nx|y,2\n");
  study::ChapterSource ch{"chx", d + "/results.md", d};
  const std::string md = study::expand_chapter("mu is {{mu}}, F is {{ F }}.\n@table tables/a.csv | Cap\n", ch);
  BOOST_TEST(md.find("mu is 0.096, F is 107\u00a0N.") != std::string::npos);
  BOOST_TEST(md.find("x\\|y") != std::string::npos);
  BOOST_TEST(md.find(": Cap") != std::string::npos);
  // Issue 55: a list item's continuation line that starts with a number and "."
  // or ")" (wrapped text, or a value) keeps it as text, not as a numbered list;
  // a real list and unindented lines are left alone; no absolute build path shows.
  const std::string li = study::expand_chapter("- over the\n  {{F}}. Next\n- rows (22 instead of\n  10) brought\n\n1. one\n2. two\n", ch);
  BOOST_TEST(li.find("  107\u00a0N. Next") != std::string::npos);  // a unit after the number: not a marker
  BOOST_TEST(li.find("  10\\) brought") != std::string::npos);
  BOOST_TEST(li.find("\n2. two") != std::string::npos);
  // A study laid out as repo/chapters/<id> and repo/build/chapters/<id>.
  const std::string repo = d + "/repo", out = repo + "/build/chapters/chy";
  write_file_atomic(out + "/values.csv", "key,value,unit\nn,6,\nmaps," + repo + "/build/chapters/ch4/maps,\n");
  study::ChapterSource chy{"chy", repo + "/chapters/chy/results.md", out};
  const std::string nv = study::expand_chapter("- of the\n  {{n}}. combinations\n\nmaps in {{maps}}\n", chy);
  BOOST_TEST(nv.find("  6\\. combinations") != std::string::npos);
  BOOST_TEST(nv.find("maps in build/chapters/ch4/maps") != std::string::npos, nv);
  BOOST_TEST(nv.find(repo) == std::string::npos, nv);
  BOOST_CHECK_THROW(study::expand_chapter("{{nope}}\n", ch), InputError);
  BOOST_CHECK_THROW(study::expand_chapter("@figure figures/none.svg | x\n", ch), InputError);
}

BOOST_AUTO_TEST_CASE(plot_passes_variables_verbatim) {
  const auto root = std::filesystem::temp_directory_path() / "drawbend_plot_quote_test";
  std::filesystem::remove_all(root);
  std::filesystem::create_directories(root / "gp");
  std::ofstream((root / "gp" / "echo.gp").string()) << "set print outfile\nprint label\nunset print\n";
  study::Chapter ch("chx", "plot quoting test");
  const std::string out = (root / "out").string(), gp = (root / "gp").string();
  const char* argv[] = {"chx", "--out", out.c_str(), "--figures", gp.c_str()};
  BOOST_REQUIRE(ch.parse(5, const_cast<char**>(argv)));
  const std::string label = "Hill'48 \"quoted\" $HOME `x` back\\slash";
  ch.plot("echo", "echoed", {{"label", label}});
  std::ifstream in((root / "out" / "figures" / "echoed.svg").string());
  std::string line;
  std::getline(in, line);
  BOOST_TEST(line == label);
  std::filesystem::remove_all(root);
}

// fmt formats with std::to_chars (general, with the precision): printf's
// "%.*g" by the standard; checked against snprintf on ties, zeros, infinities,
// subnormals and a sweep of magnitudes at every precision the outputs use.
BOOST_AUTO_TEST_CASE(fmt_is_printf_g) {
  std::vector<double> v = {0.0, -0.0, 0.5, 1.5, 2.5, -2.5, 0.125, 0.0625, 999999.5, 9.9999995, 1e100, -1e-300,
                           5e-324, 1e-5, 1e-4, 123456.0, 1234567.0, 1.0 / 3.0, 2.0 / 3.0, 1e21, 1e22, 0.1,
                           std::numeric_limits<double>::max(), std::numeric_limits<double>::infinity(),
                           -std::numeric_limits<double>::infinity()};
  for (int e = -30; e <= 30; ++e)
    for (double m : {1.0, 1.25, 3.5, 4.5, 7.0 / 9.0, 9.95, 9.995}) v.push_back(m * std::pow(10.0, e)), v.push_back(-m * std::pow(10.0, e));
  for (double x : v)
    for (int p = 0; p <= 17; ++p) {
      char buf[64];
      std::snprintf(buf, sizeof buf, "%.*g", p, x);
      BOOST_TEST(fmt(x, p) == std::string(buf), "x " << x << " precision " << p);
    }
  BOOST_TEST(fmt(std::nan(""), 4) == "nan");
}

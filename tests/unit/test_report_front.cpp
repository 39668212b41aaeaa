// The report's front page and the display of checks.
// Closed-form answers:
//  - round_for_display rounds to the tolerance's leading decimal place, with 3 to
//    6 significant digits: (74.105281, 5) -> "74.1"; (168.29819, 20) -> "168";
//    (118.647, 0.005) -> "118.647"; (0.0961234, 0.001) -> "0.0961";
//    (1234567.0, 0) -> "1.23457e+06" (6 digits, scientific beyond 1e6).
//  - A claim (unit "true=1") shows 1/0 as yes/no, tolerance as a dash, no unit;
//    "-" and "" show as the unit "1".
//  - A checks.csv without a `kind` column counts its checks as "unclassified".
//  - Two chapters with 3 and 2 checks (kinds simulated x2 disagree+pass,
//    rederived x2 pass+erratum, health x1 pass) give the counts 5 checks,
//    3 pass, 1 erratum, 1 disagree, and the abstract says so.
//  - Measured checks by what they are: 2 blind comparisons (kind measured,
//    1 pass, 1 disagree), 1 blind claim (pass), 2 fitted and 1 selected give
//    "1 of 2 blind comparisons agree", "1 of 1 yes/no claim", "2 measured
//    numbers were fitted to and 1 was used to choose a model"; the fitted and
//    selected passes are not counted as agreement.
//  - Two disagreements sharing one note show the note once (rowspan="2"),
//    a third with its own note stands alone: the note text appears once each.
//  - html_breakable("a_b.c", "._") is "a_<wbr>b.<wbr>c".
//  - html_provenance turns "[161.6 N]{.src-thesis}" into a tagged span, nothing else.
//  - link_pages on a front page and two chapter pages (x.html, y.html): the
//    front page's href="#checks-y" becomes "y.html#checks-y"; x's link to
//    "#y-sec" becomes "y.html#y-sec", its own "#x-sec" stays; every page
//    carries all three pages' contents, its own entry marked current; x has
//    two bars (no previous chapter, next y), y two (previous x, no next).
#define BOOST_TEST_MODULE report_front
#include <boost/test/unit_test.hpp>
#include <algorithm>
#include <filesystem>

#include "core/csv.hpp"
#include "study/check_format.hpp"
#include "study/list_audit.hpp"
#include "study/report_front.hpp"
#include "study/report_pages.hpp"

using namespace drawbend;
using namespace drawbend::study;
namespace fs = std::filesystem;

BOOST_AUTO_TEST_CASE(rounding_and_units) {
  BOOST_TEST(round_for_display(74.105281, 5) == "74.1");
  BOOST_TEST(round_for_display(168.29819, 20) == "168");
  BOOST_TEST(round_for_display(118.647, 0.005) == "118.647");
  BOOST_TEST(round_for_display(0.0961234, 0.001) == "0.0961");
  BOOST_TEST(round_for_display(1234567.0, 0) == "1.23457e+06");
  BOOST_TEST(round_for_display(-0.0, 1) == "0");
  BOOST_TEST(display_value("1", "true=1", "0") == "yes");
  BOOST_TEST(display_value("0", "true=1", "0") == "no");
  BOOST_TEST(display_tolerance("0", "true=1") == "\u2013");
  BOOST_TEST(display_unit("-") == "1");
  BOOST_TEST(display_unit("") == "1");
  BOOST_TEST(display_unit("true=1") == "");
  BOOST_TEST(display_unit("MPa") == "MPa");
  BOOST_TEST(display_value("n/a", "N", "1") == "n/a");
}

static ChapterSource chapter(const fs::path& root, const std::string& id, const std::string& checks,
                             const std::string& tier = "quick") {
  const fs::path src = root / "src" / id, out = root / "out" / id;
  fs::create_directories(src);
  fs::create_directories(out / "figures");
  write_file_atomic((src / "intro.md").string(), "# Chapter X \u2014 A title {#" + id + "}\n\ntext\n");
  write_file_atomic((out / "checks.csv").string(), checks);
  write_file_atomic((out / "values.csv").string(), "key,value,unit\ntier," + tier + ",\n");
  write_file_atomic((out / "figures" / "a.svg").string(), "<svg/>");
  return {id, src.string(), out.string()};
}

BOOST_AUTO_TEST_CASE(front_page_counts_by_kind) {
  const fs::path root = fs::temp_directory_path() / "drawbend_front_test";
  fs::remove_all(root);
  const std::string head = "id,kind,quantity,thesis,ours,tolerance,unit,status,note\n";
  std::vector<ChapterSource> chs{
      chapter(root, "cha", head + "a.1,simulated,F,168.29819,120.1,20,N,disagree,mesh too coarse\n"
                                  "a.2,simulated,mu,0.1,0.1004,0.005,-,pass,ok\n"
                                  "a.3,rederived,x,118.65,118.647,0.005,-,pass,ok\n"),
      chapter(root, "chb", head + "b.1,rederived,y,2,3,0.5,mm,erratum,typo in Table 9\n"
                                  "b.2,health,energy,0,0.001,0.01,1,pass,ok\n")};
  const std::string a = abstract_paragraph(chs);
  BOOST_TEST(a.find("compares 5 numbers") != std::string::npos, a);
  BOOST_TEST(a.find("in 2 checks: 1 agree") != std::string::npos, a);
  BOOST_TEST(a.find("1 is not reproduced") != std::string::npos, a);
  BOOST_TEST(a.find("(2 checks) confirms 1 value and finds 1 erratum") != std::string::npos, a);
  BOOST_TEST(a.find("No check fails.") != std::string::npos, a);
  BOOST_TEST(a.find("(mesh tier: quick)") != std::string::npos, a);
  const std::string y = front_yaml(chs, {"*T*", "2026-01-01"}, "It's a title");
  BOOST_TEST(y.find("title: 'It''s a title'") != std::string::npos, y);
  BOOST_TEST(y.find("subtitle: 'Reproduces: *T*'") != std::string::npos, y);
  BOOST_TEST(y.find("Mesh tier: quick") != std::string::npos, y);
  BOOST_TEST(y.find("2026-01-01") != std::string::npos, y);
  BOOST_TEST(y.find("abstract: 'This report rebuilds") != std::string::npos, y);
  const std::string f = front_page(chs, {"*T*", "2026-01-01"});
  BOOST_TEST(f.find(">168<") != std::string::npos);   // thesis value rounded to the tolerance
  BOOST_TEST(f.find(">120<") != std::string::npos);
  BOOST_TEST(f.find("168.29819") == std::string::npos);
  BOOST_TEST(f.find("href=\"#checks-cha\"") != std::string::npos);
  BOOST_TEST(f.find("Errata at a glance") != std::string::npos);
  BOOST_TEST(chapter_title(chs[0]) == "Chapter X \u2014 A title");
}

BOOST_AUTO_TEST_CASE(blind_measured_counts_and_shared_notes) {
  const fs::path root = fs::temp_directory_path() / "drawbend_front_blind_test";
  fs::remove_all(root);
  const std::string head = "id,kind,quantity,thesis,ours,tolerance,unit,status,note\n";
  std::vector<ChapterSource> chs{
      chapter(root, "cha", head + "m.1,measured,F,10,10.5,1,N,pass,ok\n"
                                  "m.2,measured,F,10,13,1,N,disagree,too stiff\n"
                                  "m.3,measured,claim,1,1,0,true=1,pass,ok\n"
                                  "f.1,fitted,F,10,10,1,N,pass,fit\n"
                                  "f.2,fitted,F,20,20.1,1,N,pass,fit\n"
                                  "s.1,selected,F,30,30.2,1,N,pass,chosen\n"
                                  "d.1,simulated,G,1,2,0.1,-,disagree,shared cause\n"
                                  "d.2,simulated,G,1,3,0.1,-,disagree,shared cause\n")};
  const MeasuredCounts m = measured_counts(chs);
  BOOST_TEST(m.blind.total() == 2);
  BOOST_TEST(m.blind.pass == 1);
  BOOST_TEST(m.blind_claims.total() == 1);
  BOOST_TEST(m.fitted == 2);
  BOOST_TEST(m.selected == 1);
  const std::string a = abstract_paragraph(chs);
  BOOST_TEST(a.find("1 of 2 blind comparisons agree") != std::string::npos, a);
  BOOST_TEST(a.find("1 of 1 yes/no claim tested on measured data hold") != std::string::npos, a);
  BOOST_TEST(a.find("2 measured numbers were fitted to and 1 was used to choose a model") != std::string::npos, a);
  const std::string f = front_page(chs, {"T", "d"});
  BOOST_TEST(f.find("1 of 2 blind comparisons agree") != std::string::npos);
  BOOST_TEST(f.find("rowspan=\"2\"") != std::string::npos, f);
  const auto once = [&](const std::string& x) {
    const auto p = f.find(x);
    return p != std::string::npos && f.find(x, p + 1) == std::string::npos;
  };
  BOOST_TEST(once("shared cause"));
  BOOST_TEST(once("too stiff"));
  BOOST_TEST(f.find(">fitted<") != std::string::npos);
  BOOST_TEST(f.find(">selected<") != std::string::npos);
  fs::remove_all(root);
}

BOOST_AUTO_TEST_CASE(missing_kind_column_is_unclassified) {
  const fs::path root = fs::temp_directory_path() / "drawbend_front_test_nokind";
  fs::remove_all(root);
  std::vector<ChapterSource> chs{chapter(root, "chc", "id,quantity,thesis,ours,tolerance,unit,status,note\n"
                                                      "c.1,claim,1,1,0,true=1,pass,ok\n")};
  const CsvTable t = read_csv(chs[0].out_dir + "/checks.csv");
  BOOST_TEST(kind_of(t, t.rows[0]) == "unclassified");
  const std::string f = front_page(chs, {"T", "d"});
  BOOST_TEST(f.find("unclassified") != std::string::npos);
  BOOST_TEST(abstract_paragraph(chs).find("do not record the kind") != std::string::npos);
  BOOST_TEST(checks_html_table(t, "c").find(">yes<") != std::string::npos);
}

// A report whose chapters ran different tiers (make runs some chapters on the
// quick tier) names the tier most chapters ran, then each other tier with its
// chapters; the per-chapter table has a tier column.
BOOST_AUTO_TEST_CASE(front_page_states_each_chapters_tier) {
  const fs::path root = fs::temp_directory_path() / "drawbend_front_tier_test";
  fs::remove_all(root);
  const std::string head = "id,kind,quantity,thesis,ours,tolerance,unit,status,note\n";
  std::vector<ChapterSource> chs{chapter(root, "cha", head + "a.1,simulated,F,1,1,0.1,N,pass,ok\n", "full"),
                                 chapter(root, "chb", head + "b.1,simulated,F,1,1,0.1,N,pass,ok\n", "quick"),
                                 chapter(root, "chc", head + "c.1,simulated,F,1,1,0.1,N,pass,ok\n", "full")};
  const std::string a = abstract_paragraph(chs);
  BOOST_TEST(a.find("(mesh tier: full; quick for chb)") != std::string::npos, a);
  const std::string y = front_yaml(chs, {"*T*", "2026-01-01"}, "t");
  BOOST_TEST(y.find("Mesh tier: full; quick for chb") != std::string::npos, y);
  const std::string f = front_page(chs, {"*T*", "2026-01-01"});
  BOOST_TEST(f.find("<th>tier</th>") != std::string::npos);
  BOOST_TEST(f.find("</a></td><td>quick</td>") != std::string::npos);
  fs::remove_all(root);
}

// The audit of a disagreements list (study/list_audit.hpp), chapter "cha" on
// the full tier and "chb" on the quick tier:
//  - "cha.1" (full) names a check of cha: used; "chb.1" (quick) one of chb: used;
//  - "chb.2" (full only) is not audited, since chb ran no full tier;
//  - "cha.9" (any tier) matches no check of cha, which ran: unused;
//  - "zz.1" belongs to a chapter that ran on no tier (a misspelt id): unused.
// So exactly {"cha.9", "zz.1"} are reported.
BOOST_AUTO_TEST_CASE(list_audit_checks_each_entry_on_its_chapters_tiers) {
  const fs::path root = fs::temp_directory_path() / "drawbend_list_audit_test";
  fs::remove_all(root);
  const std::string head = "id,kind,quantity,thesis,ours,tolerance,unit,status,note\n";
  std::vector<ChapterSource> chs{chapter(root, "cha", head + "cha.1,simulated,F,1,2,0.1,N,disagree,x\n", "full"),
                                 chapter(root, "chb", head + "chb.1,simulated,F,1,2,0.1,N,disagree,x\n", "quick")};
  const std::string list = (root / "disagreements.csv").string();
  write_file_atomic(list, "id,explanation,tier\ncha.1,why,full\nchb.1,why,quick\nchb.2,why,full\ncha.9,why,\nzz.1,why,\n");
  BOOST_TEST(chapter_of("cha.fb.d42") == "cha");
  BOOST_TEST(chapter_of("cha") == "cha");
  BOOST_TEST(chapter_tier(chs[0]) == "full");
  auto dead = unused_list_entries(chs, list);
  std::sort(dead.begin(), dead.end());
  BOOST_TEST(dead.size() == 2u);
  BOOST_TEST((dead == std::vector<std::string>{"cha.9", "zz.1"}));
  fs::remove_all(root);
}

BOOST_AUTO_TEST_CASE(breakable_text_breaks_after_the_given_characters) {
  BOOST_TEST(study::html_breakable("a_b.c", "._") == "a_<wbr>b.<wbr>c");
  BOOST_TEST(study::html_breakable("a<b", "") == "a&lt;b");
  // A provenance marker of a note becomes a span the style sheet tags; other brackets stay.
  BOOST_TEST(study::html_provenance("ours 1 N against [161.6 N]{.src-thesis} [sic]") ==
             "ours 1 N against <span class=\"src src-thesis\" title=\"source: thesis\">161.6 N</span> [sic]");
  BOOST_TEST(study::html_provenance("[a] and [2 mm]{.src-input}") ==
             "[a] and <span class=\"src src-input\" title=\"source: input\">2 mm</span>");
}

BOOST_AUTO_TEST_CASE(pages_share_contents_and_link_across) {
  auto page = [](const std::string& toc, const std::string& body) {
    return "<html><body>\n<nav id=\"TOC\" role=\"doc-toc\">\n<ul>\n" + toc + "</ul>\n</nav>\n" + body +
           "\n</body></html>";
  };
  std::vector<study::HtmlPage> p{
      {"index.html", "Front page",
       page("<li><a href=\"#summary\">About</a></li>\n", "<h1 id=\"summary\">About</h1><a href=\"#checks-y\">y</a>")},
      {"x.html", "Chapter X",
       page("<li><a href=\"#x\">X</a><ul><li><a href=\"#x-sec\">S</a></li></ul></li>\n",
            "<h1 id=\"x\">X</h1><h2 id=\"x-sec\">S</h2><a href=\"#x-sec\">here</a> <a href=\"#y-sec\">there</a>")},
      {"y.html", "Chapter Y",
       page("<li><a href=\"#y\">Y</a><ul><li><a href=\"#y-sec\">T</a></li></ul></li>\n",
            "<h1 id=\"y\">Y</h1><h2 id=\"y-sec\">T</h2><div id=\"checks-y\"></div>")}};
  BOOST_TEST(study::toc_items(p[1].html).find("href=\"#x-sec\"") != std::string::npos);
  study::link_pages(p);
  const std::string &f = p[0].html, &x = p[1].html, &y = p[2].html;
  BOOST_TEST(f.find("<a href=\"y.html#checks-y\">y</a>") != std::string::npos);
  BOOST_TEST(x.find("<a href=\"#x-sec\">here</a>") != std::string::npos);
  BOOST_TEST(x.find("<a href=\"y.html#y-sec\">there</a>") != std::string::npos);
  for (const std::string& h : {f, x, y}) {
    BOOST_TEST(std::count(h.begin(), h.end(), '\n') > 0);
    BOOST_TEST((h.find("#summary\"") != std::string::npos && h.find("#x-sec\"") != std::string::npos &&
                h.find("#y-sec\"") != std::string::npos));
  }
  BOOST_TEST(x.find("<li class=\"current\"><a aria-current=\"page\" href=\"#x\">X</a>") != std::string::npos);
  BOOST_TEST(x.find("<a href=\"index.html#summary\">About</a>") != std::string::npos);
  BOOST_TEST(x.find("<nav id=\"TOC\" class=\"pages\"") != std::string::npos);
  BOOST_TEST(f.find("class=\"pages\"") == std::string::npos);  // the front page lists every section
  auto count = [](const std::string& h, const std::string& what) {
    std::size_t n = 0;
    for (auto at = h.find(what); at != std::string::npos; at = h.find(what, at + 1)) ++n;
    return n;
  };
  BOOST_TEST(count(x, "class=\"pagenav\"") == 2u);
  BOOST_TEST(count(x, "class=\"prev\"") == 0u);
  BOOST_TEST(count(x, "<a class=\"next\" href=\"y.html\">Chapter Y &rarr;</a>") == 2u);
  BOOST_TEST(count(y, "<a class=\"prev\" href=\"x.html\">&larr; Chapter X</a>") == 2u);
  BOOST_TEST(count(y, "class=\"next\"") == 0u);
  BOOST_TEST(count(f, "class=\"pagenav\"") == 0u);
}

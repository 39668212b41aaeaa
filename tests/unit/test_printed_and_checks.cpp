// Printed-digit values and the checks framework.
// Closed-form answers:
//  - "106.76" has half unit 0.005; "4.5e-4" has 0.5e-5; "1,450" is 1450 with 0.5.
//  - f(x) = x1 - x2 with both inputs printed to 0.01, compared with a value
//    printed to 0.01: tolerance = 0.005 + 0.005 + 0.005 = 0.015.
//  - Checks: within tolerance -> pass; outside -> fail; outside with a
//    documented erratum -> erratum; a documented erratum that passes -> fail.
//  - Claims: true -> pass; false -> fail unless documented (erratum).
//  - The longest matching prefix explains; a wildcard entry whose check passes
//    is stale (fail); a NaN is never excused; a bare '*' entry is rejected;
//    entries matching no check are listed as unused.
//  - "1,45" (decimal comma) is rejected rather than read as 145.
//  - Disagreements with a tier column apply on their tier only (see the last case).
#define BOOST_TEST_MODULE printed_and_checks
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <filesystem>
#include <map>

#include "analysis/printed.hpp"
#include "core/csv.hpp"
#include "study/checks.hpp"

using namespace drawbend;
namespace tt = boost::test_tools;

BOOST_AUTO_TEST_CASE(printed_digits) {
  auto a = analysis::parse_printed("106.76");
  BOOST_TEST(a.value == 106.76);
  BOOST_TEST(a.half_ulp == 0.005, tt::tolerance(1e-12));
  BOOST_TEST(analysis::parse_printed("4.5e-4").half_ulp == 0.5e-5, tt::tolerance(1e-12));
  auto c = analysis::parse_printed("1,450");
  BOOST_TEST(c.value == 1450.0);
  BOOST_TEST(c.half_ulp == 0.5);
  BOOST_CHECK_THROW(analysis::parse_printed("abc"), std::invalid_argument);
  BOOST_CHECK_THROW(analysis::parse_printed("1,45"), std::invalid_argument);
  BOOST_TEST(analysis::parse_printed("12,345,678.5").value == 12345678.5);
  const double tol = analysis::rounding_tolerance([](const std::vector<double>& x) { return x[0] - x[1]; },
                                                  {analysis::parse_printed("503.60"), analysis::parse_printed("396.84")},
                                                  0.005);
  BOOST_TEST(tol == 0.015, tt::tolerance(1e-9));
}

BOOST_AUTO_TEST_CASE(check_statuses) {
  const auto dir = std::filesystem::temp_directory_path() / "drawbend_checks_test";
  std::filesystem::create_directories(dir);
  const std::string errata = (dir / "errata.csv").string();
  write_file_atomic(errata, "id,explanation\nx.known,typo in the thesis\nx.family.*,all of these\nx.stale,was wrong\n");
  study::Checks c("test", study::Errata::load(errata));
  BOOST_TEST(study::to_string(c.agree(study::Kind::simulated, "x.ok", "q", 1.0, 1.01, 0.02, "N", "r").status) == "pass");
  BOOST_TEST(study::to_string(c.agree(study::Kind::simulated, "x.bad", "q", 1.0, 1.1, 0.02, "N", "r").status) == "fail");
  BOOST_TEST(study::to_string(c.rederive("x.known", "q", 1.0, 2.0, 0.02, "N", "r").status) == "erratum");
  BOOST_TEST(study::to_string(c.rederive("x.family.a", "q", 1.0, 2.0, 0.02, "N", "r").status) == "erratum");
  BOOST_TEST(study::to_string(c.rederive("x.unknown", "q", 1.0, 2.0, 0.02, "N", "r").status) == "fail");
  BOOST_TEST(study::to_string(c.rederive("x.stale", "q", 1.0, 1.0, 0.02, "N", "r").status) == "fail");
  // An agreement check is never excused by the errata list.
  BOOST_TEST(study::to_string(c.agree(study::Kind::simulated, "x.known2", "q", 1.0, 2.0, 0.02, "N", "r").status) == "fail");
  BOOST_TEST(c.count(study::Status::fail) == 4);
  BOOST_CHECK_THROW(c.agree(study::Kind::simulated, "x.ok", "q", 1, 1, 0, "", ""), std::logic_error);
  c.write((dir / "checks.csv").string());
  const auto t = read_csv((dir / "checks.csv").string());
  BOOST_TEST(t.header.size() == 9u);
  BOOST_TEST(t.text(t.rows.front(), "kind") == "simulated");
  BOOST_TEST(t.text(t.rows.at(2), "kind") == "rederived");
  BOOST_TEST(t.rows.size() == 7u);  // the duplicate was rejected
}

BOOST_AUTO_TEST_CASE(claims_prefixes_nan_and_audit) {
  const auto dir = std::filesystem::temp_directory_path() / "drawbend_checks_test2";
  std::filesystem::create_directories(dir);
  const std::string errata = (dir / "errata.csv").string();
  write_file_atomic(errata,
                    "id,explanation\na.*,short prefix\na.b.*,long prefix\nc.claim,claim contradicted\n"
                    "w.*,wildcard\nnever.used,dead entry\n");
  const auto e = study::Errata::load(errata);
  BOOST_TEST(e.explain("a.b.x") == "long prefix");
  BOOST_TEST(e.explain("a.x") == "short prefix");
  study::Checks c("test", e);
  BOOST_TEST(study::to_string(c.claim(study::Kind::rederived, "c.ok", "q", true, "r").status) == "pass");
  BOOST_TEST(study::to_string(c.claim(study::Kind::rederived, "c.false", "q", false, "r").status) == "fail");
  BOOST_TEST(study::to_string(c.claim(study::Kind::rederived, "c.claim", "q", false, "r").status) == "erratum");
  BOOST_TEST(study::to_string(c.rederive("w.passes", "q", 1.0, 1.0, 0.1, "", "r").status) == "fail");
  BOOST_TEST(study::to_string(c.rederive("a.b.nan", "q", 1.0, NAN, 0.1, "", "r").status) == "fail");
  // An erratum never excuses a check of another kind: a claim tested on our
  // simulations that misses is a failure unless disagreements.csv documents it.
  BOOST_TEST(study::to_string(c.claim(study::Kind::simulated, "c.claim2", "q", false, "r").status) == "fail");
  BOOST_TEST(study::to_string(c.agree(study::Kind::health, "a.b.health", "q", 1.0, 2.0, 0.1, "", "r").status) == "fail");
  BOOST_CHECK_THROW(c.claim(static_cast<study::Kind>(99), "c.bad_kind", "q", true, "r"), std::logic_error);
  for (auto k : {study::Kind::rederived, study::Kind::simulated, study::Kind::measured, study::Kind::fitted,
                 study::Kind::selected, study::Kind::verification, study::Kind::health, study::Kind::software})
    BOOST_TEST(!study::to_string(k).empty());
  const auto dead = e.unused({"a.b.x", "c.claim", "w.passes"});
  BOOST_TEST(dead.size() == 1u);
  BOOST_TEST(dead.front() == "never.used");
  write_file_atomic(errata, "id,explanation\n*,everything\n");
  BOOST_CHECK_THROW(study::Errata::load(errata), InputError);
}

// Tiered disagreements (column `tier`): a row for the quick tier excuses its
// check on the quick tier only; on the full tier the same check is judged by
// its tolerance alone (pass, not stale); an empty tier applies to both; an
// unknown tier value is rejected.
BOOST_AUTO_TEST_CASE(disagreement_tiers) {
  const auto dir = std::filesystem::temp_directory_path() / "drawbend_checks_test3";
  std::filesystem::create_directories(dir);
  const std::string list = (dir / "disagreements.csv").string();
  write_file_atomic(list, "id,explanation,tier\nq.only,coarse mesh artefact,quick\nboth,any mesh,\n");
  study::Checks quick("test", {}, study::Errata::load(list, "quick"));
  study::Checks full("test", {}, study::Errata::load(list, "full"));
  BOOST_TEST(study::to_string(quick.agree(study::Kind::simulated, "q.only", "q", 1.0, 1.5, 0.1, "N", "r").status) == "disagree");
  BOOST_TEST(study::to_string(full.agree(study::Kind::simulated, "q.only", "q", 1.0, 1.05, 0.1, "N", "r").status) == "pass");
  BOOST_TEST(study::to_string(full.agree(study::Kind::simulated, "both", "q", 1.0, 1.5, 0.1, "N", "r").status) == "disagree");
  BOOST_TEST(study::Errata::load(list).explain("q.only") == "coarse mesh artefact");  // no tier: every row
  write_file_atomic(list, "id,explanation,tier\nx,y,fine\n");
  BOOST_CHECK_THROW(study::Errata::load(list, "quick"), InputError);
  // One row for several checks (ids separated by spaces): each is excused by
  // the one explanation; an unused id of the row is still reported.
  write_file_atomic(list, "id,explanation,tier\nm.a m.b m.c.*,one shared note,\n");
  const auto shared = study::Errata::load(list, "quick");
  BOOST_TEST(shared.explain("m.a") == "one shared note");
  BOOST_TEST(shared.explain("m.b") == "one shared note");
  BOOST_TEST(shared.explain("m.c.x") == "one shared note");
  BOOST_TEST(shared.explain("m.d").empty());
  const auto unused = shared.unused({"m.a", "m.c.x"});
  BOOST_TEST(unused.size() == 1u);
  BOOST_TEST(unused.front() == "m.b");
  write_file_atomic(list, "id,explanation,tier\nm.a *,bad,\n");
  BOOST_CHECK_THROW(study::Errata::load(list, "quick"), InputError);
}

// Notes quote the run's values: a documented disagreement "ours is {{fb}} N"
// with the run's value fb = 74.2 becomes "ours is 74.2 N"; a note quoting a
// key the run does not hold ({{gone}}) throws InputError naming the check.
BOOST_AUTO_TEST_CASE(notes_quote_the_runs_values) {
  const auto dir = std::filesystem::temp_directory_path() / "drawbend_checks_notes";
  std::filesystem::create_directories(dir);
  const std::string dis = (dir / "disagreements.csv").string();
  write_file_atomic(dis, "id,explanation\nn.fb,ours is {{fb}} N\nn.gone,quotes {{gone}}\n");
  const std::map<std::string, std::string> values{{"fb", "74.2"}};
  auto lookup = [&](const std::string& k) -> const std::string* {
    const auto it = values.find(k);
    return it == values.end() ? nullptr : &it->second;
  };
  study::Checks c("test", {}, study::Errata::load(dis));
  c.agree(study::Kind::simulated, "n.fb", "q", 1.0, 2.0, 0.1, "N", "r");
  c.fill_notes(lookup);
  BOOST_TEST(c.all().front().note == "ours is 74.2 N");
  c.agree(study::Kind::simulated, "n.gone", "q", 1.0, 2.0, 0.1, "N", "r");
  BOOST_CHECK_THROW(c.fill_notes(lookup), InputError);
  std::filesystem::remove_all(dir);
}

// The loop's answer does not depend on the order of the file's rows
// (loop/measured.hpp, canonical_row_order: the rows are taken by test_id in
// natural order, then time, sliding distance and back tension).  Before it,
// the folds (a test's index within its block), the permutation draws, the
// cells and the levels followed the file's order, and a shuffled copy of a
// development set ended differently (heldout_record.md, 2026-12-05 second
// session: generator 1 54400000+i 40/40 as written, 37/40 shuffled).
// Expected answers, on wild development set 65400018 (spent: h50-bundle's
// check; `fixture` one level apart on mu, noise 8 N) written as a lab file:
//  - the same text with its data rows reversed, and with them in a fixed
//    interleaved order, parse to the same rows in the same order (every
//    cell; each row keeps its own file line);
//  - the loop (defaults, one thread) on the three gives the same steps
//    (variable, form, every parameter) and the same held-out RMS, to the
//    last bit: the same arithmetic in the same order.
#define BOOST_TEST_MODULE loop_row_order
#include <boost/test/unit_test.hpp>

#include <sstream>
#include <string>
#include <vector>

#include "lab_file.hpp"
#include "loop/loop.hpp"
#include "loop/measured.hpp"
#include "loop/wild_synth.hpp"

using namespace drawbend::loop;

namespace {

// The file's text with its data rows (after the header) in the order `order` gives.
std::string reordered(const std::string& text, const std::vector<size_t>& order) {
  std::istringstream in(text);
  std::string line, head;
  std::vector<std::string> rows;
  while (std::getline(in, line)) {
    if (!line.empty() && line[0] == '#') head += line + "\n";
    else if (head.find("test_id,") == std::string::npos && line.rfind("test_id,", 0) == 0) head += line + "\n";
    else if (!line.empty()) rows.push_back(line);
  }
  std::string out = head;
  for (size_t k : order) out += rows[k % rows.size()] + "\n";
  return out;
}

}  // namespace

BOOST_AUTO_TEST_CASE(same_answer_whatever_the_row_order) {
  BlindTruth t;
  const std::string text = drawbend::test::lab_text(synthesize_wild({"level", 8.0, 65400018}, t), "row_order.csv");
  std::istringstream in(text);
  std::string line;
  size_t n = 0;  // data rows (after the comments and the header)
  bool header = false;
  while (std::getline(in, line))
    if (!line.empty() && line[0] != '#') (header ? ++n : (header = true, 0));
  BOOST_REQUIRE(n > 100);
  std::vector<size_t> reverse, interleave;
  for (size_t k = 0; k < n; ++k) reverse.push_back(n - 1 - k);
  for (size_t k = 0; k < n; ++k) interleave.push_back((k * 37) % n);  // 37 is prime to n unless n is a multiple of 37
  if (n % 37 == 0) interleave = reverse;
  const std::vector<Dataset> sets = {parse_measured(text, "a.csv"), parse_measured(reordered(text, reverse), "b.csv"),
                                     parse_measured(reordered(text, interleave), "c.csv")};
  for (size_t s = 1; s < sets.size(); ++s) {
    BOOST_REQUIRE(sets[s].rows.size() == sets[0].rows.size());
    for (size_t i = 0; i < sets[0].rows.size(); ++i) {
      const Sample &a = sets[0].rows[i], &b = sets[s].rows[i];
      BOOST_TEST(a.test_id == b.test_id);
      BOOST_TEST(a.back_tension_N == b.back_tension_N);
      BOOST_TEST(a.outlet_force_N == b.outlet_force_N);
      BOOST_TEST(a.time_s == b.time_s);
      BOOST_TEST(a.extra == b.extra);
    }
  }
  std::vector<LoopResult> r;
  for (const auto& d : sets) r.push_back(run_loop(make_design(d, drawbend::test::stand_in_maps(d)), LoopOptions{}));
  BOOST_REQUIRE(!r[0].steps.empty());
  for (size_t s = 1; s < r.size(); ++s) {
    BOOST_TEST(r[s].cv.back().rms == r[0].cv.back().rms);
    BOOST_REQUIRE(r[s].steps.size() == r[0].steps.size());
    for (size_t k = 0; k < r[0].steps.size(); ++k) {
      BOOST_TEST(r[s].steps[k].variable == r[0].steps[k].variable);
      BOOST_TEST(r[s].steps[k].effect == r[0].steps[k].effect);
      BOOST_TEST(r[s].steps[k].p_permutation == r[0].steps[k].p_permutation);
      BOOST_TEST(r[s].steps[k].params.size() == r[0].steps[k].params.size());
      for (size_t j = 0; j < std::min(r[s].steps[k].params.size(), r[0].steps[k].params.size()); ++j)
        BOOST_TEST(r[s].steps[k].params[j].value == r[0].steps[k].params[j].value);
    }
  }
}

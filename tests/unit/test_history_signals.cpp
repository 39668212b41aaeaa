// The history signals of a run (core/run_output.hpp), one place for the
// column names of history.csv:
//  - every Signal has its own name (no two enumerators share a column);
//  - run_history_columns() is time_s, step, dt_s, the six energies and
//    balance_error, in that order (the order io/run_case writes its rows in);
//  - the draw-bend builder's deck (sim/drawbend_case), parsed as a deck,
//    records exactly the draw-bend signals of the enum (outlet_force ..
//    back_tension_full, in enum order) followed by the mid-wrap sections
//    eps_mid_0, eps_mid_1, ... (mid_wrap_strain), so what the builder writes
//    is what its readers ask for.
#define BOOST_TEST_MODULE history_signals
#include <boost/test/unit_test.hpp>
#include <set>
#include <string>
#include <vector>

#include "core/run_output.hpp"
#include "io/deck.hpp"
#include "sim/drawbend_case.hpp"

using drawbend::run_output::Signal;
using drawbend::run_output::signal_name;

namespace {
constexpr int kFirst = static_cast<int>(Signal::time), kLast = static_cast<int>(Signal::back_tension_full);
}

BOOST_AUTO_TEST_CASE(names_are_distinct) {
  std::set<std::string> seen;
  for (int k = kFirst; k <= kLast; ++k) {
    const std::string n = signal_name(static_cast<Signal>(k));
    BOOST_TEST(n != "?");
    BOOST_TEST(seen.insert(n).second, "duplicate column " << n);
  }
}

BOOST_AUTO_TEST_CASE(run_columns_in_file_order) {
  const std::vector<std::string> want{"time_s",      "step",        "dt_s",           "kinetic_mJ",
                                      "internal_mJ", "hourglass_mJ", "external_work_mJ", "friction_mJ",
                                      "damping_mJ",  "balance_error"};
  BOOST_TEST(drawbend::run_output::run_history_columns() == want, boost::test_tools::per_element());
}

BOOST_AUTO_TEST_CASE(drawbend_deck_records_the_enum_signals) {
  drawbend::sim::DrawBendSpec s;  // the builder's defaults, on the thesis's RD curve
  s.hardening = std::string(DRAWBEND_DATA_DIR) + "/materials/aa5754_o_rd.csv";
  const auto deck = drawbend::io::parse_deck(drawbend::sim::deck_text(s), "drawbend.toml");
  const auto& h = deck.output.history;
  std::vector<std::string> got, want;
  for (const auto& sig : h) got.push_back(sig.name);
  for (int k = static_cast<int>(Signal::outlet_force); k <= kLast; ++k) want.push_back(signal_name(static_cast<Signal>(k)));
  const std::size_t named = want.size();
  BOOST_REQUIRE(got.size() > named);  // at least one mid-wrap section
  for (std::size_t k = 0; k + named < got.size(); ++k) want.push_back(drawbend::run_output::mid_wrap_strain(static_cast<int>(k)));
  BOOST_TEST(got == want, boost::test_tools::per_element());
}

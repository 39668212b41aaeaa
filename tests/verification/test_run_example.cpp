// `drawbend run` on the shipped example deck, through the real driver code
// (io::read_deck + io::run_case), with a short end time.
// Closed-form answers:
//  - the block slides at mu = 0.1: the last history row has friction/normal =
//    0.1 within 1 %;
//  - the energy balance error stays below 1e-3;
//  - every .vtu is well-formed XML (its appended binary block aside) with NumberOfPoints = 125 and
//    NumberOfCells = 64 (a 4 x 4 x 4 block), and the .pvd lists each snapshot.
#define BOOST_TEST_MODULE run_example
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "core/csv.hpp"
#include "io/deck.hpp"
#include "io/run_case.hpp"
#include "xml_check.hpp"

using namespace drawbend;

BOOST_AUTO_TEST_CASE(block_slide_deck) {
  io::Deck deck = io::read_deck(std::string(DRAWBEND_DATA_DIR) + "/cases/block_slide.toml");
  const auto out = std::filesystem::temp_directory_path() / "drawbend_run_example";
  std::filesystem::remove_all(out);
  std::ostringstream log;
  io::RunOptions ro;
  ro.out_dir = out.string();
  ro.quiet = true;
  const io::RunSummary r = io::run_case(deck, ro, log);
  BOOST_TEST_MESSAGE(log.str());
  BOOST_TEST(r.energy_balance_error < 1e-3);
  const CsvTable h = read_csv((out / "history.csv").string());
  const auto& last = h.rows.back();
  BOOST_TEST(std::abs(h.number(last, "friction_N") / -h.number(last, "normal_N") - 0.1) < 0.001);
  const std::string pvd = read_file((out / "fields.pvd").string());
  int files = 0;
  for (const auto& e : std::filesystem::directory_iterator(out))
    if (e.path().extension() == ".vtu") {
      ++files;
      // The XML around the appended binary block (io/vtu.hpp), which is not text.
      std::string text = read_file(e.path().string());
      const std::size_t data = text.find("<AppendedData"), end = text.rfind("</AppendedData>");
      if (data != std::string::npos && end != std::string::npos) {
        const std::size_t from = text.find('_', data) + 1;
        text.erase(from, end - from);
      }
      const auto elems = xmlcheck::parse_xml(text);
      bool piece = false;
      for (const auto& el : elems)
        if (el.name == "Piece") {
          piece = true;
          BOOST_TEST(el.attrs.at("NumberOfPoints") == "125");
          BOOST_TEST(el.attrs.at("NumberOfCells") == "64");
        }
      BOOST_TEST(piece);
      BOOST_TEST(pvd.find(e.path().filename().string()) != std::string::npos);
    }
  BOOST_TEST(files >= 3);
}

// The wrapped-strip mesh of a deck (no run).
// Closed-form answers: drawbend_12p7_wrapped.toml has 22/0.5 = 44 inlet, round(
// (6.35 + 0.52) pi/2 / 0.5) = 22 wrapped and 6/0.5 = 12 outlet elements along,
// 2 across, 4 through: 78 x 2 x 4 = 624 elements; every node of the contact
// face (zmin) on the wrapped part lies on the pin, at radius 6.35 mm.
BOOST_AUTO_TEST_CASE(wrapped_strip_deck_mesh) {
  io::Deck deck = io::read_deck(std::string(DRAWBEND_DATA_DIR) + "/cases/drawbend_12p7_wrapped.toml");
  const auto& m = deck.model.mesh;
  BOOST_TEST(m.num_elements() == 624);
  int on_pin = 0;
  for (int i : m.node_set("zmin"))
    if (m.x[i] >= 0 && m.z[i] >= 0) {
      BOOST_TEST(std::abs(std::hypot(m.x[i], m.z[i]) - 6.35) < 1e-9);
      ++on_pin;
    }
  BOOST_TEST(on_pin > 0);
}

// A case as a typed value (io/case_spec.hpp): one reader, one writer.
// Expected:
//  - every tracked deck (data/cases, tests/verification/decks,
//    tests/robustness/decks, tests/user/decks) that toml++ parses either reads
//    into a spec, writes, and reads back to the same spec with the written text
//    stable (writing the read-back spec gives the same bytes), or is a
//    robustness deck that is wrong on purpose (its material, or a section of
//    the wrong shape);
//  - a deck written from a spec reads through the deck reader (io::parse_deck)
//    to the same model numbers as the deck it came from: the data/cases decks'
//    time step, steps, tools and mesh size (the writer loses nothing the
//    solver reads);
//  - the cup builder's specs (sim::cup_case) round-trip too, and the builder
//    sets typed fields: --threads is numerics.threads, the punch radius moves
//    the punch's plane, torus and cylinder, "none" removes every friction;
//  - layout is not meaning: a tool speed read inline compares equal to the
//    same speed written as a section.
#define BOOST_TEST_MODULE case_spec
#include <boost/test/unit_test.hpp>

#include <filesystem>
#include <string>

#include "core/csv.hpp"
#include "core/toml_read.hpp"
#include "io/case_spec.hpp"
#include "io/deck.hpp"
#include "sim/cup_case.hpp"

using namespace drawbend;
namespace fs = std::filesystem;

namespace {
const std::string kRepo = fs::path(DRAWBEND_TEST_DIR).parent_path().string();

void round_trip(const io::CaseSpec& spec, const std::string& what) {
  const std::string text = io::to_toml(spec);
  const io::CaseSpec back = io::from_toml(parse_toml(text, what + " (written)"), what);
  BOOST_TEST((back == spec), what << " reads back to another spec:\n" << text);
  BOOST_TEST(io::to_toml(back) == text, what);
}
}  // namespace

BOOST_AUTO_TEST_CASE(every_tracked_deck_round_trips) {
  int read = 0, refused = 0;
  for (const char* dir : {"data/cases", "tests/verification/decks", "tests/robustness/decks", "tests/user/decks"}) {
    for (const auto& e : fs::recursive_directory_iterator(kRepo + "/" + dir)) {
      if (e.path().extension() != ".toml") continue;
      toml::table root;
      try {
        root = parse_toml_file(e.path().string());
      } catch (const InputError&) {
        continue;  // a robustness deck with a syntax error on purpose
      }
      io::CaseSpec spec;
      try {
        spec = io::from_toml(root, e.path().string());
      } catch (const InputError& err) {
        BOOST_TEST(std::string(dir) == "tests/robustness/decks", err.what());
        ++refused;
        continue;
      }
      round_trip(spec, e.path().string());
      ++read;
    }
  }
  BOOST_TEST_MESSAGE(read << " decks round-tripped, " << refused << " refused");
  BOOST_TEST(read >= 30);
}

BOOST_AUTO_TEST_CASE(written_decks_read_to_the_same_model) {
  for (const auto& e : fs::directory_iterator(kRepo + "/data/cases")) {
    if (e.path().extension() != ".toml") continue;
    const std::string path = e.path().string();
    const io::Deck a = io::read_deck(path);
    const io::Deck b = io::parse_deck(io::to_toml(io::read_case(path)), path);
    const fe::Model &ma = a.model, &mb = b.model;
    BOOST_TEST(ma.target_dt == mb.target_dt, path);
    BOOST_TEST(ma.dt_safety == mb.dt_safety, path);
    BOOST_TEST(ma.mesh.num_elements() == mb.mesh.num_elements(), path);
    BOOST_TEST(ma.mesh.x == mb.mesh.x, path);
    BOOST_TEST_REQUIRE(ma.steps.size() == mb.steps.size(), path);
    for (std::size_t k = 0; k < ma.steps.size(); ++k) {
      BOOST_TEST(ma.steps[k].duration == mb.steps[k].duration, path);
      BOOST_TEST(ma.steps[k].damping == mb.steps[k].damping, path);
    }
    BOOST_TEST_REQUIRE(ma.tools.size() == mb.tools.size(), path);
    for (std::size_t k = 0; k < ma.tools.size(); ++k) {
      BOOST_TEST(ma.tools[k].name == mb.tools[k].name, path);
      BOOST_TEST(ma.tools[k].mass == mb.tools[k].mass, path);
      BOOST_TEST(ma.tools[k].surfaces.size() == mb.tools[k].surfaces.size(), path);
    }
  }
}

BOOST_AUTO_TEST_CASE(cup_builder_sets_typed_fields) {
  sim::CupSpec s;
  s.deck = std::string(DRAWBEND_DATA_DIR) + "/cases/cup_draw.toml";
  s.threads = 3;
  s.punch_radius = 3;
  io::CaseSpec c = sim::cup_case(s);
  round_trip(c, "cup_case");
  BOOST_TEST(c.numerics->threads.value_or(0) == 3);
  io::ToolSpec& punch = c.tool("punch", "test");
  BOOST_TEST(punch.surface("torus")->tube_radius.value_or(0) == 3.0);
  BOOST_TEST(punch.surface("plane")->r_max.value_or(0) == 24.0 - 3.0);  // the wall radius (24 mm) is kept
  BOOST_TEST(punch.surface("cylinder")->z_max.value_or(0) == -3.0);
  BOOST_TEST(c.reduce->kind == "cup_draw");
  s.friction = "none";
  s.material = "{ type = \"hill48\", hill48 = { r0 = 0.7, r45 = 0.7, r90 = 0.9 } }";
  c = sim::cup_case(s);
  round_trip(c, "cup_case none");
  for (const auto& p : c.contacts) BOOST_TEST(!p.friction.has_value());
  BOOST_TEST((c.material->type == io::MaterialType::hill48));
}

BOOST_AUTO_TEST_CASE(layout_is_not_meaning) {
  const std::string deck = "[[tool]]\nname = \"p\"\nspeed = { t = [0.0, 1.0], v = [0.0, 2.0] }\n";
  io::CaseSpec a = io::from_toml(parse_toml(deck, "inline"), "inline");
  io::CaseSpec b = a;
  b.tools[0].speed->written_inline = false;
  BOOST_TEST((a == b));
  BOOST_TEST(io::to_toml(a).find("speed = {") != std::string::npos, io::to_toml(a));
  BOOST_TEST(io::to_toml(b).find("[tool.speed]") != std::string::npos, io::to_toml(b));
}

// The writer prints every float in its shortest exact form (toml++ alone prints
// 17 digits); strings, keys and integers keep their text, and the values read
// back to the same doubles, integers still integers.
BOOST_AUTO_TEST_CASE(floats_are_written_short_and_exact) {
  io::CaseSpec c;
  io::NumericsSpec& n = c.numerics.emplace();
  n.dt_safety = 0.8;
  n.threads = 5;
  n.rest.insert("mass_scaling", 1e4);
  n.rest.insert("small", 2.7e-9);
  n.rest.insert("third", 1.0 / 3.0);
  n.rest.insert("list", toml::array{-1.0, 0.0, 0.1 + 0.2});
  c.rest.insert("case", toml::table{{"name", "x 0.80000000000000004"}, {"note", "a\"b 0.10000000000000001 'c'"},
                                    {"r45", 0.73}});
  const std::string text = io::to_toml(c);
  for (const char* line : {"dt_safety = 0.8\n", "threads = 5\n", "mass_scaling = 10000.0\n", "small = 2.7e-09\n",
                           "third = 0.3333333333333333\n", "list = [ -1.0, 0.0, 0.30000000000000004 ]\n",
                           "name = 'x 0.80000000000000004'\n", "r45 = 0.73\n"})
    BOOST_TEST(text.find(line) != std::string::npos, line << " not in:\n" << text);
  BOOST_TEST(text.find("0.10000000000000001") != std::string::npos, "a string's digits were rewritten:\n" << text);
  BOOST_TEST((io::from_toml(parse_toml(text, "short"), "short") == c), text);
}

// A friction is one line of inline TOML in a fixed order whatever order its
// keys were typed in (the law, its input file, then its numbers by name), so
// the same law gives the same description and the same reuse key; it reads
// back to the same spec.
BOOST_AUTO_TEST_CASE(friction_text_has_one_order) {
  BOOST_TEST(io::friction_text(io::coulomb_friction(0.1)) == "{ law = \"coulomb\", mu = 0.1 }");
  BOOST_TEST(io::friction_text(io::stribeck_friction("t.csv", 100)) ==
             "{ law = \"stribeck\", table = \"t.csv\", interval = 100 }");
  const std::string typed = "{ v_max = 101.6, interval = 50, p_min = 0.0, nodes = \"n.csv\", law = \"surface\" }";
  const io::FrictionSpec f = io::read_friction(*parse_toml("f = " + typed, "typed")["f"].as_table());
  const std::string text = io::friction_text(f);
  BOOST_TEST(text == "{ law = \"surface\", nodes = \"n.csv\", interval = 50, p_min = 0.0, v_max = 101.6 }");
  BOOST_TEST((io::read_friction(*parse_toml("f = " + text, "text")["f"].as_table()) == f), text);
}

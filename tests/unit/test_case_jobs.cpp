// Blocks, strip draws and cups as file-level jobs (issue 56, item 1): the run
// folder holds what the chapter needs bit for bit.
// Expected answers (no tolerance anywhere: every comparison is of bits):
//  - The in-memory path (sim::run_block, run_strip_draw) gives exactly the
//    doubles of the in-memory code of commit 8a31e17, before the file-level
//    path existed (tests/unit/case_jobs_gold.csv, hex floats written by that
//    code on these small specs).
//  - The file-level job (deck.toml -> io::run_case -> reduction.csv -> the
//    builder's reader) gives exactly the in-memory doubles: the run's
//    reduction sums the same cycles in the same order, and reduction.csv
//    holds every number as the shortest text that reads back as the same double.
//  - A short cup as a job gives exactly what sim::draw_cup (in memory,
//    unchanged) gives: every scalar, curve point and element field value, and
//    a byte-identical end-of-stroke .vtu (the run's last field snapshot).
//  - A second job on the byte-identical deck reuses the folder (summary.csv
//    untouched), and gives the same bits.
//  - Bad reductions in a deck are input errors naming the key.
#define BOOST_TEST_MODULE case_jobs
#include <boost/test/unit_test.hpp>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>

#include "core/csv.hpp"
#include "io/case_reduction.hpp"
#include "io/case_spec.hpp"
#include "io/deck.hpp"
#include "sim/block_case.hpp"
#include "sim/cup_case.hpp"
#include "sim/deck_job.hpp"
#include "sim/strip_draw_case.hpp"

using namespace drawbend;
namespace fs = std::filesystem;

namespace {

const std::string kData = DRAWBEND_DATA_DIR;

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

std::map<std::string, double> gold(const std::string& which) {
  const CsvTable t = read_csv(std::string(DRAWBEND_TEST_DIR) + "/unit/case_jobs_gold.csv");
  std::map<std::string, double> g;
  for (const auto& row : t.rows)
    if (t.text(row, "case") == which) g[t.text(row, "quantity")] = std::strtod(t.text(row, "value").c_str(), nullptr);
  return g;
}

sim::BlockSpec small_block() {
  sim::BlockSpec b = sim::default_block_spec(kData);
  b.elements = 2;
  b.pressure = 40;
  b.speed = 70;
  b.direction_deg = 30;
  return b;
}

sim::StripDrawSpec small_strip() {
  sim::StripDrawSpec s = sim::default_strip_draw_spec(kData);
  s.nx = 4;
  s.ny = 2;
  s.nz = 2;
  s.slide = 0.2;
  return s;
}

std::map<std::string, double> block_values(const sim::BlockResult& r) {
  return {{"mu_x", r.mu_x}, {"mu_y", r.mu_y}, {"p_min", r.p_min}, {"p_max", r.p_max}, {"v_mean", r.v_mean},
          {"cycles", static_cast<double>(r.cycles)}};
}

std::map<std::string, double> strip_values(const sim::StripDrawResult& t) {
  // The series folded as the gold's writer folded them (in order; any change of a value or of the order shows).
  double h = 0, g = 0;
  for (const auto& [tt, v] : t.trace) h = h * 1.0000001 + tt + 3 * v;
  for (const auto& [xy, v] : t.die_map) g = g * 1.0000001 + xy.first + 7 * xy.second + v;
  return {{"mu", t.mu}, {"p_mean", t.p_mean}, {"p_spread", t.p_spread}, {"v_mean", t.v_mean}, {"v_std", t.v_std},
          {"v_min", t.v_min}, {"v_max", t.v_max}, {"ramp_v_max", t.ramp_v_max},
          {"cycles", static_cast<double>(t.cycles)}, {"trace_n", static_cast<double>(t.trace.size())},
          {"trace_mix", h}, {"map_n", static_cast<double>(t.die_map.size())}, {"map_mix", g}};
}

void check_same(const std::map<std::string, double>& want, const std::map<std::string, double>& got,
                const std::string& what) {
  BOOST_TEST(want.size() == got.size(), what << ": " << want.size() << " values against " << got.size());
  for (const auto& [q, v] : want) {
    BOOST_TEST_REQUIRE(got.count(q) == 1u, what << ": no " << q);
    BOOST_TEST(same_bits(v, got.at(q)), what << ": " << q << " " << std::hexfloat << v << " against " << got.at(q));
  }
}

std::string tmp(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("drawbend_case_jobs_" + std::to_string(::getpid())) / name;
  fs::remove_all(d);
  return d.string();
}

}  // namespace

BOOST_AUTO_TEST_CASE(block_in_memory_and_as_a_job_match_the_gold_bit_for_bit) {
  const sim::BlockSpec b = small_block();
  const auto mem = block_values(sim::run_block(b));
  check_same(gold("block"), mem, "block in memory vs gold of 8a31e17");
  const std::string dir = tmp("block");
  check_same(mem, block_values(sim::run_block_job(b, dir)), "block job vs in memory");
  BOOST_TEST(fs::exists(fs::path(dir) / "deck.toml"));
  BOOST_TEST(fs::exists(fs::path(dir) / io::kReductionFile));
  // The byte-identical deck again: reused (summary.csv not rewritten), same bits.
  const auto stamp = fs::last_write_time(fs::path(dir) / "summary.csv");
  BOOST_TEST(!sim::run_deck_job(b.name, sim::block_deck_text(b), dir, true));
  BOOST_TEST((fs::last_write_time(fs::path(dir) / "summary.csv") == stamp));
  check_same(mem, block_values(sim::read_block_run(dir)), "block reused vs in memory");
}

BOOST_AUTO_TEST_CASE(strip_draw_in_memory_and_as_a_job_match_the_gold_bit_for_bit) {
  const sim::StripDrawSpec s = small_strip();
  const sim::StripDrawResult mem = sim::run_strip_draw(s);
  check_same(gold("strip"), strip_values(mem), "strip draw in memory vs gold of 8a31e17");
  const std::string dir = tmp("strip");
  const sim::StripDrawResult job = sim::run_strip_draw_job(s, dir);
  check_same(strip_values(mem), strip_values(job), "strip draw job vs in memory");
  // Every point of the series, not only their fold.
  BOOST_TEST_REQUIRE(job.trace.size() == mem.trace.size());
  for (std::size_t k = 0; k < mem.trace.size(); ++k)
    BOOST_TEST((same_bits(job.trace[k].first, mem.trace[k].first) && same_bits(job.trace[k].second, mem.trace[k].second)));
  BOOST_TEST((job.die_map == mem.die_map));
}

BOOST_AUTO_TEST_CASE(cup_as_a_job_matches_draw_cup_bit_for_bit) {
  // A short stroke in few cycles of the Chapter 6 cup (draw_cup, in memory, is today's code).
  sim::CupSpec c;
  c.deck = kData + "/cases/cup_draw.toml";
  c.stroke = 3;
  c.cycles = 1500;
  const std::string dir = tmp("cup");
  fs::create_directories(fs::path(dir).parent_path());
  c.vtu = dir + "_memory.vtu";
  const sim::CupResult mem = sim::draw_cup(c);
  c.vtu = dir + "_job.vtu";
  const sim::CupResult job = sim::draw_cup_job(c, dir);
  const std::map<std::string, double> a{{"die_force", mem.die_force}, {"size_rd", mem.size_rd}, {"size_td", mem.size_td},
      {"max_strain", mem.max_strain}, {"max_strain_r", mem.max_strain_r}, {"max_strain_z", mem.max_strain_z},
      {"max_strain_angle", mem.max_strain_angle}, {"band_rd", mem.band_rd}, {"band_td", mem.band_td},
      {"die_lift", mem.die_lift}, {"kinetic_ratio", mem.kinetic_ratio}, {"hourglass_ratio", mem.hourglass_ratio},
      {"added_mass_ratio", mem.added_mass_ratio}, {"cycles", double(mem.cycles)}, {"elements", double(mem.elements)},
      {"layers", double(mem.layers)}};
  const std::map<std::string, double> b{{"die_force", job.die_force}, {"size_rd", job.size_rd}, {"size_td", job.size_td},
      {"max_strain", job.max_strain}, {"max_strain_r", job.max_strain_r}, {"max_strain_z", job.max_strain_z},
      {"max_strain_angle", job.max_strain_angle}, {"band_rd", job.band_rd}, {"band_td", job.band_td},
      {"die_lift", job.die_lift}, {"kinetic_ratio", job.kinetic_ratio}, {"hourglass_ratio", job.hourglass_ratio},
      {"added_mass_ratio", job.added_mass_ratio}, {"cycles", double(job.cycles)}, {"elements", double(job.elements)},
      {"layers", double(job.layers)}};
  check_same(a, b, "cup job vs draw_cup");
  BOOST_TEST(mem.curve.size() > 10u);
  BOOST_TEST_REQUIRE(job.curve.size() == mem.curve.size());
  for (std::size_t k = 0; k < mem.curve.size(); ++k)
    BOOST_TEST((same_bits(job.curve[k].first, mem.curve[k].first) && same_bits(job.curve[k].second, mem.curve[k].second)),
               "curve point " << k);
  BOOST_TEST_REQUIRE(job.field.size() == mem.field.size());
  bool fields_same = true;
  for (std::size_t k = 0; k < mem.field.size(); ++k)
    for (int q = 0; q < 5; ++q) fields_same = fields_same && same_bits(job.field[k][q], mem.field[k][q]);
  BOOST_TEST(fields_same);
  BOOST_TEST((read_file(dir + "_memory.vtu") == read_file(dir + "_job.vtu")), "end-of-stroke fields");
}

BOOST_AUTO_TEST_CASE(a_chapter_batch_runs_each_name_once_and_refuses_two_decks_under_one_name) {
  sim::BlockSpec a = small_block(), b = small_block();
  a.name = b.name = "same";
  const std::string runs = tmp("batch");
  const auto r = sim::run_blocks({a, b}, runs, false);  // one folder, one run, the result twice
  BOOST_TEST(same_bits(r[0].mu_x, r[1].mu_x));
  b.pressure = 10;
  try {
    sim::run_blocks({a, b}, runs, false);
    BOOST_FAIL("two decks under one name must be refused");
  } catch (const InputError& e) {
    BOOST_TEST(std::string(e.what()).find("two different cases named 'same'") != std::string::npos, e.what());
  }
  fs::remove_all(fs::path(runs).parent_path());
}

BOOST_AUTO_TEST_CASE(bad_reductions_are_input_errors_naming_the_key) {
  // The block's deck with one key of [output.reduce] set to `value`.
  auto message = [&](const char* key, auto value) {
    toml::table t = io::to_toml_table(sim::block_case(small_block()));
    toml::table* reduce = t["output"]["reduce"].as_table();
    BOOST_TEST_REQUIRE(reduce);
    reduce->insert_or_assign(key, value);
    std::ostringstream text;
    text << t;
    try {
      io::parse_deck(text.str(), "bad.toml");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  BOOST_TEST(message("kind", "blok").find("output.reduce.kind") != std::string::npos);
  BOOST_TEST(message("tool", "roof").find("output.reduce.tool") != std::string::npos);
  BOOST_TEST(message("step", "glide").find("output.reduce.step") != std::string::npos);
  BOOST_TEST(message("speed", 3).find("output.reduce") != std::string::npos);
}

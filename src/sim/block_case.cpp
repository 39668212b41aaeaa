// The block-sliding builder: deck text, run, reduction.  See block_case.hpp.
#include "sim/block_case.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "fe/solver.hpp"
#include "io/case_reduction.hpp"
#include "sim/case_pool.hpp"
#include "sim/deck_job.hpp"
#include "sim/deck_writer.hpp"
#include "sim/material_choice.hpp"

namespace drawbend::sim {

BlockSpec default_block_spec(const std::string& data_dir) {
  BlockSpec s;
  s.hardening = data_dir + "/materials/aa5754_o_rd.csv";
  s.surface_nodes = data_dir + "/thesis/table_6_1.csv";
  return s;
}

namespace {

void check_spec(const BlockSpec& s) {
  const std::string w = "block spec: ";
  require_positive(s.size, w + "size [mm]");
  require_positive(s.pressure, w + "pressure [MPa]");
  require_positive(s.speed, w + "speed [mm/s]");
  require_positive(s.penalty, w + "penalty");
  require_positive(s.press_time, w + "press_time [s]");
  require_positive(s.press_ramp, w + "press_ramp [s]");
  require_positive(s.slide_time, w + "slide_time [s]");
  require_positive(s.speed_ramp, w + "speed_ramp [s]");
  if (!std::isfinite(s.direction_deg)) throw InputError(w + "direction [deg] must be a finite number");
  if (!(s.mass_scaling >= 1) || !std::isfinite(s.mass_scaling))
    throw InputError(w + "mass_scaling must be a number >= 1, found " + fmt(s.mass_scaling));
  if (!(s.press_damping >= 0)) throw InputError(w + "press_damping [1/s] must be >= 0, found " + fmt(s.press_damping));
  if (s.elements < 1) throw InputError(w + "elements must be >= 1, found " + std::to_string(s.elements));
  if (s.interval < 1) throw InputError(w + "interval [cycles] must be >= 1, found " + std::to_string(s.interval));
  if (s.press_ramp >= s.press_time) throw InputError(w + "press_ramp must be shorter than press_time");
  if (s.speed_ramp >= s.slide_time) throw InputError(w + "speed_ramp must be shorter than slide_time");
  if (s.hardening.empty()) throw InputError(w + "no hardening curve");
  if (s.friction.empty() && s.surface_nodes.empty()) throw InputError(w + "no friction law and no surface nodes");
}

}  // namespace

std::string block_deck_text(const BlockSpec& s) {
  check_spec(s);
  const double FN = s.pressure * s.size * s.size, psi = s.direction_deg * M_PI / 180.0;
  const std::string L = toml_float(s.size), n = std::to_string(s.elements);
  const std::string friction = s.friction.empty() ? "{ law = \"surface\", nodes = \"" + s.surface_nodes +
                                                        "\", interval = " + std::to_string(s.interval) + " }"
                                                  : s.friction;
  std::ostringstream o;
  o << "# Block-sliding case written by drawbend's builder (src/sim/block_case.cpp; Sec. 6.5, Fig. 6.7):\n"
    << "# a " << fmt(s.size) << " mm cube pressed on a rigid floor at " << fmt(s.pressure) << " MPa ("
    << fmt(FN) << " N) and slid at " << fmt(s.speed) << " mm/s, " << fmt(s.direction_deg) << " deg from RD (x).\n"
    << "# Friction = F_t / F_N on the floor over the last third of the slide.\n"
    << "# Units: mm, N, MPa, s, t/mm^3.  Run with: drawbend run deck.toml --out DIR\n"
    << "[case]\nname = \"" << s.name << "\"\ndescription = \"block " << fmt(s.size) << " mm, " << fmt(s.pressure)
    << " MPa, slid at " << fmt(s.speed) << " mm/s, " << fmt(s.direction_deg) << " deg from RD\"\n\n"
    << "[mesh]\n";
  for (const char* axis : {"x", "y", "z"}) o << axis << " = { from = 0.0, to = " << L << ", n = " << n << " }\n";
  o << "\n" << material_section("", s.hardening) << "\n"
    << "[sheet]\nrolling_direction = [1.0, 0.0, 0.0]  # RD: friction texture (and material axes) start from it\n\n"
    << "[numerics]\n" << numerics_threads_line(s.threads) << "dt_safety = 0.8\nmass_scaling = " << toml_float(s.mass_scaling)
    << "\n\n"
    << "[[tool]]\nname = \"floor\"\ndrive = \"fixed\"\n[[tool.surface]]\nkind = \"plane\"\n"
    << "origin = [0.0, 0.0, 0.0]\nnormal = [0.0, 0.0, 1.0]\n\n"
    << "[[contact]]\nfaces = \"zmin\"\ntool = \"floor\"\npenalty = " << toml_float(s.penalty)
    << "\ntexture = \"fixed\"\nfriction = " << friction << "\n\n"
    << "[[step]]\nname = \"press\"\nduration = " << toml_float(s.press_time) << "\ndamping = "
    << toml_float(s.press_damping) << "\n"
    << "force = [ { set = \"zmax\", direction = [0.0, 0.0, -1.0], magnitude = " << toml_ramp(s.press_ramp, FN) << " } ]\n\n"
    << "[[step]]\nname = \"slide\"\nduration = " << toml_float(s.slide_time) << "\n"
    << "force = [ { set = \"zmax\", direction = [0.0, 0.0, -1.0], magnitude = " << toml_float(FN) << " } ]\n"
    << "velocity = [\n"
    << "  { set = \"all\", direction = [1.0, 0.0, 0.0], speed = " << toml_ramp(s.speed_ramp, s.speed * std::cos(psi))
    << " },\n"
    << "  { set = \"all\", direction = [0.0, 1.0, 0.0], speed = " << toml_ramp(s.speed_ramp, s.speed * std::sin(psi))
    << " },\n]\n\n"
    << "[output]\nfields_per_step = 1\nhistory = [\n"
    << "  { name = \"friction_x_N\", kind = \"tool_force\", target = \"floor\", component = 0 },\n"
    << "  { name = \"friction_y_N\", kind = \"tool_force\", target = \"floor\", component = 1 },\n"
    << "  { name = \"normal_N\", kind = \"tool_force\", target = \"floor\", component = 2 },\n]\n"
    << "# mu_x, mu_y over the last third of the slide, kept every cycle (io/case_reduction.hpp): reduction.csv\n"
    << "reduce = { kind = \"block_slide\", tool = \"floor\", step = \"slide\" }\n";
  return o.str();
}

io::Deck block_deck(const BlockSpec& s) { return io::parse_deck(block_deck_text(s), s.name + ".toml"); }

namespace {

BlockResult from_rows(const std::vector<io::ReducedValue>& rows, const std::string& where) {
  BlockResult r;
  r.mu_x = io::reduced(rows, "mu_x", where);
  r.mu_y = io::reduced(rows, "mu_y", where);
  r.p_min = io::reduced(rows, "p_min", where);
  r.p_max = io::reduced(rows, "p_max", where);
  r.v_mean = io::reduced(rows, "v_mean", where);
  r.cycles = static_cast<long>(io::reduced(rows, "cycles", where));
  return r;
}

}  // namespace

BlockResult run_block(const BlockSpec& spec) {
  io::Deck deck = block_deck(spec);
  fe::Solver s(deck.model);
  const auto reduction = io::make_reduction(deck.output.reduce, deck.model);
  s.run([&](const fe::Progress& p) { reduction->cycle(s, p); });
  return from_rows(reduction->finish(s), spec.name);
}

BlockResult read_block_run(const std::string& dir) {
  const std::string path = (std::filesystem::path(dir) / io::kReductionFile).string();
  return from_rows(io::read_reduction(path), path);
}

BlockResult run_block_job(const BlockSpec& spec, const std::string& dir, bool reuse) {
  run_deck_job(spec.name, block_deck_text(spec), dir, reuse);
  return read_block_run(dir);
}

std::vector<BlockResult> run_blocks(const std::vector<BlockSpec>& specs, const std::string& runs, bool reuse) {
  std::vector<std::string> names, texts;
  for (const auto& s : specs) names.push_back(s.name), texts.push_back(block_deck_text(s));
  const std::vector<std::string> dirs = run_jobs(names, texts, runs, reuse, "block spec");
  std::vector<BlockResult> out;
  for (std::size_t k = 0; k < specs.size(); ++k) out.push_back(read_block_run(dirs[k]));
  return out;
}

}  // namespace drawbend::sim

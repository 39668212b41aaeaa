// The block-sliding builder: the typed deck, run, reduction.  See block_case.hpp.
#include "sim/block_case.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

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
  if (!s.friction && s.surface_nodes.empty()) throw InputError(w + "no friction law and no surface nodes");
}

/// The deck's header: what the case is, what it measures, units.
std::vector<std::string> header(const BlockSpec& s, double FN) {
  return {"Block-sliding case written by drawbend's builder (src/sim/block_case.cpp; Sec. 6.5, Fig. 6.7):",
          "a " + fmt(s.size) + " mm cube pressed on a rigid floor at " + fmt(s.pressure) + " MPa (" + fmt(FN) +
              " N) and slid at " + fmt(s.speed) + " mm/s, " + fmt(s.direction_deg) + " deg from RD (x).",
          "Friction = F_t / F_N on the floor over the last third of the slide.",
          "[sheet] rolling_direction: RD; the friction texture (and the material axes) start from it.",
          "output.reduce: mu_x, mu_y over the last third of the slide, kept every cycle (io/case_reduction.hpp): "
          "reduction.csv",
          "Units: mm, N, MPa, s, t/mm^3.  Run with: drawbend run deck.toml --out DIR"};
}

}  // namespace

io::CaseSpec block_case(const BlockSpec& s) {
  check_spec(s);
  const double FN = s.pressure * s.size * s.size, psi = s.direction_deg * M_PI / 180.0;
  io::CaseSpec c;
  c.comment = header(s, FN);
  c.rest.insert("case", toml::table{{"name", s.name},
                                    {"description", "block " + fmt(s.size) + " mm, " + fmt(s.pressure) + " MPa, slid at " +
                                                        fmt(s.speed) + " mm/s, " + fmt(s.direction_deg) + " deg from RD"}});
  io::MeshSpec& mesh = c.mesh.emplace();
  for (const char* axis : {"x", "y", "z"})
    mesh.rest.insert(axis, inline_table(toml::table{{"from", 0.0}, {"to", s.size}, {"n", s.elements}}));
  c.material = material_choice("", s.hardening);
  c.rest.insert("sheet", sheet_table("rd"));
  io::NumericsSpec& n = c.numerics.emplace();
  n.dt_safety = 0.8;
  n.rest.insert("mass_scaling", s.mass_scaling);
  io::ToolSpec& floor = c.tools.emplace_back();
  floor.name = "floor", floor.drive = "fixed";
  io::SurfaceSpec& plane = floor.surfaces.emplace_back();
  plane.kind = "plane", plane.origin = io::Vec3Spec{0.0, 0.0, 0.0}, plane.normal = io::Vec3Spec{0.0, 0.0, 1.0};
  io::ContactSpec& contact = c.contacts.emplace_back();
  contact.rest = toml::table{{"faces", "zmin"}, {"tool", "floor"}, {"penalty", s.penalty}, {"texture", "fixed"}};
  contact.friction = s.friction ? *s.friction : io::surface_friction(s.surface_nodes, s.interval);
  auto load = [&](auto magnitude) {  // the normal load on the top face
    toml::table f = inline_table(toml::table{{"set", "zmax"}, {"direction", toml::array{0.0, 0.0, -1.0}}});
    f.insert("magnitude", std::move(magnitude));
    return toml::array{std::move(f)};
  };
  io::StepSpec& press = c.steps.emplace_back();
  press.name = "press", press.duration = s.press_time, press.damping = s.press_damping;
  press.rest.insert("force", load(ramp_history(s.press_ramp, FN)));
  io::StepSpec& slide = c.steps.emplace_back();
  slide.name = "slide", slide.duration = s.slide_time;
  slide.rest.insert("force", load(FN));
  toml::array velocity;
  for (const auto& [dir, v] : {std::pair{toml::array{1.0, 0.0, 0.0}, s.speed * std::cos(psi)},
                               std::pair{toml::array{0.0, 1.0, 0.0}, s.speed * std::sin(psi)}})
    velocity.push_back(inline_table(toml::table{{"set", "all"}, {"direction", dir}, {"speed", ramp_history(s.speed_ramp, v)}}));
  slide.rest.insert("velocity", std::move(velocity));
  toml::array history;
  for (const auto& [name, component] : {std::pair{"friction_x_N", 0}, std::pair{"friction_y_N", 1}, std::pair{"normal_N", 2}})
    history.push_back(inline_table(
        toml::table{{"name", name}, {"kind", "tool_force"}, {"target", "floor"}, {"component", component}}));
  c.output = toml::table{{"fields_per_step", 1}, {"history", std::move(history)}};
  c.reduce = io::ReduceSpec{"block_slide", "floor", "slide", {}, {}, {}, {}, true};
  return c;
}

std::string block_deck_text(const BlockSpec& s) { return io::to_toml(block_case(s)); }

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

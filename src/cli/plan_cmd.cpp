// `drawbend plan DECK_OR_FOLDER... [--nodes N] [--cores C]`: what the cases
// will cost before they run (sim/cost_model.hpp).  Every deck.toml found (a
// deck file, or the run folders under a folder, up to three levels down) is read
// with the deck reader and listed with its elements, predicted cycles, CPU
// time and memory; then the total CPU-hours and the makespan on N nodes of C
// cores by the largest-first schedule of the case pool.  Where a folder holds
// a finished run (summary.csv), its measured CPU time (run.log) and the ratio of
// predicted to measured CPU time are listed too, with their median and worst,
// over all runs, per case kind and per material type: how well the model
// predicts on this machine.
//
//   drawbend plan build/chapters --nodes 4 --cores 2
//   drawbend plan my.toml
#include <algorithm>
#include <set>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <sstream>

#include "core/csv.hpp"
#include "core/options.hpp"
#include "io/deck.hpp"
#include "sim/cost_model.hpp"

namespace drawbend::cli {

namespace fs = std::filesystem;

namespace {

struct Row {
  std::string deck;
  sim::CasePrediction p;
  double measured_cpu = NAN;  ///< wall time x threads of a finished run [s]
};

/// A finished run's CPU seconds: its log's "cpu:" line (the run's one thread,
/// io/run_case.hpp), else summary.csv's wall_time x the threads its log names
/// (which counts the waits of a machine shared with other work).
double measured_cpu(const fs::path& dir) {
  std::error_code ec;
  if (!fs::is_regular_file(dir / "summary.csv", ec)) {
    if (fs::exists(dir / "summary.csv", ec))  // a folder or a device where a run writes its summary: said, as a bad file
      std::cerr << "warning: " << (dir / "summary.csv").string()
                << ": expected a run's summary file, found no regular file; that run's measurement is left out\n";
    return NAN;
  }
  double wall = NAN;
  try {
    const CsvTable t = read_csv((dir / "summary.csv").string());
    const CsvRow* first = nullptr;
    for (const auto& row : t.rows)
      if (t.text(row, "quantity") == "wall_time") {
        // Two wall times (an edited or concatenated file): the last one was taken without a word.
        if (first)
          throw InputError(t.where(row, "quantity") + ": wall_time given twice (also on line " +
                           std::to_string(first->line) + ")");
        first = &row;
        wall = t.number(row, "value");
      }
  } catch (const std::exception& e) {  // said, as a wall time out of range is (silent before 2026-12-04)
    std::cerr << "warning: " << e.what() << "; that run's measurement is left out\n";
    return NAN;
  }
  // A wall time that no run can have (not a number, <= 1 ms, above a year) is
  // not a measurement: said and left out, not divided into a ratio of 1e298.
  if (!std::isnan(wall) && !(wall >= 1e-3 && wall <= 3.2e7)) {
    std::cerr << "warning: " << (dir / "summary.csv").string() << ": wall_time " << fmt_shortest(wall)
              << " s is not a run's wall time (expected 1e-3 to 3.2e7 s); that run's measurement is left out\n";
    return NAN;
  }
  long threads = 1;
  double cpu = NAN;
  if (fs::is_regular_file(dir / "run.log", ec)) {
    std::istringstream in(read_file((dir / "run.log").string()));
    for (std::string l; std::getline(in, l);) {
      if (l.rfind("  threads: ", 0) == 0) threads = std::clamp(std::strtol(l.c_str() + 11, nullptr, 10), 1L, 4096L);
      if (l.rfind("  cpu: ", 0) == 0) cpu = std::strtod(l.c_str() + 7, nullptr);
    }
  }
  if (!std::isnan(wall) && cpu >= 1e-3 && cpu <= 3.2e7) return cpu;
  return wall * static_cast<double>(threads);
}

// A folder is searched to a bounded depth and size (`drawbend plan /` walked the
// whole file system): the deck.toml files at most kMaxDepth folders below it
// (build/chapters/<chapter>/runs/<case>/deck.toml is three below
// build/chapters; a model loop's --out/runs/<case>/deck.toml two), level by
// level, links to folders not followed, at most kMaxEntries entries looked at:
// past that, an input error asks for a narrower folder instead of a long walk.
// A sub-folder that cannot be listed (no permission, gone meanwhile) is passed
// over; the named folder itself must be listable.
constexpr int kMaxDepth = 3;
constexpr long kMaxEntries = 200000;

void collect(const fs::path& p, std::vector<fs::path>& decks) {
  std::error_code ec;
  if (fs::is_regular_file(p, ec)) {
    decks.push_back(p);
    return;
  }
  if (!fs::is_directory(p, ec)) throw InputError(p.string() + ": not a deck file or a folder");
  long seen = 0;
  std::vector<fs::path> level{p};
  for (int depth = 0; depth <= kMaxDepth && !level.empty(); ++depth) {
    std::vector<fs::path> next;
    for (const auto& dir : level) {
      fs::directory_iterator it(dir, fs::directory_options::skip_permission_denied, ec), end;
      if (ec && depth == 0) throw InputError(p.string() + ": cannot list the folder (" + ec.message() + ")");
      for (; !ec && it != end; it.increment(ec)) {
        if (++seen > kMaxEntries)
          throw InputError(p.string() + ": more than " + std::to_string(kMaxEntries) + " files and folders within " +
                           std::to_string(kMaxDepth) + " levels of it; name the folder of the runs (e.g. "
                           "build/chapters, or one chapter's runs/) or the deck files");
        std::error_code e2;
        if (it->is_directory(e2) && !it->is_symlink(e2)) {
          if (depth < kMaxDepth) next.push_back(it->path());
        } else if (it->path().filename() == "deck.toml" && it->is_regular_file(e2)) {
          decks.push_back(it->path());
        }
      }
      ec.clear();
    }
    level = std::move(next);
  }
  std::sort(decks.begin(), decks.end());
}

/// "# WHAT n finished runs: median, range, worst factor" of predicted / measured ratios.
void ratio_line(const std::string& what, std::vector<double> ratio) {
  if (ratio.empty()) return;
  std::sort(ratio.begin(), ratio.end());
  const double median = ratio.size() % 2 ? ratio[ratio.size() / 2]
                                         : 0.5 * (ratio[ratio.size() / 2 - 1] + ratio[ratio.size() / 2]);
  const double worst = std::max(ratio.back(), 1 / ratio.front());
  std::cout << "# " << what << " " << ratio.size() << " finished runs: median " << fmt(median, 3) << ", range "
            << fmt(ratio.front(), 3) << " to " << fmt(ratio.back(), 3) << " (worst factor " << fmt(worst, 3) << ")\n";
}

}  // namespace

int plan_command(int argc, char** argv) {
  int nodes = 1, cores = 2;
  Options opt("drawbend plan DECK_OR_FOLDER...",
              "Predicted CPU time and memory of every deck (a deck file, or every deck.toml in a folder and its "
              "sub-folders up to three levels down, e.g. build/chapters/<chapter>/runs/<case>/), the "
              "total CPU-hours and the makespan on N nodes of C cores (largest case first, one case per node on "
              "all its cores); measured against finished runs where a folder holds one (e.g. build/chapters).");
  opt.add(nodes, "nodes", "nodes of the cluster (>= 1)");
  opt.add(cores, "cores", "cores per node (>= 1)");
  opt.example("drawbend plan data/cases/drawbend_12p7.toml data/cases/block_slide.toml");
  opt.example("drawbend plan data/cases/drawbend_12p7.toml data/cases/strip_draw.toml --nodes 2 --cores 2");
  std::vector<std::string> paths;
  std::vector<char*> rest{argv[0]};
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a.rfind("-", 0) == 0) {
      rest.push_back(argv[i]);
      if (a != "--help" && a != "-h" && i + 1 < argc) rest.push_back(argv[++i]);
    } else {
      paths.push_back(a);
    }
  }
  if (!opt.parse(static_cast<int>(rest.size()), rest.data())) return 0;
  if (nodes < 1 || nodes > 100000) throw InputError("--nodes: expected a whole number from 1 to 100000");
  if (cores < 1 || cores > 4096) throw InputError("--cores: expected a whole number from 1 to 4096");
  if (paths.empty()) throw InputError("drawbend plan: name a deck or a folder of run folders (--help)");
  std::vector<fs::path> decks;
  for (const auto& p : paths) collect(p, decks);
  {  // a deck named twice (a path given twice, or a deck and its folder) is one case, not two
    std::vector<fs::path> once;
    std::set<std::string> seen;
    for (const auto& d : decks) {
      std::error_code ec;
      if (!seen.insert(fs::weakly_canonical(d, ec).string()).second) {
        std::cerr << "warning: " << d.string() << " is named twice (the same deck from two of the paths given); "
                  << "planned once\n";
        continue;
      }
      once.push_back(d);
    }
    decks = std::move(once);
  }
  if (decks.empty())
    throw InputError("drawbend plan: no deck.toml under " + paths.front() + " (a folder is searched " +
                     std::to_string(kMaxDepth) + " levels down)");
  std::vector<Row> rows;
  for (const auto& d : decks) {
    Row r;
    r.deck = d.string();
    const io::Deck deck = io::read_deck(d.string());  // exit 2 with file:line: key on a bad deck
    r.p = sim::predict_case(deck);
    r.measured_cpu = measured_cpu(d.parent_path());
    rows.push_back(r);
  }
  std::cout << "deck,elements,cycles_predicted,cpu_s_predicted,memory_mb,cpu_s_measured,predicted_over_measured,kind,"
               "material\n";
  std::vector<double> cpu, ratio;
  for (const auto& r : rows) {
    cpu.push_back(r.p.cpu_seconds);
    std::cout << r.deck << "," << r.p.elements << "," << fmt(r.p.cycles, 4) << "," << fmt(r.p.cpu_seconds, 4) << ","
              << fmt(r.p.memory_mb, 3) << ",";
    if (std::isfinite(r.measured_cpu) && r.measured_cpu > 0) {
      ratio.push_back(r.p.cpu_seconds / r.measured_cpu);
      std::cout << fmt(r.measured_cpu, 4) << "," << fmt(ratio.back(), 3);
    } else {
      std::cout << ",";
    }
    std::cout << "," << (r.p.kind.empty() ? "draw-bend" : r.p.kind) << "," << r.p.material << "\n";
  }
  double total = 0;
  for (double c : cpu) total += c;
  std::cout << "# " << rows.size() << " cases, " << fmt(total / 3600, 3) << " CPU-hours predicted (model: "
            << "elements x predicted cycles x ns per element-cycle of the case's kind: draw-bend "
            << sim::ns_per_element_cycle("") << ", strip_draw " << sim::ns_per_element_cycle("strip_draw")
            << ", block_slide " << sim::ns_per_element_cycle("block_slide") << ", cup_draw "
            << sim::ns_per_element_cycle("cup_draw") << ", earing_cup " << sim::ns_per_element_cycle("earing_cup")
            << "; x material factor:";
  for (const auto& m : sim::costed_materials())
    std::cout << (m == sim::costed_materials().front() ? " " : ", ") << m << " " << sim::material_factor(m);
  std::cout << ")\n";
  std::cout << "# makespan on " << nodes << " node(s) x " << cores << " core(s): "
            << fmt(sim::makespan_seconds(cpu, nodes, cores) / 60, 3) << " min (largest first)\n";
  ratio_line("predicted / measured CPU over", ratio);
  std::map<std::string, std::vector<double>> by_kind;  // the same per case kind
  for (const auto& r : rows)
    if (std::isfinite(r.measured_cpu) && r.measured_cpu > 0)
      by_kind[r.p.kind.empty() ? "draw-bend" : r.p.kind].push_back(r.p.cpu_seconds / r.measured_cpu);
  if (by_kind.size() > 1)
    for (auto& [kind, v] : by_kind) ratio_line("  " + kind + ":", v);
  std::map<std::string, std::vector<double>> by_material;  // and per material type
  for (const auto& r : rows)
    if (std::isfinite(r.measured_cpu) && r.measured_cpu > 0)
      by_material[r.p.material].push_back(r.p.cpu_seconds / r.measured_cpu);
  if (by_material.size() > 1)
    for (auto& [material, v] : by_material) ratio_line("  material " + material + ":", v);
  return 0;
}

}  // namespace drawbend::cli

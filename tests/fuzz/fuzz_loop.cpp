// libFuzzer target: the whole `drawbend loop` pipeline on small arbitrary CSV
// files (issue 17), as loop_cmd.cpp runs it: parse_measured, the map library
// (the analytic stand-in for the data's pins), make_design, run_loop (19
// permutations, to stay fast) and write_loop_outputs (tables, summary and
// loop.md; no figures, so no gnuplot) into $TMPDIR/fuzz_loop_PID (run.sh sets
// TMPDIR to the fuzz build's tmp/).  Any input must end normally or with an
// exception, which `drawbend loop` turns into exit 2 or 3; a crash, a
// sanitizer report or a hang (-timeout) is a failure.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <set>
#include <string>

#include "loop/loop.hpp"
#include "loop/maps.hpp"
#include "loop/measured.hpp"
#include "loop/model.hpp"
#include "loop/report.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace drawbend::loop;
  static const std::string out =
      (std::filesystem::temp_directory_path() / ("fuzz_loop_" + std::to_string(::getpid()))).string();
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const Dataset d = parse_measured(text, "fuzz.csv");
    if (d.rows.empty()) return 0;  // `drawbend loop`: "no usable rows", exit 2
    std::set<double> pins;
    for (const auto& s : d.rows) pins.insert(s.pin_d_mm);
    const MapLibrary maps = MapLibrary::stand_in({pins.begin(), pins.end()});
    const Design design = make_design(d, maps);
    LoopOptions lo;
    lo.permutations = 19;
    lo.max_steps = 2;
    const LoopResult r = run_loop(design, lo);
    write_loop_outputs(design, r, out, "");
  } catch (const std::exception&) {
    // exit 2 (InputError, invalid_argument) or 3 (any other failure) in drawbend loop
  }
  return 0;
}

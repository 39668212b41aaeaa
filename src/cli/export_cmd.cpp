// drawbend export FRICTION_MODEL.toml --to lsdyna|openradioss|abaqus [--out FILE]
//   Writes the friction model identified by `drawbend loop` (friction_model.toml
//   and its nodes CSV) as a deck fragment of another solver, with the error of
//   the written table or polynomial against our law (loop/export.hpp).
// Exit codes: 0 ok, 2 bad input, 3 numerical failure.
#include <omp.h>

#include <iostream>

#include "cli/exit_codes.hpp"
#include "cli/threads.hpp"
#include "core/csv.hpp"
#include "core/file_gate.hpp"
#include "core/options.hpp"
#include "loop/export.hpp"

namespace drawbend::cli {

int export_main(int argc, char** argv) {
  if (argc < 2 || std::string(argv[1]).rfind("--", 0) == 0) {
    std::cerr << "usage: drawbend export friction_model.toml --to lsdyna|openradioss|abaqus [--out FILE] [--threads N]\n";
    return argc >= 2 && std::string(argv[1]) == "--help" ? 0 : 2;
  }
  const std::string path = argv[1];
  std::string to, out;
  int threads = 0;
  Options opt("drawbend export FRICTION_MODEL.toml", "Export an identified friction model to another solver.");
  opt.add(to, "to", "lsdyna, openradioss or abaqus");
  opt.add(out, "out", "output file (default: friction_<to>.k|.rad|.inp next to the model)");
  opt.add(threads, "threads", "OpenMP threads (0: OMP_NUM_THREADS or all; the export itself is serial)");
  return with_exit_codes([&] {
    if (!opt.parse(argc - 1, argv + 1)) return 0;
    apply_threads(threads);
    const loop::ExportModel m = loop::read_friction_model(path);
    loop::ExportResult r;
    std::string ext;
    if (to == "lsdyna") r = loop::export_lsdyna(m), ext = ".k";
    else if (to == "openradioss") r = loop::export_openradioss(m), ext = ".rad";
    else if (to == "abaqus") r = loop::export_abaqus(m), ext = ".inp";
    else throw std::invalid_argument("--to must be lsdyna, openradioss or abaqus, not '" + to + "'");
    if (out.empty()) {
      const auto slash = path.find_last_of('/');
      out = (slash == std::string::npos ? std::string() : path.substr(0, slash + 1)) + "friction_" + to + ext;
    }
    name_input(out, "--out");  // never replaces a folder, FIFO or device (core/file_gate.hpp)
    write_file_atomic(out, r.text);
    std::cout << "wrote " << out << " (" << to << "; max |mu - law| = " << fmt(r.max_error, 3) << " over the domain)\n";
    return 0;
  });
}

}  // namespace drawbend::cli

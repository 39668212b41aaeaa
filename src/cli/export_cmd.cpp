// drawbend export FRICTION_MODEL.toml --to lsdyna|openradioss|abaqus [options]
//   Writes the friction model identified by `drawbend loop` (friction_model.toml
//   and its nodes CSV) as a deck fragment of another solver, with the error of
//   the written table or polynomial against our law (loop/export.hpp).
// Exit codes: 0 ok, 2 bad input (the option named), 3 numerical failure (the
// OpenRadioss polynomial cannot meet its error bound).
#include <iostream>

#include "cli/exit_codes.hpp"
#include "cli/threads.hpp"
#include "core/csv.hpp"
#include "core/file_gate.hpp"
#include "core/options.hpp"
#include "loop/export.hpp"

namespace drawbend::cli {

int export_main(int argc, char** argv) {
  std::string to, out, parts, rd_vector, band;
  int threads = 0;
  loop::ExportOptions eo;
  Options opt("drawbend export FRICTION_MODEL.toml", "Export an identified friction model to another solver.");
  opt.add(to, "to", "lsdyna, openradioss or abaqus");
  opt.add(out, "out", "output file (default: friction_<to>.k|.rad|.inp next to the model)");
  opt.add(parts, "parts", "SHEET,TOOL part IDs (required for openradioss; lsdyna SSID,MSID)");
  opt.add(eo.direction, "direction",
          "rd, td or mean: one isotropic law (openradioss, lsdyna, abaqus explicit); ortho: both directions "
          "(openradioss Idir = 1, lsdyna ORTHO_FRICTION); abaqus standard always writes both");
  opt.add(rd_vector, "rd-vector", "X,Y,Z rolling direction in the deck's axes (OpenRadioss /FRIC_ORIENT; default 1,0,0)");
  opt.add(eo.friction_id, "id", "/FRICTION ID (OpenRadioss; speed bands take ID, ID+1, ...) and LS-DYNA contact ID");
  opt.add(band, "speed-band", "MIN,MAX sliding speeds [mm/s] the OpenRadioss polynomial is fitted over (default: the data's)");
  opt.add(eo.max_rel_error, "max-rel-error", "bound of the OpenRadioss fit's relative error per speed band (0.001 to 0.5)");
  opt.add(eo.abaqus_product, "abaqus", "standard (anisotropic table) or explicit (isotropic table)");
  opt.add(threads, "threads", "OpenMP threads (0: OMP_NUM_THREADS or all; the export itself is serial)");
  opt.example("drawbend loop data/measured/thesis_drawbend.csv --out my-loop --figures ''");
  opt.example("drawbend export my-loop/friction_model.toml --to abaqus    # writes my-loop/friction_abaqus.inp");
  opt.example("drawbend export my-loop/friction_model.toml --to lsdyna --out my-friction.k");
  const bool help = argc >= 2 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h");
  if (help) {
    std::cout << opt.usage();
    return 0;
  }
  if (argc >= 2 && std::string(argv[1]).rfind("-", 0) == 0) {  // as `run`: the option is named
    std::cerr << "input error: drawbend export: expected FRICTION_MODEL.toml first, found the option '"
              << clip_for_message(argv[1]) << "' (drawbend export MODEL.toml --to lsdyna; --help lists the options)\n";
    return 2;
  }
  if (argc < 2) {
    std::cerr << "usage: drawbend export friction_model.toml --to lsdyna|openradioss|abaqus [--out FILE] [--threads N]"
                 " (drawbend export --help: options and examples)\n";
    return 2;
  }
  const std::string path = argv[1];
  return with_exit_codes([&] {
    if (!opt.parse(argc - 1, argv + 1)) return 0;
    apply_threads(threads);
    if (to.empty()) throw std::invalid_argument("--to: expected lsdyna, openradioss or abaqus");
    // The options of one format given for another: refused, not ignored.
    opt.only_when(to == "openradioss", {"rd-vector", "speed-band", "max-rel-error"}, "with --to openradioss");
    opt.only_when(to == "abaqus", {"abaqus"}, "with --to abaqus");
    // Abaqus's *FRICTION has no part or contact IDs, and Abaqus/Standard's anisotropic table
    // always holds both directions: these options were ignored with exit 0 (before 2026-12-05).
    opt.only_when(to != "abaqus", {"parts", "id"}, "with --to lsdyna or openradioss (Abaqus's *FRICTION has no IDs)");
    opt.only_when(to != "abaqus" || eo.abaqus_product == "explicit", {"direction"},
                  "with --to lsdyna, openradioss or --abaqus explicit (Abaqus/Standard writes both directions)");
    loop::set_list_options(eo, parts, rd_vector, band);
    eo.contact_id = eo.friction_id;
    eo.validate(to == "lsdyna" || to == "openradioss" || to == "abaqus" ? to : "lsdyna");
    const loop::ExportModel m = loop::read_friction_model(path);
    const loop::ExportResult r = loop::export_to(to, m, eo);
    if (out.empty()) out = loop::export_path(path, to);
    name_input(out, "--out");  // never replaces a folder, FIFO or device (core/file_gate.hpp)
    refuse_input_as_output(out);  // nor the model or its nodes file
    write_file_atomic(out, r.text);
    std::cout << "wrote " << out << " (" << to << "; "
              << (to == "openradioss" ? "max relative error " + fmt(100 * r.max_error, 3) + " % in " +
                                            std::to_string(r.bands) + " speed band(s)"
                                      : "max |mu - law| = " + fmt(r.max_error, 3))
              << (m.td_copied ? "; TD copied from RD: the data had no TD rows" : "") << ")\n";
    return 0;
  });
}

}  // namespace drawbend::cli

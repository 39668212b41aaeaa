// libFuzzer target: `drawbend export` (issue 53) on a friction model and its
// nodes file.  The input is three parts separated by lines "%%"
// (fuzz_split.hpp): friction_model.toml, nodes.csv (the seeds name it in
// [friction] nodes) and the options, one per line: --to, --direction,
// --parts, --rd-vector, --speed-band (missing lines: the defaults).  They go
// through loop::read_friction_model, set_list_options, validate and export_to
// as export_cmd.cpp runs them.  Any input must give an export or throw
// InputError / std::invalid_argument (exit 2) or runtime_error (the
// OpenRadioss polynomial cannot meet its bound, exit 3); a crash, a sanitizer
// report, a hang, or an export that holds nan or inf is a bug.
#include <cstddef>
#include <cstdint>
#include <sstream>

#include "core/csv.hpp"
#include "fuzz_split.hpp"
#include "loop/export.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace drawbend::loop;
  const auto parts = fuzz::split_parts(std::string(reinterpret_cast<const char*>(data), size), 3);
  const std::string dir = fuzz::scratch("export");
  fuzz::write(dir + "/friction_model.toml", parts[0]);
  fuzz::write(dir + "/nodes.csv", parts[1]);
  std::istringstream opts(parts[2]);
  std::string to = "lsdyna", direction = "rd", part_ids, rd_vector, band;
  std::getline(opts, to) && std::getline(opts, direction) && std::getline(opts, part_ids) &&
      std::getline(opts, rd_vector) && std::getline(opts, band);
  if (to.empty()) to = "lsdyna";
  if (direction.empty()) direction = "rd";
  try {
    ExportOptions eo;
    eo.direction = direction;
    set_list_options(eo, part_ids, rd_vector, band);
    if (to == "openradioss" && eo.sheet_part == 0) eo.sheet_part = 1, eo.tool_part = 2;
    eo.validate(to == "lsdyna" || to == "openradioss" || to == "abaqus" ? to : "lsdyna");
    const ExportModel m = read_friction_model(dir + "/friction_model.toml");
    const ExportResult r = export_to(to, m, eo);
    fuzz::write(dir + "/out.txt", r.text);
    if (fuzz::has_non_finite(dir + "/out.txt")) fuzz::fail("an export holding nan or inf");
  } catch (const drawbend::InputError&) {
  } catch (const std::invalid_argument&) {
  } catch (const std::runtime_error& e) {  // only the polynomial's bound: exit 3 with its reason
    if (std::string(e.what()).rfind("OpenRadioss: ", 0) != 0) fuzz::fail(std::string("unexpected exception: ") + e.what());
  } catch (const std::exception& e) {
    fuzz::fail(std::string("unexpected exception: ") + e.what());
  }
  return 0;
}

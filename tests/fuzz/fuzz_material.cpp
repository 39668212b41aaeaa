// libFuzzer target: the builders' `--material FILE` (issue 53): a material
// TOML file and the hardening curve CSV it may name.  The input is two files
// separated by a line "%%" (fuzz_split.hpp): material.toml and curve.csv (the
// default flow curve, and the file `hardening = "curve.csv"` names), read as
// `drawbend-deck --material material.toml` reads them (sim::material_choice:
// the merge with the defaults, io::read_material's checks) and built as the
// deck reader builds them (io::make_material: the hardening table, Hill'48,
// Yld2004-18p and their checks); the flow curve is evaluated at a few strains.
// Any input must give a material or throw InputError / std::invalid_argument
// (exit 2 in every builder); a crash, a sanitizer report, another exception,
// a hang, or a built material whose flow stress is not finite is a bug.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <variant>

#include "core/csv.hpp"
#include "fuzz_split.hpp"
#include "io/material_spec.hpp"
#include "sim/material_choice.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto parts = fuzz::split_parts(std::string(reinterpret_cast<const char*>(data), size), 2);
  const std::string dir = fuzz::scratch("material");
  fuzz::write(dir + "/material.toml", parts[0]);
  fuzz::write(dir + "/curve.csv", parts[1]);
  try {
    const drawbend::io::MaterialSpec spec = drawbend::sim::material_choice(dir + "/material.toml", dir + "/curve.csv");
    const auto m = drawbend::io::make_material(spec, dir);
    if (spec.curve) {
      const auto curve = drawbend::io::make_flow_curve(*spec.curve, dir);
      for (double ep : {0.0, 1e-3, 0.1, 1.0, 10.0})
        if (!std::isfinite(curve.stress(ep))) fuzz::fail("a flow curve accepted with a non-finite stress");
    }
  } catch (const drawbend::InputError&) {
  } catch (const std::invalid_argument&) {
  } catch (const std::exception& e) {
    fuzz::fail(std::string("unexpected exception: ") + e.what());
  }
  return 0;
}

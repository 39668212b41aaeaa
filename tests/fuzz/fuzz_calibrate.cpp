// libFuzzer target: `drawbend calibrate TESTS.csv --out DIR` (issue 53), the
// command itself (cli/calibrate_cmd.cpp) on arbitrary bytes as the sheet's
// material tests (columns test, angle_deg, stress_ratio, r_value): the CSV
// reader, the tests' checks, Hill'48 from the r-values and from the stress
// ratios, the Yld2004-18p fit and the written table.  Any input must end with
// exit 0 or throw InputError / std::invalid_argument (exit 2; the command is
// run under with_codes); a crash, a sanitizer report, another exception, a
// hang, or an exit 0 whose material.toml or calibration.csv holds nan or inf
// is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/csv.hpp"
#include "fuzz_split.hpp"

namespace drawbend::cli {
int calibrate_command(int argc, char** argv);
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string dir = fuzz::scratch("calibrate");
  fuzz::write(dir + "/tests.csv", std::string(reinterpret_cast<const char*>(data), size));
  std::string a0 = "drawbend calibrate", a1 = dir + "/tests.csv", a2 = "--out", a3 = dir + "/out";
  char* argv[] = {a0.data(), a1.data(), a2.data(), a3.data(), nullptr};
  try {
    if (drawbend::cli::calibrate_command(4, argv) == 0)
      for (const char* f : {"/out/material.toml", "/out/calibration.csv"})
        if (fuzz::has_non_finite(dir + f)) fuzz::fail(std::string("exit 0 with nan or inf in ") + f);
  } catch (const drawbend::InputError&) {
  } catch (const std::invalid_argument&) {
  } catch (const std::exception& e) {
    fuzz::fail(std::string("unexpected exception: ") + e.what());
  }
  return 0;
}

// libFuzzer target: `drawbend plan FOLDER` (issue 53), the command itself
// (cli/plan_cmd.cpp) on a run folder made of the input: three parts separated
// by lines "%%" (fuzz_split.hpp) written as run/deck.toml, run/summary.csv
// (a finished run's wall time) and run/run.log (its thread count).  The deck
// reader, the cost model (sim/cost_model.hpp), the measured time and the
// makespan.  Any input must end with exit 0 or throw InputError /
// std::invalid_argument (exit 2); a crash, a sanitizer report, another
// exception or a hang is a bug.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

#include "core/csv.hpp"
#include "fuzz_split.hpp"

namespace drawbend::cli {
int plan_command(int argc, char** argv);
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto parts = fuzz::split_parts(std::string(reinterpret_cast<const char*>(data), size), 3);
  const std::string dir = fuzz::scratch("plan");
  std::filesystem::create_directories(dir + "/run");
  fuzz::write(dir + "/run/deck.toml", parts[0]);
  if (!parts[1].empty()) fuzz::write(dir + "/run/summary.csv", parts[1]);
  if (!parts[2].empty()) fuzz::write(dir + "/run/run.log", parts[2]);
  std::string a0 = "drawbend plan", a1 = dir, a2 = "--nodes", a3 = "2";
  char* argv[] = {a0.data(), a1.data(), a2.data(), a3.data(), nullptr};
  try {
    drawbend::cli::plan_command(4, argv);
  } catch (const drawbend::InputError&) {
  } catch (const std::invalid_argument&) {
  } catch (const std::exception& e) {
    fuzz::fail(std::string("unexpected exception: ") + e.what());
  }
  return 0;
}

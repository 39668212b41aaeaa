// libFuzzer target: the CSV reader (parse_csv) and its cell access on
// arbitrary bytes.  Any input must give a table or throw drawbend::InputError;
// reading every cell as a number may throw InputError only.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/csv.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const drawbend::CsvTable t = drawbend::parse_csv(text, "fuzz.csv");
    for (const auto& r : t.rows)
      for (const auto& h : t.header) try {
          t.number(r, h);
        } catch (const drawbend::InputError&) {
        }
  } catch (const drawbend::InputError&) {
  } catch (const std::exception& e) {
    std::fprintf(stderr, "unexpected exception: %s\n", e.what());
    std::abort();
  }
  return 0;
}

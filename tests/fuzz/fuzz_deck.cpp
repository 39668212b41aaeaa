// libFuzzer target: the case-deck reader (io::parse_deck) on arbitrary bytes.
// Any input must either give a Deck or throw drawbend::InputError (or
// std::invalid_argument, which `drawbend run` also reports as input, exit 2);
// a crash, a sanitizer report, a hang or any other exception is a bug.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/csv.hpp"
#include "io/deck.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    drawbend::io::parse_deck(text, "/nonexistent/fuzz/deck.toml");
  } catch (const drawbend::InputError&) {
  } catch (const std::invalid_argument&) {
  } catch (const std::exception& e) {
    std::fprintf(stderr, "unexpected exception: %s\n", e.what());
    std::abort();
  }
  return 0;
}

// toml++'s parser and formatter, compiled once for the whole project.
//
// toml++ is header-only by default: every source that includes it compiles
// its implementation again (about 3 s of g++ -O3 for each one that calls
// toml::parse, 5.5 s of clang -O1 with the fuzz build's sanitizers; 0.5 s
// with TOML_HEADER_ONLY=0).  drawbend_core sets TOML_HEADER_ONLY=0 for itself
// and everything that links it (src/CMakeLists.txt; tests/fuzz/CMakeLists.txt
// for the fuzz build), and this file supplies the definitions, built with the
// project's flags: so the sanitizer and fuzz builds still instrument toml++'s
// own code, where findings 1-5 of tests/fuzz/README.md were.
#define TOML_IMPLEMENTATION
#include <toml++/toml.h>

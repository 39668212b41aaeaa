#pragma once
// Where the data the commands read at run time live (materials, thesis tables,
// example decks, gnuplot scripts): found, in this order,
//   1. the environment variable DRAWBEND_DATA_DIR (DRAWBEND_FIGURES_DIR);
//   2. an installed tree: <prefix>/share/drawbend/data (figures) beside the
//      running binary's <prefix>/bin (`make install`, CMake's install rules);
//   3. the source tree the binary was built from (the build folder's binary).
#include <string>

namespace drawbend {

std::string data_dir();     ///< the data/ folder (materials/, thesis/, cases/, measured/)
std::string figures_dir();  ///< the figures/ folder of gnuplot scripts

}  // namespace drawbend

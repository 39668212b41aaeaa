// The precompiled header of every chapter executable (chapters/CMakeLists.txt
// says what it saves).  CMake includes it before the first line of each
// chapter source.  It holds what the chapters share and rarely change: the
// standard headers they use most and the study, simulation and analysis
// headers that most chapters include anyway (each has include guards, so a
// source's own #include of them costs nothing).  Nothing here may define a
// macro a chapter source tests: the header is seen before the source's first line.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "analysis/pressure_ratio.hpp"
#include "analysis/rope.hpp"
#include "core/csv.hpp"
#include "sim/case_pool.hpp"
#include "sim/drawbend_case.hpp"
#include "sim/fe_options.hpp"
#include "sim/map_tools.hpp"
#include "study/chapter.hpp"
#include "study/run_health.hpp"
#include "study/thesis_data.hpp"

// The precompiled header of every Boost.Test executable (tests/CMakeLists.txt
// says what it saves).  CMake includes it before the first line of each test
// file.  It holds what the tests share and never change: Boost.Test's
// machinery and the standard headers the tests use most; no drawbend header.
//
// Not <boost/test/unit_test.hpp> itself: a test file's
//   #define BOOST_TEST_MODULE name
//   #include <boost/test/unit_test.hpp>
// must still generate that test's main() and name its module, and a header
// included before the #define would have skipped both.  The part of Boost.Test
// that reads BOOST_TEST_MODULE is unit_test.hpp, unit_test_suite.hpp and
// detail/config.hpp (which turns BOOST_TEST_MODULE into BOOST_TEST_MAIN); the
// first two are not included here, and config.hpp, which holds macros only, is
// opened again by removing its include guard.  Should a newer Boost rename that
// guard, no test would have a main() and every test would fail to link.
#include <boost/test/framework.hpp>
#include <boost/test/test_tools.hpp>
#include <boost/test/tree/auto_registration.hpp>
#include <boost/test/tree/global_fixture.hpp>
#include <boost/test/tree/test_case_template.hpp>
#undef BOOST_TEST_CONFIG_HPP_071894GER

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

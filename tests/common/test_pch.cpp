// The host of the tests' precompiled header (test_pch.hpp, tests/CMakeLists.txt):
// CMake compiles a precompiled header only for a target with a source.

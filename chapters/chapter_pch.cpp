// The host of the chapters' precompiled header (chapter_pch.hpp,
// chapters/CMakeLists.txt): CMake compiles a precompiled header only for a
// target with a source.

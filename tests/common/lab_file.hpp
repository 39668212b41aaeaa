#pragma once
// A synthetic data set as a lab would send it: written with write_measured to
// a file and read back, as the text (lab_text) or parsed as `drawbend loop`
// parses it (lab_file); and the stand-in pressure maps of its pins.  The file
// is named per process: the sanitizer suite runs the same tests beside the
// main one, and two runs must not read (or remove) each other's rows.
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "loop/maps.hpp"
#include "loop/measured.hpp"

namespace drawbend::test {

// The file's text; its path (removed again) in *path when given.
inline std::string lab_text(const loop::Dataset& d, const std::string& name, std::string* path = nullptr) {
  const std::string p =
      (std::filesystem::temp_directory_path() / ("drawbend_" + std::to_string(::getpid()) + "_" + name)).string();
  loop::write_measured(p, d);
  std::ifstream in(p, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  in.close();
  std::filesystem::remove(p);
  if (path) *path = p;
  return text.str();
}

inline loop::Dataset lab_file(const loop::Dataset& d, const std::string& name) {
  std::string path;
  const std::string text = lab_text(d, name, &path);
  return loop::parse_measured(text, path);
}

inline loop::MapLibrary stand_in_maps(const loop::Dataset& d) {
  std::set<double> pins;
  for (const auto& s : d.rows) pins.insert(s.pin_d_mm);
  return loop::MapLibrary::stand_in(std::vector<double>(pins.begin(), pins.end()));
}

// The rows of the first test whose `column` differs from the first row's,
// moved to the top (the file's order otherwise kept): another level of the
// column comes first (Design::levels numbers levels by first appearance).
inline loop::Dataset another_level_first(const loop::Dataset& d, const std::string& column) {
  const int k = d.extra_index(column);
  if (k < 0) throw std::invalid_argument("another_level_first: no column '" + column + "'");
  std::string test;
  for (const auto& s : d.rows)
    if (s.extra[k] != d.rows[0].extra[k]) {
      test = s.test_id;
      break;
    }
  if (test.empty()) throw std::invalid_argument("another_level_first: '" + column + "' has one level");
  loop::Dataset out = d;
  std::stable_partition(out.rows.begin(), out.rows.end(), [&](const loop::Sample& s) { return s.test_id == test; });
  return out;
}

}  // namespace drawbend::test

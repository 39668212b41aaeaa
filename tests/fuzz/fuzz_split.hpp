#pragma once
// Helpers of the file-reading fuzz targets (fuzz_material, fuzz_export,
// fuzz_calibrate, fuzz_plan): one fuzz input holds several files, separated
// by lines "%%" (the dictionaries hold the separator, so mutations move text
// between the files and make new ones); each part is written to a scratch
// folder under $TMPDIR (run.sh points it at the fuzz build's tmp/), one per
// target and process, and the entry point reads the files from there, through
// the same file gate (core/file_gate.hpp) as the command.
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace fuzz {

/// The parts of `text` between lines "%%" (at most `max` parts; the rest stays in the last).
inline std::vector<std::string> split_parts(const std::string& text, std::size_t max) {
  std::vector<std::string> parts{std::string()};
  std::size_t pos = 0;
  while (parts.size() < max) {
    const std::size_t at = text.find("\n%%\n", pos);
    if (at == std::string::npos) break;
    parts.back() = text.substr(pos, at + 1 - pos);
    parts.emplace_back();
    pos = at + 4;
  }
  parts.back() = text.substr(pos);
  parts.resize(max);
  return parts;
}

/// An empty scratch folder $TMPDIR/fuzz_NAME_PID (made once, emptied on each call).
inline std::string scratch(const std::string& name) {
  static const std::string dir =
      (std::filesystem::temp_directory_path() / ("fuzz_" + name + "_" + std::to_string(::getpid()))).string();
  std::error_code ec;
  std::filesystem::remove_all(dir, ec);
  std::filesystem::create_directories(dir);
  return dir;
}

inline void write(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

/// Whether a file the entry point wrote holds "nan" or "inf" as a number: an
/// exit 0 with a non-finite result is nonsense (the oracle beyond "no crash").
inline bool has_non_finite(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string s((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (const char* w : {"nan", "inf", "NaN", "Inf"})
    for (std::size_t at = s.find(w); at != std::string::npos; at = s.find(w, at + 1)) {
      const bool left = at == 0 || std::string(" ,=[\t-+(").find(s[at - 1]) != std::string::npos;
      const std::size_t e = at + 3;
      const bool right = e >= s.size() || std::string(" ,]\n\r\t)").find(s[e]) != std::string::npos ||
                         s.compare(e, 5, "inity") == 0;
      if (left && right) return true;
    }
  return false;
}

[[noreturn]] inline void fail(const std::string& what) {
  std::fprintf(stderr, "fuzz oracle: %s\n", what.c_str());
  std::abort();
}

}  // namespace fuzz

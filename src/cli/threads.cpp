// --threads N written into a deck (cli/threads.hpp says where and why).
#include "cli/threads.hpp"

#include <cstdint>
#include <sstream>
#include <vector>

#include <toml++/toml.h>

namespace drawbend::cli {

std::string deck_with_threads(const std::string& text, int n) {
  check_threads(n);
  if (n == 0) return text;
  const std::string line = "threads = " + std::to_string(n) + "  # OpenMP threads of `drawbend run` (--threads)";
  std::vector<std::string> lines;
  {
    std::istringstream in(text);
    for (std::string l; std::getline(in, l);) lines.push_back(l);
  }
  auto trimmed = [](const std::string& l) {
    const std::size_t a = l.find_first_not_of(" \t");
    return a == std::string::npos ? std::string() : l.substr(a);
  };
  std::size_t head = lines.size();
  for (std::size_t i = 0; i < lines.size() && head == lines.size(); ++i)
    if (trimmed(lines[i]).rfind("[numerics]", 0) == 0) head = i;
  if (head == lines.size()) {
    lines.push_back("");
    lines.push_back("[numerics]");
    lines.push_back(line);
  } else {
    bool replaced = false;
    for (std::size_t i = head + 1; i < lines.size() && trimmed(lines[i]).rfind("[", 0) != 0; ++i) {
      const std::string t = trimmed(lines[i]);
      if (t.rfind("threads", 0) == 0 && t.find_first_not_of(" \t", 7) != std::string::npos &&
          t[t.find_first_not_of(" \t", 7)] == '=') {
        lines[i] = line;
        replaced = true;
        break;
      }
    }
    if (!replaced) lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(head + 1), line);
  }
  std::string out;
  for (const auto& l : lines) out += l + "\n";
  toml::table t;
  try {
    t = toml::parse(out);
  } catch (const toml::parse_error& e) {
    throw InputError("--threads: the deck could not take threads = " + std::to_string(n) + " (" +
                     std::string(e.description()) + ")");
  }
  if (t["numerics"]["threads"].value<std::int64_t>() != std::int64_t{n})
    throw InputError("--threads: the deck could not take threads = " + std::to_string(n) +
                     " (its [numerics] table is not where this command looks for it)");
  return out;
}

}  // namespace drawbend::cli

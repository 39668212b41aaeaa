// Run-time data folders; see install_paths.hpp.
#include "core/install_paths.hpp"

#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace drawbend {
namespace {

std::string find(const char* env, const char* installed, const char* built) {
  if (const char* e = std::getenv(env); e != nullptr && *e != '\0') return e;
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path d = exe.parent_path().parent_path() / "share" / "drawbend" / installed;
    if (fs::is_directory(d, ec)) return d.string();
  }
  return built;
}

}  // namespace

std::string data_dir() { return find("DRAWBEND_DATA_DIR", "data", DRAWBEND_BUILD_DATA_DIR); }
std::string figures_dir() { return find("DRAWBEND_FIGURES_DIR", "figures", DRAWBEND_BUILD_FIGURES_DIR); }

}  // namespace drawbend

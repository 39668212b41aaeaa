#include "core/provenance.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <mutex>

#include "core/csv.hpp"
#include "core/hash.hpp"

namespace drawbend {

namespace {
std::mutex& inputs_mutex() {
  static std::mutex m;
  return m;
}
std::vector<std::string>& inputs() {
  static std::vector<std::string> v;
  return v;
}
}  // namespace

void note_input(const std::string& path) {
  std::error_code ec;
  const auto abs = std::filesystem::weakly_canonical(std::filesystem::absolute(path, ec), ec);
  const std::string p = ec ? path : abs.string();
  const std::lock_guard<std::mutex> lock(inputs_mutex());
  auto& v = inputs();
  if (std::find(v.begin(), v.end(), p) == v.end()) v.push_back(p);
}

std::vector<std::string> inputs_read() {
  const std::lock_guard<std::mutex> lock(inputs_mutex());
  return inputs();
}

FileHash hash_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  FileHash h;
  if (!in) return h;
  h.exists = true;
  h.hash = fnv1a64({});
  char buf[1 << 16];
  while (in) {
    in.read(buf, sizeof buf);
    const auto n = static_cast<std::size_t>(in.gcount());
    h.hash = fnv1a64(std::string_view(buf, n), h.hash);
    h.bytes += n;
  }
  return h;
}

void write_provenance(const std::string& path, const std::string& version) {
  CsvWriter w({"kind", "path", "fnv1a64", "bytes"});
  w.comment("inputs this result was computed from and the binary that computed it (FNV-1a 64 of the contents)");
  w.row({"version", version, "", ""});
  std::error_code ec;
  const std::string exe = std::filesystem::read_symlink("/proc/self/exe", ec).string();
  if (!ec) {
    const FileHash h = hash_file(exe);
    w.row({"binary", exe, hex64(h.hash), std::to_string(h.bytes)});
  }
  for (const auto& p : inputs_read()) {
    const FileHash h = hash_file(p);
    if (h.exists) w.row({"input", p, hex64(h.hash), std::to_string(h.bytes)});
  }
  w.save(path);
}

std::vector<std::string> stale_inputs(const std::string& provenance_csv) {
  const CsvTable t = read_csv(provenance_csv);
  std::vector<std::string> stale;
  for (const auto& r : t.rows) {
    const std::string kind = t.text(r, "kind");
    if (kind != "input" && kind != "binary") continue;
    const std::string p = t.text(r, "path");
    const FileHash h = hash_file(p);
    if (!h.exists) stale.push_back(kind + " " + p + " is gone");
    else if (hex64(h.hash) != t.text(r, "fnv1a64"))
      stale.push_back(kind + " " + p + " has changed (recorded " + t.text(r, "fnv1a64") + ", now " + hex64(h.hash) + ")");
  }
  return stale;
}

}  // namespace drawbend

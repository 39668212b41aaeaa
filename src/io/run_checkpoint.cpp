#include "io/run_checkpoint.hpp"

#include <cstring>

#include "core/csv.hpp"
#include "core/file_gate.hpp"
#include "core/hash.hpp"

namespace drawbend::io {

namespace {

// Format 2 ends with the FNV-1a hash of every byte before it: a checkpoint
// damaged on disk or in transfer (a flipped byte) is refused, where format 1
// restarted from the damaged state with exit 0.
constexpr const char* kMagic = "drawbend-checkpoint 2\n";
constexpr const char* kMagicV1 = "drawbend-checkpoint 1\n";

void put_u64(std::string& o, std::uint64_t v) { o.append(reinterpret_cast<const char*>(&v), 8); }
void put_f64(std::string& o, double v) { o.append(reinterpret_cast<const char*>(&v), 8); }
void put_str(std::string& o, const std::string& s) {
  put_u64(o, s.size());
  o += s;
}

struct In {
  const std::string& d;
  const std::string& src;
  std::size_t pos;
  void need(std::uint64_t n) const {
    if (n > d.size() - pos) throw InputError(src + ": checkpoint is truncated (at byte " + std::to_string(pos) + ")");
  }
  std::uint64_t u64() {
    need(8);
    std::uint64_t v;
    std::memcpy(&v, d.data() + pos, 8);
    pos += 8;
    return v;
  }
  double f64() {
    need(8);
    double v;
    std::memcpy(&v, d.data() + pos, 8);
    pos += 8;
    return v;
  }
  std::string str() {
    const std::uint64_t n = u64();
    need(n);
    std::string s = d.substr(pos, n);
    pos += n;
    return s;
  }
};

}  // namespace

void write_checkpoint(const std::string& path, std::uint64_t deck_hash, const fe::Solver& s, const RunState& r) {
  std::string o = kMagic;
  put_u64(o, deck_hash);
  std::string state;
  s.save_state(state);
  put_str(o, state);
  put_u64(o, r.history_rows.size());
  for (const auto& row : r.history_rows) {
    put_u64(o, row.size());
    for (const auto& c : row) put_str(o, c);
  }
  put_f64(o, r.next_hist);
  put_f64(o, r.next_field);
  put_u64(o, static_cast<std::uint64_t>(static_cast<std::int64_t>(r.current_step)));
  put_u64(o, static_cast<std::uint64_t>(r.snap));
  put_u64(o, r.snapshots.size());
  for (const auto& [t, name] : r.snapshots) {
    put_f64(o, t);
    put_str(o, name);
  }
  put_u64(o, fnv1a64(o));
  write_file_atomic(path, o);
}

RunState read_checkpoint(const std::string& path, std::uint64_t deck_hash, fe::Solver& s) {
  std::string d = read_input(path, kMaxCheckpointBytes);  // core/file_gate.hpp
  if (d.compare(0, std::strlen(kMagicV1), kMagicV1) == 0)
    throw InputError(path + ": checkpoint of an older drawbend (format 1, without a checksum): run the deck from the start");
  if (d.compare(0, std::strlen(kMagic), kMagic) != 0)
    throw InputError(path + ": not a drawbend checkpoint (expected the header 'drawbend-checkpoint 2')");
  std::uint64_t sum = 0;
  if (d.size() < std::strlen(kMagic) + 8) throw InputError(path + ": checkpoint is truncated (at byte " + std::to_string(d.size()) + ")");
  std::memcpy(&sum, d.data() + d.size() - 8, 8);
  d.resize(d.size() - 8);
  if (sum != fnv1a64(d))
    throw InputError(path + ": checkpoint is damaged (its checksum does not match its contents): run the deck from the start");
  In in{d, path, std::strlen(kMagic)};
  const std::uint64_t h = in.u64();
  if (h != deck_hash)
    throw InputError(path + ": checkpoint was written for another deck (deck hash " + hex64(h) + ", this deck " +
                     hex64(deck_hash) + ")");
  s.load_state(in.str(), path);
  RunState r;
  const std::uint64_t rows = in.u64();
  for (std::uint64_t i = 0; i < rows; ++i) {
    const std::uint64_t n = in.u64();
    in.need(8 * n);
    std::vector<std::string> row;
    for (std::uint64_t k = 0; k < n; ++k) row.push_back(in.str());
    r.history_rows.push_back(std::move(row));
  }
  r.next_hist = in.f64();
  r.next_field = in.f64();
  r.current_step = static_cast<int>(static_cast<std::int64_t>(in.u64()));
  r.snap = static_cast<int>(in.u64());
  const std::uint64_t ns = in.u64();
  in.need(16 * ns);
  for (std::uint64_t i = 0; i < ns; ++i) {
    const double t = in.f64();
    r.snapshots.push_back({t, in.str()});
  }
  if (in.pos != d.size()) throw InputError(path + ": checkpoint has trailing data (another version?)");
  return r;
}

}  // namespace drawbend::io

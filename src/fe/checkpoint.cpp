// Checkpoint/restart of the explicit solver (members of fe::Solver).
//
// The state saved is everything a cycle reads that it did not compute itself
// in the same cycle: nodal positions and velocities; per element the stresses
// at both integration points, the material state (plastic strain, back
// stress...), the hourglass forces and tangent ratio and the stable step; tool
// offsets, velocities and forces; per contact node the tangential spring force
// and the friction law's state; the time, step index and time into the step,
// cycle, time steps, energies, and the slid offsets of rotation conditions.
// Quantities a cycle recomputes before use (corner forces, nodal forces,
// reactions) are not saved.  Doubles are stored as raw bytes, so a restarted
// run continues bit for bit.
//
// Layout: "drawbend-solver-state 3\n", the mesh's fingerprint (64 bits,
// fe::mesh_fingerprint), then a fixed sequence of blocks, each a 64-bit count
// followed by that many 8-byte values.  A count that does not match the
// solver being restored (another deck or mesh) is an error, and so is
// another fingerprint: the same counts on another numbering (format 1 had no
// fingerprint, and a structured block that fe::block_order numbers anew,
// since 2026-11-29, would have restored its state onto the wrong nodes).
#include <cstring>
#include <stdexcept>

#include "core/csv.hpp"
#include "core/hash.hpp"
#include "fe/solver.hpp"

namespace drawbend::fe {

namespace {

constexpr const char* kMagic = "drawbend-solver-state 3\n";
constexpr const char* kMagicV1 = "drawbend-solver-state 1\n";
constexpr const char* kMagicV2 = "drawbend-solver-state 2\n";
/// Doubles per contact node: area, normal force, pressure, depth, normal (3),
/// friction force (3), slip speed, surface, foot (3), accumulated slip, status.
constexpr std::size_t kContactValues = 17;

struct Writer {
  std::string& out;
  void raw(const void* p, std::size_t n) {
    if (n > 0) out.append(static_cast<const char*>(p), n);  // p may be null for an empty block
  }
  void count(std::uint64_t n) { raw(&n, 8); }
  void doubles(const double* p, std::size_t n) {
    count(n);
    raw(p, 8 * n);
  }
  void vec(const std::vector<double>& v) { doubles(v.data(), v.size()); }
  void vec3s(const std::vector<Vec3>& v) { doubles(v.empty() ? nullptr : v[0].data(), 3 * v.size()); }
};

struct Reader {
  const std::string& in;
  const std::string& source;
  std::size_t pos = 0;
  void raw(void* p, std::size_t n) {
    if (n > in.size() - pos) throw InputError(source + ": checkpoint is truncated (at byte " + std::to_string(pos) + ")");
    if (n == 0) return;  // p may be null for an empty block (memcpy must not get it)
    std::memcpy(p, in.data() + pos, n);
    pos += n;
  }
  std::uint64_t count() {
    std::uint64_t n = 0;
    raw(&n, 8);
    return n;
  }
  void doubles(double* p, std::size_t n, const char* what) {
    const std::uint64_t m = count();
    if (m != n)
      throw InputError(source + ": checkpoint does not match this case: " + what + " has " + std::to_string(m) +
                       " values, expected " + std::to_string(n) + " (another deck or mesh?)");
    raw(p, 8 * n);
  }
  void vec(std::vector<double>& v, const char* what) { doubles(v.data(), v.size(), what); }
  void vec3s(std::vector<Vec3>& v, const char* what) { doubles(v.empty() ? nullptr : v[0].data(), 3 * v.size(), what); }
};

}  // namespace

void Solver::save_state(std::string& out) const {
  out = kMagic;
  Writer w{out};
  w.count(mesh_fingerprint(m_.mesh));
  const double scalars[] = {t_, dt_, dt0_, last_dt_, static_cast<double>(cycle_), static_cast<double>(step_index_),
                            step_time_, step_t_start_};
  w.doubles(scalars, std::size(scalars));
  const double en[] = {en_.kinetic, en_.internal, en_.hourglass, en_.external_work, en_.friction, en_.contact_stored,
                       en_.damping, en_.initial_kinetic};
  w.doubles(en, std::size(en));
  double warned[kGuardIds];
  for (int k = 0; k < kGuardIds; ++k) warned[k] = warned_[k];
  w.doubles(warned, kGuardIds);
  for (const auto* v : {&x_, &y_, &z_, &vx_, &vy_, &vz_, &sig_, &state_, &hgq_, &hg_ratio_, &dt_elem_}) w.vec(*v);
  for (const auto* v : {&tool_offset_, &tool_vel_, &tool_force_, &slide_offset_}) w.vec3s(*v);
  for (std::size_t p = 0; p < contact_.size(); ++p) {
    std::vector<double> c;
    for (const ContactNode& n : contact_[p])
      c.insert(c.end(), {n.area, n.normal_force, n.pressure, n.depth, n.normal[0], n.normal[1], n.normal[2], n.ft[0],
                         n.ft[1], n.ft[2], n.slip_speed, static_cast<double>(n.surface), n.foot[0], n.foot[1], n.foot[2], n.slip,
                         static_cast<double>(n.status)});
    w.vec(c);
    w.vec(friction_state_[p]);
  }
}

void Solver::load_state(const std::string& in, const std::string& source) {
  if (in.compare(0, std::strlen(kMagicV1), kMagicV1) == 0)
    throw InputError(source + ": checkpoint of format 1, without the mesh's fingerprint (drawbend before 2026-11-29, "
                     "whose structured blocks may be numbered otherwise): run the deck again from the start");
  if (in.compare(0, std::strlen(kMagicV2), kMagicV2) == 0)
    throw InputError(source + ": checkpoint of format 2, without the contact nodes' accumulated slip (drawbend "
                     "before 2026-12-02): run the deck again from the start");
  if (in.compare(0, std::strlen(kMagic), kMagic) != 0)
    throw InputError(source + ": not a drawbend checkpoint (expected the header 'drawbend-solver-state 3')");
  Reader r{in, source, std::strlen(kMagic)};
  const std::uint64_t fp = r.count(), here = mesh_fingerprint(m_.mesh);
  if (fp != here)
    throw InputError(source + ": checkpoint does not match this case's mesh (fingerprint " + hex64(fp) + ", this mesh " +
                     hex64(here) + "): another mesh, or the same one numbered otherwise by another drawbend version");
  double scalars[8];
  r.doubles(scalars, 8, "the time and step counters");
  t_ = scalars[0];
  dt_ = scalars[1];
  dt0_ = scalars[2];
  last_dt_ = scalars[3];
  cycle_ = static_cast<long>(scalars[4]);
  step_index_ = static_cast<int>(scalars[5]);
  step_time_ = scalars[6];
  step_t_start_ = scalars[7];
  if (step_index_ < 0 || step_index_ > static_cast<int>(m_.steps.size()))
    throw InputError(source + ": checkpoint is at step " + std::to_string(step_index_) + ", but the case has " +
                     std::to_string(m_.steps.size()) + " steps");
  double en[8];
  r.doubles(en, 8, "the energies");
  en_ = {en[0], en[1], en[2], en[3], en[4], en[5], en[6], en[7]};
  double warned[kGuardIds];
  r.doubles(warned, kGuardIds, "the guard flags");
  for (int k = 0; k < kGuardIds; ++k) warned_[k] = warned[k] != 0;
  const char* names[] = {"x", "y", "z", "vx", "vy", "vz", "stress", "material state", "hourglass forces",
                         "hourglass ratio", "element time steps"};
  int k = 0;
  for (auto* v : {&x_, &y_, &z_, &vx_, &vy_, &vz_, &sig_, &state_, &hgq_, &hg_ratio_, &dt_elem_}) r.vec(*v, names[k++]);
  // Rotation offsets belong to the step the checkpoint is in.
  if (step_index_ < static_cast<int>(m_.steps.size()))
    slide_offset_.assign(m_.steps[step_index_].rotations.size(), Vec3{0, 0, 0});
  r.vec3s(tool_offset_, "tool offsets");
  r.vec3s(tool_vel_, "tool velocities");
  r.vec3s(tool_force_, "tool forces");
  r.vec3s(slide_offset_, "rotation offsets");
  for (std::size_t p = 0; p < contact_.size(); ++p) {
    std::vector<double> c(kContactValues * contact_[p].size());
    r.vec(c, "contact nodes");
    for (std::size_t i = 0; i < contact_[p].size(); ++i) {
      ContactNode& n = contact_[p][i];
      const double* q = &c[kContactValues * i];
      n.area = q[0];
      n.normal_force = q[1];
      n.pressure = q[2];
      n.depth = q[3];
      n.normal = {q[4], q[5], q[6]};
      n.ft = {q[7], q[8], q[9]};
      n.slip_speed = q[10];
      n.surface = static_cast<int>(q[11]);
      n.foot = {q[12], q[13], q[14]};
      n.slip = q[15];
      n.status = static_cast<int>(q[16]);
    }
    r.vec(friction_state_[p], "friction state");
  }
  if (r.pos != in.size()) throw InputError(source + ": checkpoint has trailing data (another version?)");
}

}  // namespace drawbend::fe

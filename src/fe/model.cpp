#include "fe/model.hpp"

#include <cmath>
#include <stdexcept>

namespace drawbend::fe {

namespace {
void unit(const Vec3& v, const std::string& what) {
  const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  if (std::abs(n - 1.0) > 1e-9) throw std::invalid_argument(what + " must be a unit vector");
}
}  // namespace

void Model::validate() const {
  mesh.validate();
  if (!material) throw std::invalid_argument("model '" + name + "': no material");
  if (!(dt_safety > 0 && dt_safety <= 1)) throw std::invalid_argument("dt_safety must lie in (0, 1]");
  if (!(mass_scaling >= 1)) throw std::invalid_argument("mass_scaling must be >= 1");
  if (!(target_dt >= 0)) throw std::invalid_argument("target_dt must be >= 0 s");
  if (!(hourglass >= 0)) throw std::invalid_argument("hourglass factor must be >= 0");
  if (steps.empty()) throw std::invalid_argument("model '" + name + "': no steps");
  for (const auto& t : tools) {
    for (std::size_t s = 0; s < t.surfaces.size(); ++s)
      t.surfaces[s].validate("tool '" + t.name + "' surface " + std::to_string(s));
    if (t.drive != Tool::Drive::fixed) unit(t.direction, "tool '" + t.name + "' direction");
    if (t.drive == Tool::Drive::force && !(t.mass > 0))
      throw std::invalid_argument("tool '" + t.name + "': a force-driven tool needs a mass > 0 t");
  }
  for (const auto& c : contacts) {
    mesh.face_set(c.faces);
    bool found = false;
    for (const auto& t : tools) found = found || t.name == c.tool;
    if (!found) throw std::invalid_argument("contact refers to unknown tool '" + c.tool + "'");
    if (!(c.penalty > 0)) throw std::invalid_argument("contact penalty factor must be > 0");
    if (!(c.damping >= 0 && c.damping <= 1)) throw std::invalid_argument("contact damping must lie in [0, 1] (fraction of critical)");
  }
  for (const auto& s : steps) {
    const std::string w = "step '" + s.name + "'";
    if (!(s.duration > 0)) throw std::invalid_argument(w + ": duration must be > 0 s");
    if (!(s.damping >= 0)) throw std::invalid_argument(w + ": damping must be >= 0 1/s");
    for (const auto& b : s.fixed) mesh.node_set(b.set);
    for (const auto& b : s.velocities) {
      mesh.node_set(b.set);
      unit(b.direction, w + " velocity direction");
      b.speed.validate(w.c_str());
    }
    for (const auto& b : s.rotations) {
      mesh.node_set(b.set);
      unit(b.axis, w + " rotation axis");
      if (b.slide != Vec3{0, 0, 0}) unit(b.slide, w + " rotation slide direction");
      b.omega.validate(w.c_str());
    }
    for (const auto& b : s.affine) {
      mesh.node_set(b.set);
      b.scale.validate(w.c_str());
    }
    for (const auto& f : s.forces) {
      mesh.node_set(f.set);
      unit(f.direction, w + " force direction");
      f.magnitude.validate(w.c_str());
    }
  }
}

ContactPair& Model::add_rigid_contact(const std::string& tool, const contact::Surface& surface, const std::string& faces,
                                      std::shared_ptr<friction::FrictionLaw> friction) {
  Tool t;
  t.name = tool;
  t.surfaces.push_back(surface);
  tools.push_back(t);
  ContactPair cp;
  cp.faces = faces;
  cp.tool = tool;
  cp.friction = std::move(friction);
  contacts.push_back(cp);
  return contacts.back();
}

}  // namespace drawbend::fe

#include "fe/contact_springs.hpp"

#include <algorithm>
#include <stdexcept>

#include "fe/model.hpp"

namespace drawbend::fe {

ContactSprings contact_springs(const Mesh& mesh, const NodeCorners& nc, const std::vector<Quad>& faces,
                               const std::vector<double>& x, const std::vector<double>& y,
                               const std::vector<double>& z, const std::string& face_set_name) {
  ContactSprings s;
  for (const auto& f : faces) s.nodes.insert(s.nodes.end(), f.begin(), f.end());
  std::sort(s.nodes.begin(), s.nodes.end());
  s.nodes.erase(std::unique(s.nodes.begin(), s.nodes.end()), s.nodes.end());
  const auto slot_of = [&](int node) {
    return static_cast<int>(std::lower_bound(s.nodes.begin(), s.nodes.end(), node) - s.nodes.begin());
  };
  s.length.assign(s.nodes.size(), 1e30);
  for (const auto& f : faces) {
    int owner = -1;  // the element with all four of the face's nodes
    for (int c = nc.start[f[0]]; c < nc.start[f[0] + 1] && owner < 0; ++c) {
      const int e = nc.corner[c] / 8;
      int hits = 0;
      for (int a = 0; a < 8; ++a)
        for (int q = 0; q < 4; ++q) hits += mesh.hex[e][a] == f[q];
      if (hits == 4) owner = e;
    }
    if (owner < 0) throw std::invalid_argument("contact: face set '" + face_set_name + "' has a face on no element");
    double ex[8], ey[8], ez[8];
    gather(x, y, z, mesh.hex[owner], ex, ey, ez);
    const double L = hex_volume(ex, ey, ez) / quad_area(x, y, z, f);
    for (int q = 0; q < 4; ++q) {
      double& len = s.length[slot_of(f[q])];
      len = std::min(len, L);
    }
  }
  for (const auto& f : faces)
    for (int q = 0; q < 4; ++q) s.face_slot.push_back(slot_of(f[q]));
  return s;
}

double spring_stiffness(const ContactSprings& s, const std::vector<Quad>& faces, const std::vector<double>& x,
                        const std::vector<double>& y, const std::vector<double>& z, double penalty,
                        double bulk_modulus) {
  std::vector<double> area(s.length.size(), 0.0);
  for (std::size_t f = 0; f < faces.size(); ++f)
    for (int q = 0; q < 4; ++q) area[s.face_slot[4 * f + q]] += 0.25 * quad_area(x, y, z, faces[f]);
  double k = 0;
  for (std::size_t i = 0; i < area.size(); ++i) k += penalty * bulk_modulus * area[i] / s.length[i];
  return k;
}

double tool_contact_stiffness(const Model& m, const std::string& tool) {
  const NodeCorners nc = NodeCorners::build(m.mesh);
  double k = 0;
  for (const auto& cp : m.contacts) {
    if (cp.tool != tool) continue;
    const auto& faces = m.mesh.face_set(cp.faces);
    const ContactSprings s = contact_springs(m.mesh, nc, faces, m.mesh.x, m.mesh.y, m.mesh.z, cp.faces);
    k += spring_stiffness(s, faces, m.mesh.x, m.mesh.y, m.mesh.z, cp.penalty, m.material->bulk_modulus());
  }
  return k;
}

}  // namespace drawbend::fe

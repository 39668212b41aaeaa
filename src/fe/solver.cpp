#include "fe/solver.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>

#include "fe/contact_springs.hpp"
#include "fe/element_view.hpp"
#include "fe/hex8.hpp"
#include "material/sheet_frame.hpp"

namespace drawbend::fe {

double Energies::balance_error() const {
  // The contact work on the sheet is part of external_work; friction and the
  // stored penalty energy are diagnostics of how that work splits.
  const double lhs = kinetic + internal + hourglass + damping;
  // Relative to the largest energy flow: where drawing work and frictional loss
  // nearly cancel, the net work is small and would exaggerate the error.
  const double scale = std::max({std::abs(external_work), std::abs(kinetic) + std::abs(internal) + std::abs(hourglass),
                                 std::abs(friction), std::abs(damping), initial_kinetic, 1e-30});
  return std::abs(lhs - external_work - initial_kinetic) / scale;
}

Solver::Solver(Model& model) : m_(model) {
  m_.validate();
  const Mesh& mesh = m_.mesh;
  const int n = mesh.num_nodes(), ne = mesh.num_elements();
  nc_ = NodeCorners::build(mesh);
  x_ = mesh.x;
  y_ = mesh.y;
  z_ = mesh.z;
  for (auto* v : {&vx_, &vy_, &vz_, &mass_, &ex_, &ey_, &ez_, &v0x_, &v0y_, &v0z_}) v->assign(n, 0.0);
  const auto& mat = *m_.material;
  // Two integration points per element (through the thickness): 12 stresses
  // and 2 material states each.
  sig_.assign(12 * ne, 0.0);
  state_.assign(static_cast<std::size_t>(ne) * 2 * mat.state_size(), 0.0);
  hgq_.assign(6 * ne, 0.0);
  hg_ratio_.assign(ne, 1.0);
  corner_.assign(8 * kCornerStride * static_cast<std::size_t>(ne), 0.0);
  // Node-major corner slots: node i's corners at slots nc_.start[i] .. start[i+1]-1,
  // in the order the nodal sum has always added them (ascending element, corner).
  corner_slot_.assign(8 * static_cast<std::size_t>(ne), 0);
  for (int k = 0; k < static_cast<int>(nc_.corner.size()); ++k) corner_slot_[nc_.corner[k]] = k;
  ie_inc_.assign(ne, 0.0);
  elem_partial_.assign(3 * static_cast<std::size_t>((ne + kSumChunk - 1) / kSumChunk), 0.0);
  node_partial_.assign(3 * static_cast<std::size_t>((n + kSumChunk - 1) / kSumChunk), 0.0);
  hg_inc_.assign(ne, 0.0);
  dt_elem_.assign(ne, 0.0);
  elem_mass_factor_.assign(ne, m_.mass_scaling);
  wave_speed_ = mat.wave_speed();
  // Lumped masses with mass scaling (uniform factor, then per element up to the target step).
  for (int e = 0; e < ne; ++e) {
    double ex[8], ey[8], ez[8];
    gather(x_, y_, z_, mesh.hex[e], ex, ey, ez);
    const double V = hex_volume(ex, ey, ez);
    HexGeometry g;
    if (!hex_geometry(ex, ey, ez, g)) throw std::invalid_argument("element " + std::to_string(e) + " is inverted");
    const double length = hex_stable_length(g);
    min_length_ = e == 0 ? length : std::min(min_length_, length);
    const double dt_e = length / wave_speed_ * std::sqrt(elem_mass_factor_[e]);
    if (m_.target_dt > 0 && m_.dt_safety * dt_e < m_.target_dt)
      elem_mass_factor_[e] *= std::pow(m_.target_dt / (m_.dt_safety * dt_e), 2);
    // Material state; an anisotropic material gets the sheet axes: the model's
    // rolling direction projected into the element's sheet plane (normal: its
    // third natural axis zeta, the thickness direction of the generated meshes).
    if (const int ns = mat.state_size(); ns > 0) {
      material::SheetAxes axes;
      if (mat.directional()) {
        try {
          axes = material::sheet_axes(m_.rolling_direction, {g.R[0][2], g.R[1][2], g.R[2][2]});
        } catch (const std::invalid_argument& ex) {
          throw std::invalid_argument("element " + std::to_string(e) + ": " + ex.what());
        }
      }
      for (int gp = 0; gp < 2; ++gp) mat.init_state(&state_[(2 * static_cast<std::size_t>(e) + gp) * ns], axes);
    }
    const double me = mat.density() * V;
    phys_mass_ += me;
    added_mass_ += me * (elem_mass_factor_[e] - 1.0);
    for (int a = 0; a < 8; ++a) mass_[mesh.hex[e][a]] += me * elem_mass_factor_[e] / 8.0;
  }
  elem_sqrt_mass_factor_.resize(elem_mass_factor_.size());
  for (std::size_t e = 0; e < elem_mass_factor_.size(); ++e) elem_sqrt_mass_factor_[e] = std::sqrt(elem_mass_factor_[e]);
  inv_mass_.resize(mass_.size());
  for (std::size_t i = 0; i < mass_.size(); ++i) inv_mass_[i] = 1.0 / mass_[i];
  // Contact pairs: unique slave nodes, tributary faces, penalty length scale.
  for (const auto& cp : m_.contacts) {
    const auto& faces = mesh.face_set(cp.faces);
    ContactSprings springs = contact_springs(mesh, nc_, faces, x_, y_, z_, cp.faces);  // fe/contact_springs.hpp
    const std::vector<int>& nodes = springs.nodes;
    std::vector<ContactNode> cn(nodes.size());
    for (std::size_t k = 0; k < nodes.size(); ++k) cn[k].node = nodes[k];
    face_slot_.push_back(std::move(springs.face_slot));
    slot_faces_.push_back(contact::slot_faces(face_slot_.back().data(), static_cast<int>(faces.size()),
                                              static_cast<int>(nodes.size())));
    face_area_scratch_.resize(std::max(face_area_scratch_.size(), faces.size()), 0.0);
    pair_faces_.push_back(&faces);
    pair_tool_.push_back(tool_index(m_, cp.tool));
    contact_.push_back(std::move(cn));
    contact_stiffness_len_.push_back(std::move(springs.length));
    contact_force_.emplace_back(nodes.size(), Vec3{0, 0, 0});
    const int ss = cp.friction ? cp.friction->state_size() : 0;
    friction_state_.emplace_back(nodes.size() * ss, 0.0);
    // Corotational texture axes: each node's reference face and initial RD, from the reference mesh
    // (only where a step turns friction on: the axes are used by friction alone).
    texture_ref_.emplace_back();
    const bool friction_used = std::any_of(m_.steps.begin(), m_.steps.end(), [](const Step& s) { return s.friction; });
    if (cp.friction && friction_used && cp.texture == ContactPair::Texture::corotational)
      texture_ref_.back() = contact::texture_refs(faces, mesh.x.data(), mesh.y.data(), mesh.z.data(), nodes,
                                                  m_.rolling_direction, cp.faces);
    for (auto& s : energy_scratch_) s.resize(std::max(s.size(), nodes.size()), 0.0);
  }
  tool_offset_.assign(m_.tools.size(), Vec3{0, 0, 0});
  tool_vel_.assign(m_.tools.size(), Vec3{0, 0, 0});
  tool_force_.assign(m_.tools.size(), Vec3{0, 0, 0});
  compute_dt();
  dt0_ = dt_;
  check_dt();
}

void Solver::check_dt() const {
  // A zero or non-finite step would make the run loop for ever at one time
  // (or produce NaN at once); it comes from a material or mesh value the
  // floating-point range cannot hold (E = 1e308: the wave speed overflows).
  if (dt_ > 0 && std::isfinite(dt_)) return;
  int worst = 0;  // the first element whose own step is not finite and > 0
  while (worst + 1 < m_.mesh.num_elements() && dt_elem_[worst] > 0 && std::isfinite(dt_elem_[worst])) ++worst;
  std::ostringstream os;
  os << "stable time step " << dt_ << " s of element " << worst << " (wave speed " << wave_speed_
     << " mm/s, mass factor " << elem_mass_factor_[worst] << ") at t = " << t_ << " s (cycle " << cycle_
     << "): the time step must be finite and > 0 (check the material's E and density, and the mesh)";
  throw NumericalFault(os.str());
}

void Solver::set_velocity(int node, const Vec3& v) {
  vx_.at(node) = v[0];
  vy_.at(node) = v[1];
  vz_.at(node) = v[2];
}

void Solver::set_stress(int element, const double s[6]) {
  for (int k = 0; k < 6; ++k) sig_.at(12 * element + k) = sig_.at(12 * element + 6 + k) = s[k];
}

std::vector<double> Solver::stress() const {
  const int ne = m_.mesh.num_elements();
  std::vector<double> s(6 * ne);
  for (int e = 0; e < ne; ++e)
    for (int k = 0; k < 6; ++k) s[6 * e + k] = 0.5 * (sig_[12 * e + k] + sig_[12 * e + 6 + k]);
  return s;
}

double Solver::plastic_strain(int e) const {
  const int ns = m_.material->state_size();
  const double* st = state_.data() + static_cast<std::size_t>(e) * 2 * ns;
  return 0.5 * (m_.material->plastic_strain(st) + m_.material->plastic_strain(st + ns));
}

void Solver::compute_dt() {
  const Mesh& mesh = m_.mesh;
  double dtmin = 1e30;
  for (int e = 0; e < mesh.num_elements(); ++e) {
    double ex[8], ey[8], ez[8];
    gather(x_, y_, z_, mesh.hex[e], ex, ey, ez);
    HexGeometry g;
    if (!hex_geometry(ex, ey, ez, g)) throw std::invalid_argument("element " + std::to_string(e) + " is inverted");
    dt_elem_[e] = hex_stable_length(g) / wave_speed_ * std::sqrt(elem_mass_factor_[e]);
    dtmin = std::min(dtmin, dt_elem_[e]);
  }
  dt_ = m_.dt_safety * dtmin;
}

double Solver::stable_dt() const { return dt_; }

}  // namespace drawbend::fe

// A sheet that starts inside a rigid tool (deck_overlap.hpp).
//
// Which nodes.  The nodes of each [[contact]] pair's face set against that
// pair's tool, the nodes the penalty contact pushes: a tool with no contact
// pair never acts on the sheet, so where it stands changes nothing.  Depth is
// measured without the contact's search distance (twice the element size, past
// which the solver ignores a node: a sheet deep inside a pin ran as if the pin
// were not there).
//
// The tolerance: a tenth of the node's element size normal to the contact face
// (L, the length of the pair's penalty springs, fe/contact_springs.hpp).  The
// decks this project writes start in contact on purpose (a strip wrapped on the
// pin, a blank under the holder, a block on the floor) with their contact nodes
// exactly on the tool's surface (deepest 0 mm in every builder's deck and every
// deck under data/cases/ and tests/, 2026-12-04).  The penalty's own gap, the
// depth at which a contact spring carries a pressure p, is d = p L / (alpha K):
// 100 MPa at the default alpha = 0.1 on aluminium (K = 69 GPa) is 1.4 % of L,
// so a deck written from a run's positions (or rounded to a few decimals)
// passes.  A start at a tenth of L already presses at 0.1 alpha K (690 MPa on
// aluminium, several times any flow stress of a sheet): that is not contact but
// overlap, and it is a fifth of the run's penetration guard ([guards]
// penetration = 0.5 x L by default), which would stop such a run in its first
// cycle with a numerical fault instead of naming the tool.
#include "io/deck_overlap.hpp"

#include <limits>

#include "contact/surface.hpp"
#include "core/csv.hpp"
#include "fe/contact_springs.hpp"

namespace drawbend::io {

namespace {

/// The fraction of the element size normal to the face a node may start inside a tool (see above).
constexpr double kOverlapFraction = 0.1;

const char* kind_name(contact::Surface::Kind k) {
  switch (k) {
    case contact::Surface::Kind::plane: return "plane";
    case contact::Surface::Kind::cylinder: return "cylinder";
    case contact::Surface::Kind::torus: return "torus";
  }
  return "surface";
}

/// The deepest start of one tool's contact nodes, measured in their allowed depth.
struct Overlap {
  double ratio = 0;  ///< depth / allowed depth of the worst node (> 1: refused)
  double depth = 0, allowed = 0, length = 0;
  int node = -1, surface = -1, count = 0;  ///< count: nodes beyond the tolerance
  std::string faces;
  fe::Vec3 x{0, 0, 0};
};

void scan_pair(const fe::Model& m, const fe::NodeCorners& nc, const fe::ContactPair& cp, const fe::Tool& tool,
               Overlap& o) {
  const auto& faces = m.mesh.face_set(cp.faces);
  const fe::ContactSprings s = fe::contact_springs(m.mesh, nc, faces, m.mesh.x, m.mesh.y, m.mesh.z, cp.faces);
  for (std::size_t k = 0; k < s.nodes.size(); ++k) {
    const int i = s.nodes[k];
    const fe::Vec3 x{m.mesh.x[i], m.mesh.y[i], m.mesh.z[i]};
    const double allowed = kOverlapFraction * s.length[k];
    bool beyond = false;
    for (std::size_t j = 0; j < tool.surfaces.size(); ++j) {
      double d = 0;
      fe::Vec3 n, foot;
      if (!contact::penetration(tool.surfaces[j], {0, 0, 0}, x, std::numeric_limits<double>::infinity(), d, n, foot) ||
          !(d > allowed))
        continue;
      beyond = true;
      if (d / allowed > o.ratio)
        o = {d / allowed, d, allowed, s.length[k], i, static_cast<int>(j), o.count, cp.faces, x};
    }
    o.count += beyond;
  }
}

}  // namespace

void check_initial_overlap(const DeckContext& c, const toml::table& root, const fe::Model& m) {
  if (m.contacts.empty() || m.mesh.num_nodes() == 0) return;
  const fe::NodeCorners nc = fe::NodeCorners::build(m.mesh);
  for (const auto& tool : m.tools) {
    Overlap o;
    for (const auto& cp : m.contacts)
      if (cp.tool == tool.name && m.mesh.face_sets.count(cp.faces)) scan_pair(m, nc, cp, tool, o);
    if (o.node < 0) continue;
    const toml::table* t = tool_table(root, tool.name);
    const std::string where = t ? c.where(*t, "tool '" + tool.name + "'") : c.path + ": tool '" + tool.name + "'";
    c.problems().add(where + ": the sheet starts inside this tool: node " + std::to_string(o.node) + " of face set '" +
                     o.faces + "' at (" + fmt(o.x[0]) + ", " + fmt(o.x[1]) + ", " + fmt(o.x[2]) + ") mm is " +
                     fmt(o.depth, 4) + " mm inside its " + kind_name(tool.surfaces[o.surface].kind) + " surface " +
                     std::to_string(o.surface + 1) + ", more than the " + fmt(o.allowed, 3) +
                     " mm allowed (a tenth of the " + fmt(o.length, 3) + " mm element under the face)" +
                     (o.count > 1 ? "; " + std::to_string(o.count - 1) + " more of its contact nodes are inside too" : "") +
                     ": move the tool (or the sheet) so that they start in contact or apart");
  }
}

}  // namespace drawbend::io

#pragma once
// The slave side of a penalty contact pair as springs, and the one rule for a
// force-driven tool's stiffness and mass.  Units: mm, N, t, s.
//
// Each slave node i carries a spring of stiffness (penalty contact, Ch. 2 of
// the thesis's FE model as we build it in contact/contact.cpp)
//     k_i = alpha K A_i / L_i                                        [N/mm]
// alpha the pair's penalty factor, K the bulk modulus [MPa], A_i the node's
// tributary area (a quarter of each contact face it is on) [mm^2], and L_i
// the element size normal to the face, V/A of the element owning the face,
// the smallest over the node's faces [mm].  A rigid tool pushed by a force
// rides on the sum k = sum_i k_i of its pairs' springs; explicit integration
// is stable for omega dt <= 2 (omega = sqrt(k / m)).
//
// Who uses it: the solver (the springs' lengths and the stability guard of a
// force-driven tool), and the case builders that size a tool's mass (the cup
// in sim/cup_case.cpp, the strip draw's die in sim/strip_draw_case.cpp) at
// omega dt = 0.5, i.e. m = 4 k dt^2.
#include <string>
#include <vector>

#include "fe/mesh.hpp"

namespace drawbend::fe {

struct Model;

/// One pair's slave nodes as springs.
struct ContactSprings {
  std::vector<int> nodes;      ///< slave nodes, sorted, unique
  std::vector<int> face_slot;  ///< per face corner (4 per face): the index into nodes
  std::vector<double> length;  ///< per node: L_i, the element size normal to its faces [mm]
};

/// The springs of face set `faces` on coordinates x, y, z.  Throws
/// std::invalid_argument if a face lies on no element.
ContactSprings contact_springs(const Mesh& mesh, const NodeCorners& nc, const std::vector<Quad>& faces,
                               const std::vector<double>& x, const std::vector<double>& y,
                               const std::vector<double>& z, const std::string& face_set_name);

/// k = sum_i alpha K A_i / L_i [N/mm], with the areas A_i on coordinates x, y, z
/// (summed face by face, then node by node: a fixed order).
double spring_stiffness(const ContactSprings& s, const std::vector<Quad>& faces, const std::vector<double>& x,
                        const std::vector<double>& y, const std::vector<double>& z, double penalty,
                        double bulk_modulus);

/// A tool's contact stiffness over all its contact pairs, on the model's
/// reference mesh [N/mm].  0 if the tool has no contact pair.
double tool_contact_stiffness(const Model& m, const std::string& tool);

/// The mass [t] that puts a rigid tool on stiffness k [N/mm] at omega dt = 0.5: 4 k dt^2.
inline double tool_mass_half_omega_dt(double k, double dt) { return 4.0 * k * dt * dt; }

}  // namespace drawbend::fe

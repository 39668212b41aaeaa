// Chapter 2, the strip's fields at the end of the draw (mu = 0.1), read back
// from the runs' last ParaView snapshots (sim/strip_fields.hpp):
//   - Fig. 2.8: the section of the strip at mid-wrap, on both meshes: does the
//     strip edge lift off the pin?
//   - Figs. 2.15 and 2.16: the longitudinal stress and longitudinal plastic
//     strain through the thickness along the strip (centre row of elements).
//   - Fig. 2.13's inside curve (element layer nearest the pin), and Sec. 2.3.2:
//     the outside strain rises at the inlet, the inside strain at the outlet
//     (the mechanism behind Fig. 2.13), checked on both meshes.
#include <cmath>
#include <sstream>

#include "ch2_steps.hpp"
#include "io/deck.hpp"
#include "sim/strip_fields.hpp"

namespace ch2 {

using namespace drawbend;

namespace {

/// Mean longitudinal log strain of the centre-row elements of one layer
/// (depth within half a layer of `depth`) whose position lies in [a, b] mm.
double layer_mean(const std::vector<sim::StripElement>& els, double depth, double half_layer, double a, double b) {
  double sum = 0;
  int n = 0;
  const double y_centre = els.empty() ? 0 : els.front().y0;  // sorted by y0: the centre row first
  for (const auto& e : els)
    if (std::abs(e.y0 - y_centre) < 1e-6 && std::abs(e.depth - depth) < half_layer && e.s >= a && e.s <= b)
      sum += e.eps_L, ++n;
  return n > 0 ? sum / n : NAN;
}

/// The two runs' last snapshots and what the steps share.
struct Fields {
  sim::DrawBendSpec s;      ///< the chapter mesh's run
  double Lw = 0;            ///< wrap length [mm]
  double E = 0, nu = 0;     ///< the runs' elasticity [MPa, -]
  sim::StripFields f, g;    ///< chapter mesh, finer mesh
};

Fields read_fields(const sim::DrawBendResult& fr, const sim::DrawBendResult& gr) {
  Fields F;
  F.s = fr.spec;
  F.Lw = sim::wrap_length(F.s);
  const io::Deck deck = io::read_deck(fr.dir + "/deck.toml");
  F.E = deck.model.material->youngs_modulus(), F.nu = deck.model.material->poisson_ratio();
  F.f = sim::read_fields_vtu(sim::last_fields_vtu(fr.dir));
  F.g = sim::read_fields_vtu(sim::last_fields_vtu(gr.dir));
  return F;
}

/// Fig. 2.8: the node plane nearest mid-wrap (45 deg), as polylines of the
/// mesh (layers across the width, then columns through the thickness), one
/// gnuplot index per mesh; h = distance from the pin surface.
void mid_wrap_section(study::Chapter& c, const Fields& F) {
  const sim::DrawBendSpec& s = F.s;
  const sim::StripFields &f = F.f, &g = F.g;
  std::ostringstream o;
  o << "# section of the strip nearest mid-wrap at the end of the draw, mu = 0.1 (Fig. 2.8)\n"
    << "# index 0: chapter mesh, index 1: finer mesh; blocks: layers, then columns of nodes\n"
    << "# y_mm (current, across the half width), h_mm (current radial distance from the pin surface)\n";
  for (const auto* run : {&f, &g}) {
    const sim::StripSection sec = sim::section_at(*run, s, 45.0);
    const bool chapter_mesh = run == &f;
    // Layers: nodes of one reference z (sorted by z0, then y0).
    for (std::size_t i = 0; i < sec.nodes.size(); ++i) {
      if (i > 0 && std::abs(sec.nodes[i].z0 - sec.nodes[i - 1].z0) > 1e-6) o << "\n";
      o << fmt(sec.nodes[i].y, 6) << " " << fmt(sec.nodes[i].h, 6) << "\n";
    }
    o << "\n";
    // Columns: nodes of one reference y.
    std::vector<double> ys;
    for (const auto& q : sec.nodes)
      if (std::abs(q.z0 - sec.nodes.front().z0) < 1e-6) ys.push_back(q.y0);
    for (double y0 : ys) {
      for (const auto& q : sec.nodes)
        if (std::abs(q.y0 - y0) < 1e-6) o << fmt(q.y, 6) << " " << fmt(q.h, 6) << "\n";
      o << "\n";
    }
    o << "\n";
    // The inside surface (lowest layer): centre and edge clearance from the pin.
    const auto& centre = sec.nodes.front();
    const auto* edge = &centre;
    for (const auto& q : sec.nodes)
      if (std::abs(q.z0 - centre.z0) < 1e-6 && q.y0 > edge->y0) edge = &q;
    const std::string sfx = chapter_mesh ? "" : "_fine";
    c.value("section_deg" + sfx, fmt_fixed(sec.angle_deg, 1), "deg");
    c.value("section_centre_gap" + sfx, fmt_fixed(1000 * centre.h, 1), "µm");
    c.value("section_edge_gap" + sfx, fmt_fixed(1000 * edge->h, 1), "µm");
  }
  write_file_atomic(c.out("tables/section_mid_wrap.dat"), o.str());
  c.plot("strip_section", "fig_2_8",
         {{"datafile", c.out("tables/section_mid_wrap.dat")}, {"thickness", fmt(s.thickness)}});
}

/// Figs. 2.15 and 2.16: the centre row of elements of the chapter mesh; returns its elements.
std::vector<sim::StripElement> centre_row_fields(study::Chapter& c, const Fields& F) {
  const sim::DrawBendSpec& s = F.s;
  const double Lw = F.Lw, E = F.E, nu = F.nu;
  const sim::StripFields& f = F.f;
  const auto els = sim::strip_elements(f, s, E, nu);
  auto w = c.table({"position_mm", "length_mm", "depth", "layer", "sigma_L_MPa", "eps_L", "eps_p_L", "eps_p_eq"},
                   "centre-row elements at the end of the draw (mu = 0.1, chapter mesh): position of the centroid "
                   "along the strip from the entry tangent (wrap length " + fmt(Lw, 4) + " mm), its extent along the strip, "
                   "reference depth (0 = pin side, 1 = free side), layer thickness as a fraction, longitudinal "
                   "stress, longitudinal log strain, longitudinal plastic strain (log strain less the elastic part "
                   "with E = " + fmt(E) + " MPa, nu = " + fmt(nu) + ") and the equivalent plastic strain");
  const double layer = 1.0 / s.through;
  for (const auto& e : els)
    if (std::abs(e.y0 - els.front().y0) < 1e-6)
      w.row({fmt(e.s, 6), fmt(e.ds, 5), fmt(e.depth, 5), fmt(layer, 5), fmt(e.sigma_L, 6), fmt(e.eps_L, 6),
             fmt(e.eps_pL, 6), fmt(e.eps_p, 6)});
  c.save(w, "strip_fields");
  c.plot("strip_field", "fig_2_15", {{"datafile", c.out("tables/strip_fields.csv")}, {"column", "5"},
                                     {"wrapfile", fmt(Lw, 5)},
                                     {"title_text", "Longitudinal stress, centre row, μ = 0.1 (Fig. 2.15)"},
                                     {"cb_text", "Longitudinal stress (MPa)"}});
  c.plot("strip_field", "fig_2_16", {{"datafile", c.out("tables/strip_fields.csv")}, {"column", "7"},
                                     {"wrapfile", fmt(Lw, 5)},
                                     {"title_text", "Longitudinal plastic strain, centre row, μ = 0.1 (Fig. 2.16)"},
                                     {"cb_text", "Longitudinal plastic strain"}});
  return els;
}

/// Fig. 2.13's inside curve: the longitudinal log strain of the element
/// layer nearest the pin, centre row, at the end of the draw, on both meshes
/// (the tracked sections of the history follow the outside surface only).
void inside_strain(study::Chapter& c, const Fields& F, const std::vector<sim::StripElement>& els) {
  const sim::DrawBendSpec& s = F.s;
  const double E = F.E, nu = F.nu;
  const sim::StripFields &f = F.f, &g = F.g;
  for (const auto* run : {&f, &g}) {
    const bool chapter_mesh = run == &f;
    auto lt = c.table({"position_mm", "inside_strain"},
                      std::string("longitudinal log strain of the element layer nearest the pin, centre row, end of "
                                  "the draw (mu = 0.1), ") + (chapter_mesh ? "chapter mesh" : "finer mesh") +
                          ", from the last snapshot; position of the element centroid from the entry tangent [mm]");
    const auto el = chapter_mesh ? els : sim::strip_elements(*run, s, E, nu);
    for (const auto& e : el)
      if (std::abs(e.y0 - el.front().y0) < 1e-6 && e.depth < 1.0 / s.through) lt.row({fmt(e.s, 6), fmt(e.eps_L, 6)});
    c.save(lt, chapter_mesh ? "inside_strain" : "inside_strain_fine");
  }
}

/// Sec. 2.3.2: the outside strain rises at the inlet, the inside strain at the outlet.
void strain_rise_claim(study::Chapter& c, const Fields& F) {
  const sim::DrawBendSpec& s = F.s;
  const double Lw = F.Lw, E = F.E, nu = F.nu;
  const sim::StripFields &f = F.f, &g = F.g;
  // Sec. 2.3.2 (Fig. 2.13): "the strain increase was concentrated at the
  // inlet region of outside surface and at the outlet region of inside
  // surface".  Stated before the run: the mean longitudinal log strain of the
  // outer and inner element layers of the centre row over three windows,
  // upstream (-0.5 to -0.2 wrap lengths from the entry tangent), in the
  // contact (0.3 to 0.7) and downstream (1.2 to 1.5); the windows keep 0.2
  // wrap lengths (two elements of the chapter mesh) clear of each tangent,
  // where bending is spread over an element.  The claim holds if, on both
  // meshes, the outside layer's rise across the inlet is positive and larger
  // than its change across the outlet, and the inside layer's rise across the
  // outlet is positive and larger than its change across the inlet.
  auto claim = [&](const sim::StripFields& fields, const std::string& sfx) {
    const auto el = sim::strip_elements(fields, s, E, nu);
    const double half = 0.5 / s.through, out = 1 - half, in = half;
    auto m = [&](double depth, double a, double b) { return layer_mean(el, depth, half, a * Lw, b * Lw); };
    const double o_in = m(out, 0.3, 0.7) - m(out, -0.5, -0.2), o_out = m(out, 1.2, 1.5) - m(out, 0.3, 0.7);
    const double i_in = m(in, 0.3, 0.7) - m(in, -0.5, -0.2), i_out = m(in, 1.2, 1.5) - m(in, 0.3, 0.7);
    c.value("rise_outside_inlet" + sfx, fmt_fixed(100 * o_in, 2), "%");
    c.value("rise_outside_outlet" + sfx, fmt_fixed(100 * o_out, 2), "%");
    c.value("rise_inside_inlet" + sfx, fmt_fixed(100 * i_in, 2), "%");
    c.value("rise_inside_outlet" + sfx, fmt_fixed(100 * i_out, 2), "%");
    const bool ok = o_in > 0 && o_in > o_out && i_out > 0 && i_out > i_in;
    const std::string txt = "outside " + fmt(100 * o_in, 3) + " % at the inlet, " + fmt(100 * o_out, 3) +
                            " % at the outlet; inside " + fmt(100 * i_in, 3) + " % at the inlet, " +
                            fmt(100 * i_out, 3) + " % at the outlet";
    return std::make_pair(ok, txt);
  };
  const auto a = claim(f, ""), b = claim(g, "_fine");
  c.checks().claim(study::Kind::simulated, "ch2.fe.strain_rise_inlet_outside_outlet_inside",
                   "outside strain rises at the inlet, inside strain at the outlet, both meshes (Sec. 2.3.2, Fig. 2.13)",
                   a.first && b.first,
                   "chapter mesh: " + a.second + "; finer mesh: " + b.second);
}

}  // namespace

void field_figures(study::Chapter& c, const sim::DrawBendResult& fr, const sim::DrawBendResult& gr) {
  const Fields F = read_fields(fr, gr);
  mid_wrap_section(c, F);
  const std::vector<sim::StripElement> els = centre_row_fields(c, F);
  inside_strain(c, F, els);
  strain_rise_claim(c, F);
}

}  // namespace ch2

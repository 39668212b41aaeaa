// The identified friction model; see friction_model.hpp.
#include "loop/friction_model.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <sstream>

#include <Eigen/Dense>

#include "core/quote.hpp"
#include "core/csv.hpp"

namespace drawbend::loop {

namespace {


std::vector<std::string> split_cell(const std::string& c) {
  std::vector<std::string> out;
  size_t a = 0;
  for (;;) {
    const size_t b = c.find(" | ", a);
    out.push_back(c.substr(a, b == std::string::npos ? std::string::npos : b - a));
    if (b == std::string::npos) break;
    a = b + 3;
  }
  return out;
}

const Param* find_param(const Fit& f, const std::string& name) {
  for (const auto& p : f.params)
    if (p.name == name) return &p;
  return nullptr;
}

}  // namespace

std::string lubricant_tag(const std::string& s) {
  std::string o;
  for (char c : s) o += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return o;
}

namespace {

// Least-squares nodal values on the given domain (rank-aware: min-norm).
analysis::FrictionSurface fit_nodes(const std::vector<double>& p, const std::vector<double>& v,
                                    const std::vector<double>& mu, analysis::FrictionSurface s, bool with_speed,
                                    double& rms) {
  const int n = static_cast<int>(p.size());
  const int q = with_speed ? 9 : 3;
  Eigen::MatrixXd A(n, q);
  Eigen::VectorXd b(n);
  for (int k = 0; k < n; ++k) {
    const auto N = analysis::nine_node_shape(s.xi(p[k]), with_speed ? s.eta(v[k]) : 0.0);
    if (with_speed)
      for (int j = 0; j < 9; ++j) A(k, j) = N[j];
    else
      for (int i = 0; i < 3; ++i) A(k, i) = N[3 * i] + N[3 * i + 1] + N[3 * i + 2];  // constant along eta
    b[k] = mu[k];
  }
  const Eigen::VectorXd x = A.completeOrthogonalDecomposition().solve(b);
  for (int k = 0; k < 9; ++k) s.mu[k] = with_speed ? x[k] : x[k / 3];
  rms = n ? std::sqrt((A * x - b).squaredNorm() / n) : 0.0;
  return s;
}

}  // namespace

FrictionModel identify_friction(const Design& d, const LoopResult& r) {
  FrictionModel m;
  const Fit& f = r.final_fit;
  for (const auto& c : d.cells) {
    const auto parts = split_cell(c);
    std::string speed = "all (continuous: see effects)";
    for (const auto& s : parts)
      if (s.find("mm/s") != std::string::npos) speed = s;
    const Param* a1 = find_param(f, "a1 [" + c + "] (1/MPa)");
    for (const char* dir : {"RD", "TD"}) {
      const Param* mu = find_param(f, std::string("mu_") + dir + " [" + c + "]");
      if (!mu) continue;
      FrictionCellRow row{parts[0], speed, dir, mu->value, mu->se, a1 ? a1->value : 0.0, a1 ? a1->se : 0.0, a1 != nullptr};
      m.cells.push_back(row);
    }
  }
  for (const auto& p : f.params)
    if (p.name.rfind("bending", 0) == 0) m.bending.push_back(p);
  // Surfaces per lubricant.
  std::set<std::string> lubs;
  for (size_t i = 0; i < d.rows.size(); ++i)
    if (!d.rows[i].rotating) lubs.insert(d.data->rows[i].lubricant);
  for (const auto& lub : lubs) {
    FittedSurface fs;
    fs.lubricant = lub;
    std::vector<double> P[2], V[2], MU[2];
    for (size_t i = 0; i < d.rows.size(); ++i) {
      const Row& row = d.rows[i];
      if (row.rotating || d.data->rows[i].lubricant != lub || std::isnan(f.b0[row.pin])) continue;
      for (int k = 0; k < 2; ++k) {
        const bool has = k == 0 ? d.cell_rd[row.cell] : d.cell_td[row.cell];
        if (!has) continue;
        double p = 0;
        const double mu = predict_mu_at(d, f, static_cast<int>(i), k == 0 ? 0.0 : M_PI / 2, &p);
        if (!std::isfinite(mu) || !std::isfinite(p)) continue;
        P[k].push_back(p), V[k].push_back(d.data->rows[i].speed_mm_s), MU[k].push_back(mu);
      }
    }
    if (P[0].empty() && P[1].empty()) continue;
    analysis::FrictionSurface dom;
    double plo = INFINITY, phi = -INFINITY, vlo = INFINITY, vhi = -INFINITY;
    std::set<double> speeds;
    for (int k = 0; k < 2; ++k)
      for (size_t j = 0; j < P[k].size(); ++j) {
        plo = std::min(plo, P[k][j]), phi = std::max(phi, P[k][j]);
        vlo = std::min(vlo, V[k][j]), vhi = std::max(vhi, V[k][j]);
        speeds.insert(V[k][j]);
      }
    fs.speeds = static_cast<int>(speeds.size());
    if (!(phi > plo)) plo = std::max(0.0, plo - 1), phi = phi + 1;
    if (!(vhi > vlo)) vlo = 0.9 * vlo, vhi = 1.1 * vhi;
    dom.p_min = plo, dom.p_max = phi, dom.v_min = vlo, dom.v_max = vhi;
    const bool with_speed = fs.speeds >= 3;
    fs.note = with_speed ? "fitted over " + std::to_string(fs.speeds) + " speeds"
                         : "only " + std::to_string(fs.speeds) + " speed(s): speed dependence not identified, the "
                           "surface is constant in v";
    for (int k = 0; k < 2; ++k) {
      double rms = 0;
      analysis::FrictionSurface s = dom;
      if (!P[k].empty()) s = fit_nodes(P[k], V[k], MU[k], dom, with_speed, rms);
      else {
        s.mu.fill(std::nan(""));
        fs.note += std::string("; no ") + (k == 0 ? "RD" : "TD") + " rows";
      }
      (k == 0 ? fs.rd : fs.td) = s;
      (k == 0 ? fs.rms_rd : fs.rms_td) = rms;
      fs.rows += static_cast<int>(P[k].size());
    }
    // A direction without rows takes the other's nodes (stated in the note).
    if (P[0].empty()) fs.rd = fs.td, fs.rd_copied = true;
    if (P[1].empty()) fs.td = fs.rd, fs.td_copied = true;
    m.surfaces.push_back(fs);
  }
  return m;
}

std::string write_friction_outputs(const Design& d, const LoopResult& r, const FrictionModel& m,
                                   const std::string& out) {
  namespace fs = std::filesystem;
  fs::create_directories(out + "/tables");
  std::ostringstream md;
  CsvWriter t({"lubricant", "speed", "direction", "mu0", "mu0_se", "a1_per_MPa", "a1_se", "a1_identified"});
  t.comment(" identified friction model: mu(p) = mu0 + a1 p per lubricant x speed x direction (value, one standard "
            "error); a1 = 0 when the loop added no pressure effect; bending: " + r.bending);
  md << "\n## Identified friction model\n\nmu(p) = mu0 + a1 p per cell (± one standard error); a1 is 0 and marked "
        "'not identified' unless the loop added the pressure effect. Other added effects multiply mu (see 'Added "
        "effects'). Bending force: " << r.bending << ".\n\n| lubricant | speed | direction | mu0 | a1 (1/MPa) |\n"
        "|---|---|---|---|---|\n";
  for (const auto& c : m.cells) {
    t.row({c.lubricant, c.speed, c.direction, fmt(c.mu0, 5), fmt(c.mu0_se, 3), fmt(c.a1, 5), fmt(c.a1_se, 3),
           c.a1_identified ? "yes" : "no"});
    md << "| " << c.lubricant << " | " << c.speed << " | " << c.direction << " | " << fmt(c.mu0, 4) << " ± "
       << fmt(c.mu0_se, 2) << " | "
       << (c.a1_identified ? fmt(c.a1, 4) + " ± " + fmt(c.a1_se, 2) : std::string("0 (not identified)")) << " |\n";
  }
  t.save(out + "/tables/friction_model.csv");
  CsvWriter b({"parameter", "value", "se", "unit"});
  b.comment(" bending force per pin, F_B = b0 + b1 F_back (or constant); " + r.bending);
  md << "\nBending line per pin:\n\n| parameter | value ± se |\n|---|---|\n";
  for (const auto& p : m.bending) {
    b.row({p.name, fmt(p.value, 6), fmt(p.se, 3), p.unit});
    md << "| " << p.name << " | " << fmt(p.value, 5) << " ± " << fmt(p.se, 2) << " " << p.unit << " |\n";
  }
  for (size_t k = 0; k < d.pins.size(); ++k)
    if (!std::isnan(d.bend_fallback[k])) {
      b.row({"assumed F_B " + fmt(d.pins[k]) + " mm", fmt(d.bend_fallback[k], 6), "", "N"});
      md << "| assumed F_B " << fmt(d.pins[k]) << " mm (no rotating rows) | " << fmt(d.bend_fallback[k], 5)
         << " N |\n";
    }
  b.save(out + "/tables/bending_lines.csv");
  md << "\n## Nine-node surface mu(p, v) (Chapter 6, Eqs. 6.1-6.3) fitted to these data\n\n";
  for (size_t k = 0; k < m.surfaces.size(); ++k) {
    const FittedSurface& s = m.surfaces[k];
    const std::string tag = k == 0 ? "" : "_" + lubricant_tag(s.lubricant);
    const std::string nodes = "friction_surface_nodes" + tag + ".csv";
    CsvWriter n({"node", "mu_RD", "mu_TD"});
    n.comment(" nine-node surface (Eq. 6.1 numbering), lubricant " + s.lubricant + ", domain p " +
              fmt(s.rd.p_min, 5) + "-" + fmt(s.rd.p_max, 5) + " MPa, v " + fmt(s.rd.v_min, 5) + "-" +
              fmt(s.rd.v_max, 5) + " mm/s; " + s.note);
    for (int j = 0; j < 9; ++j) n.row({std::to_string(j + 1), fmt(s.rd.mu[j], 8), fmt(s.td.mu[j], 8)});
    n.save(out + "/" + nodes);
    std::ostringstream toml;
    toml << "# drawbend loop: friction model identified from " << d.data->path << ", lubricant " << s.lubricant
         << "\n# bending: " << r.bending << "\n# " << s.note << "; fit RMS of mu: RD " << fmt(s.rms_rd, 3) << ", TD "
         << fmt(s.rms_td, 3) << "\n# Use in a deck: copy " << nodes << " next to it and add, under [[contact]],\n"
         << "#   friction = { law = \"surface\", nodes = \"" << nodes << "\", p_min = " << fmt(s.rd.p_min, 8)
         << ", p_max = " << fmt(s.rd.p_max, 8) << ", v_min = " << fmt(s.rd.v_min, 8) << ", v_max = "
         << fmt(s.rd.v_max, 8) << ", interval = 100 }\n"
         << "# (or this file's [friction] table as [contact.friction]); outside the domain the solver clamps.\n"
         << "# Export: drawbend export friction_model" << tag << ".toml --to lsdyna|openradioss|abaqus --parts SHEET,TOOL\n\n[friction]\n"
         << "law = \"surface\"\nnodes = \"" << nodes << "\"\np_min = " << fmt(s.rd.p_min, 8) << "\np_max = "
         << fmt(s.rd.p_max, 8) << "\nv_min = " << fmt(s.rd.v_min, 8) << "\nv_max = " << fmt(s.rd.v_max, 8)
         << "\ninterval = 100\n\n# where it came from (read by `drawbend export` for the exported files' headers)\n[model]\n"
         << "data = " << string_literal(d.data->path) << "\nlubricant = " << string_literal(s.lubricant)
         << "\ntd_copied_from_rd = " << (s.td_copied ? "true" : "false") << "\nrd_copied_from_td = "
         << (s.rd_copied ? "true" : "false") << "\n";
    write_file_atomic(out + "/friction_model" + tag + ".toml", toml.str());
    md << "Lubricant " << s.lubricant << " (`friction_model" << tag << ".toml`, `" << nodes << "`): domain p "
       << fmt(s.rd.p_min, 4) << "–" << fmt(s.rd.p_max, 4) << " MPa (the rows' force-weighted map pressures), v "
       << fmt(s.rd.v_min, 4) << "–" << fmt(s.rd.v_max, 4) << " mm/s; " << s.note << "; fit RMS of mu " << fmt(s.rms_rd, 2)
       << " (RD), " << fmt(s.rms_td, 2) << " (TD).\n\n| node | mu_RD | mu_TD |\n|---|---|---|\n";
    for (int j = 0; j < 9; ++j) md << "| " << j + 1 << " | " << fmt(s.rd.mu[j], 4) << " | " << fmt(s.td.mu[j], 4) << " |\n";
    md << "\n";
    for (int dir = 0; dir < 2; ++dir) {  // grids for the surface plots
      const analysis::FrictionSurface& S = dir == 0 ? s.rd : s.td;
      std::ostringstream g;
      g << "# p_MPa v_mm_s mu (" << (dir == 0 ? "RD" : "TD") << ", lubricant " << s.lubricant << ")\n";
      for (int a = 0; a <= 20; ++a) {
        for (int c = 0; c <= 20; ++c) {
          const double p = S.p_min + (S.p_max - S.p_min) * a / 20, v = S.v_min + (S.v_max - S.v_min) * c / 20;
          g << fmt(p, 6) << " " << fmt(v, 6) << " " << fmt(S(p, v), 6) << "\n";
        }
        g << "\n";
      }
      write_file_atomic(out + "/tables/surface" + tag + (dir == 0 ? "_RD" : "_TD") + ".dat", g.str());
    }
  }
  return md.str();
}

}  // namespace drawbend::loop

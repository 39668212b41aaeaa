// Loop outputs; see report.hpp.
#include "loop/report.hpp"

#include <algorithm>

#include "loop/friction_model.hpp"

#include <cmath>
#include <filesystem>
#include <iostream>
#include <cctype>
#include <sstream>

namespace drawbend::loop {

namespace fs = std::filesystem;

CsvWriter candidates_table(const LoopResult& r) {
  CsvWriter w({"round", "rank", "candidate", "kind", "dof", "permuted", "ess_N2", "p_value", "permutations",
               "decision", "cv_reduction", "significant"});
  w.comment(" candidates ranked on held-out residuals (N); p from the blocked permutation test; cv_reduction = "
            "fractional SSE reduction of the probe under grouped cross-validation (" + r.cv_mode + ")");
  for (size_t k = 0; k < r.rankings.size(); ++k)
    for (size_t i = 0; i < r.rankings[k].size(); ++i) {
      const auto& c = r.rankings[k][i];
      w.row({std::to_string(k + 1), std::to_string(i + 1), c.name, c.kind, std::to_string(c.dof), c.permuted,
             fmt(c.stat, 6), fmt(c.p_value, 4), std::to_string(c.n_perm), c.decision, fmt(c.cv_reduction, 4),
             c.significant ? "yes" : "no"});
    }
  return w;
}

CsvWriter effects_table(const LoopResult& r) {
  CsvWriter w({"step", "variable", "effect", "parameter", "value", "se"});
  w.comment(" effects added by the loop; value +- one standard error from s^2 (J^T J)^-1 of the full-data refit");
  for (size_t k = 0; k < r.steps.size(); ++k)
    for (const auto& p : r.steps[k].params)
      w.row({std::to_string(k + 1), r.steps[k].variable, r.steps[k].effect, p.name, fmt(p.value, 5), fmt(p.se, 3)});
  return w;
}

CsvWriter steps_table(const LoopResult& r) {
  CsvWriter w({"step", "variable", "effect", "p_value", "threshold", "rms_before_N", "rms_after_N", "max_before_N",
               "max_after_N"});
  w.comment(" held-out (grouped cross-validation: " + r.cv_mode + ") error of the outlet force before and after each step");
  for (size_t k = 0; k < r.steps.size(); ++k) {
    const Step& s = r.steps[k];
    w.row({std::to_string(k + 1), s.variable, s.effect, fmt(s.p_value, 4), fmt(s.threshold, 3), fmt(s.rms_before, 5),
           fmt(s.rms_after, 5), fmt(s.max_before, 5), fmt(s.max_after, 5)});
  }
  return w;
}

CsvWriter residuals_table(const Design& d, const LoopResult& r) {
  std::vector<std::string> h = {"line", "test_id", "pin", "resid_before_N", "resid_after_N"};
  // A candidate named like a fixed column (the categorical candidate "pin", the
  // pin diameter as a group) gets "_candidate": a column is never named twice.
  for (const auto& c : r.candidates)
    h.push_back(std::find(h.begin(), h.begin() + 5, c.name) != h.begin() + 5 ? c.name + "_candidate" : c.name);
  CsvWriter w(h);
  w.comment(" held-out residual (measured - predicted outlet force, N) of the base model and of the final model;"
            " categorical candidates as level index");
  for (size_t i = 0; i < d.rows.size(); ++i) {
    const Sample& s = d.data->rows[i];
    std::vector<std::string> row = {std::to_string(s.line), s.test_id, s.rotating ? "rotating" : "fixed",
                                    fmt(r.cv.front().resid[i], 6), fmt(r.cv.back().resid[i], 6)};
    for (const auto& c : r.candidates) row.push_back(fmt(c.x[i], 8));
    w.row(row);
  }
  return w;
}

CsvWriter problems_table(const Dataset& d) {
  CsvWriter w({"file", "line", "column", "problem"});
  w.comment(" data problems found in one pass; " + std::to_string(d.rows_read) + " rows read, " +
            std::to_string(d.rows.size()) + " kept, " + std::to_string(d.rows_dropped) + " dropped");
  for (const auto& p : d.problems) w.row({p.file, std::to_string(p.line), p.column, p.message});
  return w;
}

std::string write_loop_outputs(const Design& d, const LoopResult& r, const std::string& out,
                               const std::string& figdir, const std::string& gnuplot) {
  fs::create_directories(out + "/tables");
  fs::create_directories(out + "/figures");
  candidates_table(r).save(out + "/tables/candidates.csv");
  effects_table(r).save(out + "/tables/effects.csv");
  steps_table(r).save(out + "/tables/steps.csv");
  residuals_table(d, r).save(out + "/tables/residuals.csv");
  problems_table(*d.data).save(out + "/tables/problems.csv");
  write_file_atomic(out + "/loop_summary.json", summary_json(r));
  std::vector<std::string> figs, failed;  // a figure gnuplot could not draw is a warning, repeated in loop.md
  // A column name goes into a file name and a shell command: only [A-Za-z0-9_.-], the rest as '_'.
  auto safe = [](const std::string& name) {
    std::string t = name;
    for (char& ch : t)
      if (!(std::isalnum(static_cast<unsigned char>(ch)) || ch == '_' || ch == '-' || ch == '.')) ch = '_';
    return t;
  };
  if (!figdir.empty()) {
    for (size_t k = 0; k < r.candidates.size(); ++k) {
      const auto& c = r.candidates[k];
      const std::string svg = out + "/figures/resid_" + safe(c.name) + ".svg";
      std::string e = "outfile='" + svg + "'; datafile='" + out + "/tables/residuals.csv'; figdir='" + figdir +
                      "'; xcol='" + std::to_string(6 + k) + "'; xname='" + safe(c.name) + "'";
      const std::string cmd = gnuplot + " -e \"" + e + "\" '" + figdir + "/loop_residual.gp'";
      if (std::system(cmd.c_str()) == 0) figs.push_back("figures/resid_" + safe(c.name) + ".svg");
      else failed.push_back("figures/resid_" + safe(c.name) + ".svg");
    }
  }
  std::ostringstream m;
  m << "# Closing the loop: " << d.data->path << "\n\n";
  m << "**Conclusion.** " << r.conclusion << "\n\n";
  m << "- Bending force: " << r.bending << ".\n";
  if (std::isfinite(r.noise.sigma_N))
    m << "- Replicate noise: " << fmt(r.noise.sigma_N, 4) << " N from the within-test scatter of " << r.noise.tests
      << " tests (" << r.noise.rows << " rows; successive differences in " << r.noise.order
      << " order about a line in the back tension per test).\n";
  else
    m << "- Replicate noise: not estimable (no test with 4 or more rows).\n";
  m << "- Rows: " << d.data->rows_read << " read, " << d.data->rows.size() << " used, " << d.data->rows_dropped
    << " dropped (" << d.data->problems.size() << " problems, `tables/problems.csv`).\n";
  m << "- Base model: " << r.base_model << ".\n- Pressure maps: " << r.maps << ".\n";
  m << "- Held-out errors by grouped cross-validation (" << r.cv_mode << ", " << r.folds.k << " folds).\n";
  for (const auto& n : d.notes) m << "- " << n << ".\n";
  m << "\n## Steps\n\n| step | variable | effect | p | threshold | RMS before (N) | RMS after (N) | max before (N) | max "
       "after (N) |\n|---|---|---|---|---|---|---|---|---|\n";
  for (size_t k = 0; k < r.steps.size(); ++k) {
    const Step& s = r.steps[k];
    m << "| " << k + 1 << " | " << s.variable << " | " << s.effect << " | " << fmt(s.p_value, 3) << " | "
      << fmt(s.threshold, 3) << " | " << fmt(s.rms_before, 4) << " | " << fmt(s.rms_after, 4) << " | "
      << fmt(s.max_before, 4) << " | " << fmt(s.max_after, 4) << " |\n";
  }
  if (r.steps.empty())
    m << "| – | (no step) | | | | " << fmt(r.cv.front().rms, 4) << " | | " << fmt(r.cv.front().max_abs, 4) << " | |\n";
  for (size_t k = 0; k < r.steps.size(); ++k)
    if (!r.steps[k].sign.empty()) m << "\nStep " << k + 1 << ": " << r.steps[k].sign << ".\n";
  m << "\nStopped because: " << r.stopped_because << ".\n";
  if (!r.remaining.empty()) {
    m << "\nStructure remains unexplained; strongest remaining candidates:\n\n";
    for (const auto& u : r.remaining) m << "- " << u << "\n";
  }
  if (!r.screened.empty()) {
    m << "\nPassed the permutation screen; every effect tried for it (library and generic) failed the F test, the "
         "held-out error or the minimum effect:\n\n";
    for (const auto& u : r.screened) m << "- " << u << "\n";
  }
  m << "\n## Effects tried per step\n\n| step | variable | effect tried | held-out RMS (N) |\n|---|---|---|---|\n";
  for (size_t k = 0; k < r.steps.size(); ++k)
    for (const auto& t : r.steps[k].tried)
      m << "| " << k + 1 << " | " << r.steps[k].variable << " | " << t.first << " | " << fmt(t.second, 4) << " |\n";
  m << "\n## Added effects\n\n| step | effect | meaning | parameter | value ± se |\n|---|---|---|---|---|\n";
  for (size_t k = 0; k < r.steps.size(); ++k)
    for (const auto& p : r.steps[k].params)
      m << "| " << k + 1 << " | " << r.steps[k].effect << " | " << r.steps[k].meaning << " | " << p.name << " | "
        << fmt(p.value, 4) << " ± " << fmt(p.se, 2) << " |\n";
  m << "\n## Candidates, first round\n\nSequential permutation p-values (stopped when the decision against the "
       "threshold was clear at 99.9 % confidence, else undecided); test_id as a random effect (F test).\n\n"
       "| rank | candidate | kind | dof | permuted | p | permutations | decision | CV reduction |\n"
       "|---|---|---|---|---|---|---|---|---|\n";
  if (!r.rankings.empty())
    for (size_t i = 0; i < r.rankings[0].size(); ++i) {
      const auto& c = r.rankings[0][i];
      m << "| " << i + 1 << " | " << c.name << " | " << c.kind << " | " << c.dof << " | " << c.permuted << " | "
        << fmt(c.p_value, 3) << " | " << c.n_perm << " | " << c.decision << " | " << fmt(c.cv_reduction, 3) << " |\n";
    }
  const FrictionModel fm = identify_friction(d, r);
  m << write_friction_outputs(d, r, fm, out);
  if (!figdir.empty()) {  // one surface plot per lubricant and direction (our own script, in the output)
    for (size_t k = 0; k < fm.surfaces.size(); ++k)
      for (const char* dir : {"RD", "TD"}) {
        const std::string tag = (k == 0 ? std::string() : "_" + std::to_string(k)) + "_" + dir;
        const std::string dat = out + "/tables/surface" +
                                (k == 0 ? std::string() : "_" + lubricant_tag(fm.surfaces[k].lubricant)) + "_" + dir + ".dat";
        const std::string gp = out + "/figures/surface" + tag + ".gp", svg = "figures/surface" + tag + ".svg";
        write_file_atomic(gp, "set terminal svg size 640,480 noenhanced\nset output '" + out + "/" + svg +
                                  "'\nset xlabel 'p [MPa]'\nset ylabel 'v [mm/s]'\nset zlabel 'mu'\n"
                                  "set title 'fitted mu(p, v), " + std::string(dir) + ", " +
                                  safe(fm.surfaces[k].lubricant) + "'\nsplot '" + dat + "' with lines notitle\n");
        if (std::system((gnuplot + " '" + gp + "' 2>/dev/null").c_str()) == 0) figs.push_back(svg);
        else failed.push_back(svg);
      }
  }
  if (!failed.empty()) {
    const std::string w = std::to_string(failed.size()) + " of " + std::to_string(failed.size() + figs.size()) +
                          " figures could not be drawn ('" + gnuplot + "' failed or is missing), first " +
                          failed.front() + "; their data are in tables/";
    std::cerr << "warning: " << w << "\n";
    m << "\n**Warning:** " << w << ".\n";
  }
  if (!figs.empty()) {
    m << "\n## Figures: residuals against each candidate (before: base model; after: final model), fitted surfaces\n\n";
    for (const auto& f : figs) m << "![" << f << "](" << f << ")\n\n";
  }
  write_file_atomic(out + "/loop.md", m.str());
  return m.str();
}

}  // namespace drawbend::loop

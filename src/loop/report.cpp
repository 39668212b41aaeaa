// Loop outputs; see report.hpp.
#include "loop/report.hpp"

#include <algorithm>

#include "loop/friction_model.hpp"

#include <cmath>
#include <filesystem>
#include <sstream>

namespace drawbend::loop {

namespace fs = std::filesystem;

CsvWriter candidates_table(const LoopResult& r) {
  CsvWriter w({"round", "rank", "candidate", "kind", "dof", "permuted", "ess_N2", "p_value", "permutations",
               "decision", "cv_reduction", "significant", "probe", "cv_probe"});
  w.comment(" candidates ranked on held-out residuals (N); p from the blocked permutation test of the probe "
            "family's maximum (probe: the family member with the largest statistic, dof its largest dof); "
            "cv_reduction = fractional SSE reduction of the best probe (cv_probe) under grouped cross-validation (" +
            r.cv_mode + ")");
  for (size_t k = 0; k < r.rankings.size(); ++k)
    for (size_t i = 0; i < r.rankings[k].size(); ++i) {
      const auto& c = r.rankings[k][i];
      w.row({std::to_string(k + 1), std::to_string(i + 1), c.name, c.kind, std::to_string(c.dof), c.permuted,
             fmt(c.stat, 6), fmt(c.p_value, 4), std::to_string(c.n_perm), c.decision, fmt(c.cv_reduction, 4),
             c.significant ? "yes" : "no", c.probe, c.cv_probe});
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
               "max_after_N", "class", "channel", "contribution_N2"});
  w.comment(" held-out (grouped cross-validation: " + r.cv_mode + ") error of the outlet force before and after each "
            "step, steps in report order (undeclared variables, then base-model terms, each by contribution); p: F "
            "test of the effect given all the others");
  for (size_t k = 0; k < r.steps.size(); ++k) {
    const Step& s = r.steps[k];
    w.row({std::to_string(k + 1), s.variable, s.effect, fmt(s.p_value, 4), fmt(s.threshold, 3), fmt(s.rms_before, 5),
           fmt(s.rms_after, 5), fmt(s.max_before, 5), fmt(s.max_after, 5), s.cls, s.channel, fmt(s.contribution, 4)});
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
  std::vector<std::string> figs;
  if (!figdir.empty()) {
    for (size_t k = 0; k < r.candidates.size(); ++k) {
      const auto& c = r.candidates[k];
      const std::string svg = out + "/figures/resid_" + c.name + ".svg";
      std::string e = "outfile='" + svg + "'; datafile='" + out + "/tables/residuals.csv'; figdir='" + figdir +
                      "'; xcol='" + std::to_string(6 + k) + "'; xname='" + c.name + "'";
      const std::string cmd = gnuplot + " -e \"" + e + "\" '" + figdir + "/loop_residual.gp'";
      if (std::system(cmd.c_str()) == 0) figs.push_back("figures/resid_" + c.name + ".svg");
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
  m << "\n## Steps\n\nUndeclared variables (columns of the data) first, then terms adjusting the base model's own "
       "inputs, each by its contribution; p is the F test of the effect given all the others.\n\n"
       "| step | variable | class | channel | effect | p | threshold | RMS before (N) | RMS after (N) | max before (N) | max "
       "after (N) |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (size_t k = 0; k < r.steps.size(); ++k) {
    const Step& s = r.steps[k];
    m << "| " << k + 1 << " | " << s.variable << " | " << s.cls << " | " << s.channel << " | " << s.effect << " | "
      << fmt(s.p_value, 3) << " | "
      << fmt(s.threshold, 3) << " | " << fmt(s.rms_before, 4) << " | " << fmt(s.rms_after, 4) << " | "
      << fmt(s.max_before, 4) << " | " << fmt(s.max_after, 4) << " |\n";
  }
  if (r.steps.empty())
    m << "| – | (no step) | | | | | | " << fmt(r.cv.front().rms, 4) << " | | " << fmt(r.cv.front().max_abs, 4) << " | |\n";
  for (size_t k = 0; k < r.steps.size(); ++k)
    if (!r.steps[k].sign.empty()) m << "\nStep " << k + 1 << ": " << r.steps[k].sign << ".\n";
  m << "\nStopped because: " << r.stopped_because << ".\n";
  if (!r.remaining.empty()) {
    m << "\nNot at the noise level; strongest remaining candidates:\n\n";
    for (const auto& u : r.remaining) m << "- " << u << "\n";
  }
  if (!r.base_mismatch.empty()) {
    m << "\nBase-model mismatch (remaining structure in the model's own inputs, reported apart from undeclared "
         "variables):\n\n";
    for (const auto& u : r.base_mismatch) m << "- " << u << "\n";
  }
  if (!r.removed.empty()) {
    m << "\nRemoved by backfitting (not needed once the later effects were in):\n\n";
    for (const auto& u : r.removed) m << "- " << u << "\n";
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
                                  fm.surfaces[k].lubricant + "'\nsplot '" + dat + "' with lines notitle\n");
        if (std::system((gnuplot + " '" + gp + "' 2>/dev/null").c_str()) == 0) figs.push_back(svg);
      }
  }
  if (!figs.empty()) {
    m << "\n## Figures: residuals against each candidate (before: base model; after: final model), fitted surfaces\n\n";
    for (const auto& f : figs) m << "![" << f << "](" << f << ")\n\n";
  }
  write_file_atomic(out + "/loop.md", m.str());
  return m.str();
}

}  // namespace drawbend::loop

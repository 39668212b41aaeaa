// Loop outputs; see report.hpp.
#include "loop/report.hpp"

#include <algorithm>
#include <cctype>

#include "loop/figure_data.hpp"
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
               "decision", "cv_reduction", "significant", "probe", "probe_dof", "cv_probe", "same_test_as"});
  w.comment(" candidates ranked on held-out residuals (N); p from the blocked permutation test of the probe "
            "family's maximum (dof: the family's largest dof; probe: the family member with the largest statistic, "
            "probe_dof its own dof); "
            "cv_reduction = fractional SSE reduction of the best probe (cv_probe) under grouped cross-validation (" +
            r.cv_mode + "); same_test_as: the candidate whose test this one shares (the same levels on the same "
            "rows: one test, counted once in the Bonferroni threshold)");
  for (size_t k = 0; k < r.rankings.size(); ++k)
    for (size_t i = 0; i < r.rankings[k].size(); ++i) {
      const auto& c = r.rankings[k][i];
      w.row({std::to_string(k + 1), std::to_string(i + 1), c.name, c.kind, std::to_string(c.dof), c.permuted,
             fmt(c.stat, 6), fmt(c.p_value, 4), std::to_string(c.n_perm), c.decision, fmt(c.cv_reduction, 4),
             c.significant ? "yes" : "no", c.probe, c.probe_dof > 0 ? std::to_string(c.probe_dof) : "", c.cv_probe,
             c.same_as});
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

namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

/// The page an engineer reads first: what the data say (mu per lubricant, speed
/// and direction with its standard error; what else matters; how good the
/// model is), before the evidence.  Numbers only from the loop's own results.
std::string engineer_summary(const Design& d, const LoopResult& r, const FrictionModel& fm) {
  std::ostringstream m;
  m << "## What the data say\n\n";
  bool slope = false;
  for (const auto& c : fm.cells) slope = slope || c.a1_identified;
  m << "**Friction coefficient** by lubricant, speed and direction (Eq. 5.1 with the bending force below; "
       "± one standard error"
    << (slope ? "; mu = mu0 + a1 p with the contact pressure p in MPa" : "") << "):\n\n"
    << "| lubricant | speed | direction | mu" << (slope ? "0 | a1 [1/MPa]" : "") << " |\n|---|---|---|---"
    << (slope ? "|---" : "") << "|\n";
  for (const auto& c : fm.cells) {
    m << "| " << c.lubricant << " | " << c.speed << " | " << c.direction << " | " << fmt(c.mu0, 3) << " ± "
      << fmt(c.mu0_se, 2);
    if (slope) m << " | " << (c.a1_identified ? fmt(c.a1, 3) + " ± " + fmt(c.a1_se, 2) : std::string("–"));
    m << " |\n";
  }
  m << "\n**What else matters:** ";
  if (r.steps.empty()) {
    m << "nothing beyond lubricant, speed and direction passed the tests.";
  } else {
    for (std::size_t k = 0; k < r.steps.size(); ++k) {
      const Step& s = r.steps[k];
      m << (k ? "; " : "") << s.variable << " (" << (s.meaning.empty() ? s.effect : s.meaning)
        << "): held-out error " << fmt(s.rms_before, 3) << " N → " << fmt(s.rms_after, 3) << " N"
        << (s.far_note.empty() ? "" : " (named by its held-out gain, not by the permutation screen: see step " +
                                          std::to_string(k + 1) + ")");
      // Columns the data cannot tell from it, or that make the same effect (names only; the step says more).
      const std::vector<std::string>& alike = s.alike_names;
      for (std::size_t j = 0; j < alike.size(); ++j) m << (j ? ", " : "; ") << alike[j];
      if (!alike.empty())
        m << (alike.size() == 1 ? " explains" : " explain") << " it as well (see step " << k + 1 << ")";
    }
    m << ".";
  }
  if (!r.remaining.empty()) m << " Still unexplained: " << r.remaining.front() << ".";
  const double final_rms = r.cv.empty() ? NAN : r.cv.back().rms;
  m << "\n\n**How good the model is:** it predicts a held-out test's outlet force to " << fmt(final_rms, 3)
    << " N RMS (grouped cross-validation, " << r.folds.k << " folds)";
  if (!std::isfinite(r.noise.sigma_N))
    m << "; the replicate noise cannot be estimated (no test with 4 or more rows), so this cannot be compared with "
         "the measurement's own scatter.";
  else if (r.noise.sigma_N < 1e-6)
    m << "; the rows of each test lie exactly on a line (data sampled from fits, not measurements), so all of it "
         "is model error.";
  else
    m << ", against a replicate noise of " << fmt(r.noise.sigma_N, 3) << " N (the scatter of repeated samples "
      << "within one test): " << fmt(final_rms / r.noise.sigma_N, 3) << " times the noise"
      << (r.at_noise ? ", at the noise level." : ", so structure remains.");
  m << " Bending force: " << r.bending << ". Pressure: " << r.maps << ". " << d.data->rows.size() << " of "
    << d.data->rows_read << " rows used.\n";
  return m.str();
}

// A column name goes into a file name and a shell command: only [A-Za-z0-9_.-], the rest as '_'.
std::string safe(const std::string& name) {
  std::string t = name;
  for (char& ch : t)
    if (!(std::isalnum(static_cast<unsigned char>(ch)) || ch == '_' || ch == '-' || ch == '.')) ch = '_';
  return t;
}

// The figures drawn, and those gnuplot could not draw (a warning, repeated in loop.md).
struct Figures {
  std::vector<std::string> drawn, failed;
  void add(bool ok, const std::string& svg) { (ok ? drawn : failed).push_back(svg); }
};

// The tables and loop_summary.json.
void write_tables(const Design& d, const LoopResult& r, const std::string& out) {
  fs::create_directories(out + "/tables");
  fs::create_directories(out + "/figures");
  candidates_table(r).save(out + "/tables/candidates.csv");
  effects_table(r).save(out + "/tables/effects.csv");
  steps_table(r).save(out + "/tables/steps.csv");
  residuals_table(d, r).save(out + "/tables/residuals.csv");
  problems_table(*d.data).save(out + "/tables/problems.csv");
  write_file_atomic(out + "/loop_summary.json", summary_json(r));
}

// The residuals against each candidate (gnuplot, figdir/loop_residual.gp):
// every row, or above kFigurePointRows rows each bin's mean and spread
// (tables/residual_bins.csv, figdir/loop_residual_bins.gp; figure_data.hpp).
void residual_figures(const LoopResult& r, const std::string& out, const std::string& figdir,
                      const std::string& gnuplot, Figures& figs) {
  const std::vector<double>&before = r.cv.front().resid, &after = r.cv.back().resid;
  const bool binned = before.size() > kFigurePointRows;
  if (binned) {
    CsvWriter w({"candidate", "x", "rows", "before_mean_N", "before_sd_N", "after_mean_N", "after_sd_N", "name"});
    w.comment(" held-out residual (N) of the base model (before) and the final model (after) in bins of each "
              "candidate (numbered as in residuals.csv): one bin per value up to " + std::to_string(kFigureBins) +
              " values (per level up to " + std::to_string(kFigureLevels) + " levels of a categorical column), else " +
              std::to_string(kFigureBins) + " bins of equal row count; x the bin's mean, sd the rows' sample "
              "standard deviation");
    for (size_t k = 0; k < r.candidates.size(); ++k)
      for (const ResidualBin& b : residual_bins(r.candidates[k].x, before, after,
                                                r.candidates[k].categorical ? kFigureLevels : kFigureBins))
        w.row({std::to_string(k + 1), fmt(b.x, 8), std::to_string(b.rows), fmt(b.before_mean, 6),
               fmt(b.before_sd, 6), fmt(b.after_mean, 6), fmt(b.after_sd, 6), safe(r.candidates[k].name)});
    w.save(out + "/tables/residual_bins.csv");
  }
  for (size_t k = 0; k < r.candidates.size(); ++k) {
    const auto& c = r.candidates[k];
    const std::string svg = out + "/figures/resid_" + safe(c.name) + ".svg";
    std::string e = "outfile='" + svg + "'; figdir='" + figdir + "'; xname='" + safe(c.name) + "'; " +
                    (binned ? "datafile='" + out + "/tables/residual_bins.csv'; cand='" + std::to_string(k + 1) +
                                  "'; rows='" + std::to_string(before.size()) + "'"
                            : "datafile='" + out + "/tables/residuals.csv'; xcol='" + std::to_string(6 + k) + "'");
    const std::string cmd =
        gnuplot + " -e \"" + e + "\" '" + figdir + (binned ? "/loop_residual_bins.gp'" : "/loop_residual.gp'");
    figs.add(std::system(cmd.c_str()) == 0, "figures/resid_" + safe(c.name) + ".svg");
  }
}

// The evidence's opening: the data read, the base model, the noise, the folds.
void evidence_header(std::ostringstream& m, const Design& d, const LoopResult& r, const FrictionModel& fm) {
  m << "# Closing the loop: " << d.data->path << "\n\n";
  m << engineer_summary(d, r, fm) << "\n# Evidence\n\nHow the loop reached the summary above: the data read, "
       "the base model, each step with its permutation p-value against the Bonferroni threshold and its held-out "
       "error, the candidates, the identified friction model.\n\n";
  m << "**Conclusion.** " << r.conclusion << "\n\n";
  m << "- Bending force: " << r.bending << ".\n";
  if (std::isfinite(r.noise.sigma_N))
    m << "- Replicate noise (the scatter of repeated samples within one test, about a line in the back tension): "
    << fmt(r.noise.sigma_N, 4) << " N from " << r.noise.tests << " tests (" << r.noise.rows
    << " rows; residuals of polynomials in the back tension and the run position, rows in " << r.noise.order
    << " order"
    << (std::isfinite(r.noise_data_N)
            ? "; measured on the final model's held-out residual (`--noise-floor model`), the data's own being " +
                  fmt(r.noise_data_N, 4) + " N"
            : std::string())
    << ")"
    << (r.noise.sigma_N < 1e-6 ? ": none at all, the rows lie exactly on lines (data sampled from fits)" : "")
    << ".\n";
  else
    m << "- Replicate noise: not estimable (no test with 4 or more rows).\n";
  m << "- Rows: " << d.data->rows_read << " read, " << d.data->rows.size() << " used, " << d.data->rows_dropped
    << " dropped (" << d.data->problems.size() << " problems, `tables/problems.csv`).\n";
  if (!r.response_columns.empty()) {
    m << "- NOT SCREENED, computed from the measured forces (the forces determine them; they carry the outlet "
         "force's own noise and would explain any residual; response_columns.hpp):";
    for (size_t i = 0; i < r.response_columns.size(); ++i) m << (i ? ", " : " ") << r.response_columns[i];
    m << ".\n";
  }
  m << "- Base model: " << r.base_model << ".\n- Pressure maps: " << r.maps << ".\n";
  m << "- Held-out errors by grouped cross-validation (" << r.cv_mode << ", " << r.folds.k << " folds).\n";
  for (const auto& n : d.notes) {  // a note that repeats a bullet above (bending force, pressure maps) once only
    const std::string low = lower(n);
    if (low.rfind("bending force:", 0) == 0 || low.rfind("pressure maps:", 0) == 0) continue;
    m << "- " << n << ".\n";
  }
}

// The steps table, each step's sign and aliases, and why the search stopped.
void steps_section(std::ostringstream& m, const LoopResult& r) {
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
  for (size_t k = 0; k < r.steps.size(); ++k)
    if (r.steps[k].columns.size() == 2)
      m << "\nStep " << k + 1 << ": an effect of two columns together, " << r.steps[k].columns[0] << " and "
        << r.steps[k].columns[1] << " (" << r.steps[k].effect << " of the product of the two centred columns; "
        << "found by the pairwise probes).\n";
  for (size_t k = 0; k < r.steps.size(); ++k)
    if (!r.steps[k].far_note.empty())
      m << "\nStep " << k + 1 << " (taken by the far-from-noise rule, `--far-ratio`): " << r.steps[k].far_note << ".\n";
  for (size_t k = 0; k < r.steps.size(); ++k)
    if (!r.steps[k].pair_note.empty())
      m << "\nStep " << k + 1 << " (a pair must beat its own columns, the simpler explanation): "
        << r.steps[k].pair_note << ".\n";
  for (size_t k = 0; k < r.steps.size(); ++k)
    if (!r.steps[k].aliased_with.empty()) {
      m << "\nStep " << k + 1 << ": " << r.steps[k].variable << " (held-out RMS " << fmt(r.steps[k].rms_after, 4)
        << " N) cannot be told apart on held-out data from ";
      for (size_t j = 0; j < r.steps[k].aliased_with.size(); ++j) m << (j ? ", " : "") << r.steps[k].aliased_with[j];
      m << " (each column's own best form, within one standard error): these columns explain the same structure.\n";
    }
  for (size_t k = 0; k < r.steps.size(); ++k)
    if (!r.steps[k].same_effect_as.empty()) {
      m << "\nStep " << k + 1 << ": " << r.steps[k].variable << " makes the same effect as ";
      for (size_t j = 0; j < r.steps[k].same_effect_as.size(); ++j) m << (j ? ", " : "") << r.steps[k].same_effect_as[j];
      m << ": their held-out predictions differ by less than the minimum effect of a step (`--min-effect` x the "
           "noise), though the held-out data prefer "
        << r.steps[k].variable << "'s form. Which column is the cause, the data do not say.\n";
    }
  m << "\nStopped because: " << r.stopped_because << ".\n";
}

// A heading and its items, when there are any.
void item_list(std::ostringstream& m, const std::string& heading, const std::vector<std::string>& items) {
  if (items.empty()) return;
  m << heading;
  for (const auto& u : items) m << "- " << u << "\n";
}

// What the search left: remaining candidates, base-model mismatch, removals, screened columns.
void leftovers_section(std::ostringstream& m, const LoopResult& r) {
  item_list(m, "\nNot at the noise level; strongest remaining candidates:\n\n", r.remaining);
  item_list(m,
            "\nBase-model mismatch corrected (steps on the model's own inputs: the base model misfits there; reported "
            "apart from undeclared variables, not an undeclared effect):\n\n",
            r.base_terms);
  item_list(m,
            "\nBase-model mismatch (remaining structure in the model's own inputs, reported apart from undeclared "
            "variables):\n\n",
            r.base_mismatch);
  item_list(m, "\nRemoved by backfitting (not needed once the later effects were in):\n\n", r.removed);
  item_list(m,
            "\nPassed the permutation screen; every effect tried for it (library and generic) failed the F test, the "
            "held-out error or the minimum effect:\n\n",
            r.screened);
}

// The effects tried per step, the added effects' parameters, and the first round's candidates.
void effects_and_candidates(std::ostringstream& m, const LoopResult& r) {
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
       "threshold was clear at 99.9 % confidence; at the cap, significant when p <= the threshold, else undecided); test_id as a random effect (F test); "
       "candidates with the same levels on the same rows share one test (\"test of\").\n\n"
       "| rank | candidate | kind | dof (family's largest / strongest probe) | permuted | p | permutations | decision | CV reduction |\n"
       "|---|---|---|---|---|---|---|---|---|\n";
  if (!r.rankings.empty())
    for (size_t i = 0; i < r.rankings[0].size(); ++i) {
      const auto& c = r.rankings[0][i];
      m << "| " << i + 1 << " | " << c.name << " | " << c.kind << " | " << c.dof
        << (c.probe_dof > 0 ? " / " + std::to_string(c.probe_dof) : std::string()) << " | " << c.permuted << " | "
        << fmt(c.p_value, 3) << " | " << c.n_perm << " | " << c.decision
        << (c.same_as.empty() ? std::string() : " (test of " + c.same_as + ")") << " | " << fmt(c.cv_reduction, 3) << " |\n";
    }
}

// The friction model's files and their exports.
void model_files(std::ostringstream& m, const Design& d, const LoopResult& r, const FrictionModel& fm,
                 const std::string& out, const std::string& exports, const ExportOptions& eo) {
  m << write_friction_outputs(d, r, fm, out);
  std::vector<std::string> tomls;
  for (size_t k = 0; k < fm.surfaces.size(); ++k)
    tomls.push_back(out + "/friction_model" + (k == 0 ? std::string() : "_" + lubricant_tag(fm.surfaces[k].lubricant)) + ".toml");
  m << write_exports(tomls, exports, eo);
}

// One surface plot of lubricant surface k in direction dir (our own script, in
// the output), the fixed-pin rows on it.
void surface_figure(const Design& d, const LoopResult& r, const FrictionModel& fm, size_t k, const char* dir,
                    const std::string& out, const std::string& gnuplot, Figures& figs) {
  const std::string tag = (k == 0 ? std::string() : "_" + std::to_string(k)) + "_" + dir;
  const std::string dat = out + "/tables/surface" +
                          (k == 0 ? std::string() : "_" + lubricant_tag(fm.surfaces[k].lubricant)) + "_" + dir + ".dat";
  const std::string gp = out + "/figures/surface" + tag + ".gp", svg = "figures/surface" + tag + ".svg";
  // The data behind the surface, the points identify_friction fits it to: each fixed-pin row of
  // this lubricant whose cell has this direction, at the pressure predict_mu_at gives it.
  const std::string pts = out + "/tables/surface_points" + tag + ".dat";
  std::vector<double> ps, vs;
  const bool rd = dir[0] == 'R';
  for (std::size_t i = 0; i < d.rows.size(); ++i) {
    const Row& row = d.rows[i];
    if (row.rotating || d.data->rows[i].lubricant != fm.surfaces[k].lubricant ||
        std::isnan(r.final_fit.b0[row.pin]) || !(rd ? d.cell_rd[row.cell] : d.cell_td[row.cell]))
      continue;
    double p = 0;
    const double mu = predict_mu_at(d, r.final_fit, static_cast<int>(i), rd ? 0.0 : M_PI / 2, &p);
    if (std::isfinite(mu) && std::isfinite(p)) ps.push_back(p), vs.push_back(d.data->rows[i].speed_mm_s);
  }
  // Each distinct point at the figure's resolution once, with its count of rows (figure_data.hpp).
  const std::vector<PlotPoint> drawn = distinct_points(ps, vs);
  const std::size_t n_pts = ps.size();
  std::ostringstream pt;
  pt << "# p_MPa v_mm_s rows: " << n_pts << " fixed-pin rows, " << dir << ", lubricant " << fm.surfaces[k].lubricant
     << ", at " << drawn.size() << " distinct points (1/" << kFigureCells
     << " of each axis's range; a point at its first row's values)\n";
  for (const PlotPoint& q : drawn) pt << fmt(q.u, 6) << " " << fmt(q.v, 6) << " " << q.rows << "\n";
  write_file_atomic(pts, pt.str());
  // Markers of about 4 px, or 1.5 px above kFigurePointRows rows, where larger ones cover the surface.
  const std::string marker = n_pts > kFigurePointRows ? "0.2" : "0.5";
  // A coloured map with its colour bar, the rows on it.
  write_file_atomic(gp, "set terminal svg size 720,520 noenhanced\nset output '" + out + "/" + svg +
                            "'\nset view map\nset xlabel 'p [MPa]'\nset ylabel 'v [mm/s]'\n"
                            "set cblabel 'mu'\nset colorbox\nset palette rgbformulae 33,13,10\n"
                            "set key outside below\nset title 'fitted mu(p, v), " + std::string(dir) + ", " +
                            safe(fm.surfaces[k].lubricant) + (n_pts ? "" : " (no fixed-pin rows in this direction)") +
                            "'\nsplot '" + dat + "' with pm3d notitle" +
                            (n_pts ? ", '" + pts + "' using 1:2:(0) with points pt 7 ps " + marker + " lc rgb 'black' "
                                                   "title 'fixed-pin rows'"
                                   : std::string()) +
                            "\n");
  figs.add(std::system((gnuplot + " '" + gp + "' 2>/dev/null").c_str()) == 0, svg);
}

// The figures that failed (a warning, also on stderr) and those drawn.
void figures_section(std::ostringstream& m, const Figures& figs, const std::string& gnuplot) {
  const auto& failed = figs.failed;
  if (!failed.empty()) {
    const std::string w = std::to_string(failed.size()) + " of " + std::to_string(failed.size() + figs.drawn.size()) +
                          " figures could not be drawn ('" + gnuplot + "' failed or is missing), first " +
                          failed.front() + "; their data are in tables/";
    std::cerr << "warning: " << w << "\n";
    m << "\n**Warning:** " << w << ".\n";
  }
  if (!figs.drawn.empty()) {
    m << "\n## Figures: residuals against each candidate (before: base model; after: final model), fitted surfaces\n\n";
    for (const auto& f : figs.drawn) m << "![" << f << "](" << f << ")\n\n";
  }
}

}  // namespace

std::string write_loop_outputs(const Design& d, const LoopResult& r, const std::string& out,
                               const std::string& figdir, const std::string& gnuplot, const std::string& exports,
                               const ExportOptions& eo) {
  write_tables(d, r, out);
  Figures figs;
  if (!figdir.empty()) residual_figures(r, out, figdir, gnuplot, figs);
  std::ostringstream m;
  const FrictionModel fm = identify_friction(d, r);
  evidence_header(m, d, r, fm);
  steps_section(m, r);
  leftovers_section(m, r);
  effects_and_candidates(m, r);
  model_files(m, d, r, fm, out, exports, eo);
  if (!figdir.empty())  // one surface plot per lubricant and direction
    for (size_t k = 0; k < fm.surfaces.size(); ++k)
      for (const char* dir : {"RD", "TD"}) surface_figure(d, r, fm, k, dir, out, gnuplot, figs);
  figures_section(m, figs, gnuplot);
  write_file_atomic(out + "/loop.md", m.str());
  return m.str();
}

}  // namespace drawbend::loop

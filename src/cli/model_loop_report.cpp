// OUT/model_loop.md, OUT/blind.csv and the answer on standard output of
// `drawbend model-loop` (see model_loop_report.hpp).
#include "cli/model_loop_report.hpp"

#include <cmath>
#include <iostream>
#include <sstream>

#include "core/csv.hpp"
#include "core/file_gate.hpp"

namespace drawbend::cli {

namespace {

std::string pct(double v) { return fmt_fixed(100 * v, 1) + " %"; }

std::string pins_text(const std::vector<double>& pins) {
  std::string t;
  for (double d : pins) t += (t.empty() ? "" : ", ") + fmt(d);
  return t;
}

}  // namespace

double blind_rms(const modelloop::BlindLoopResult& b, bool final_model) {
  double s = 0;
  std::size_t n = 0;
  for (const auto& f : b.folds)
    for (const auto& p : final_model ? f.final_model : f.baseline) s += p.rel_error() * p.rel_error(), ++n;
  return n ? std::sqrt(s / static_cast<double>(n)) : 0.0;
}

void save_blind_csv(const modelloop::BlindLoopResult& b, const std::string& path) {
  CsvWriter w({"pin_mm", "fold_fit_pin_mm", "fold_choice_pins_mm", "fold_model", "back_tension_N", "measured_N",
               "baseline_N", "fold_model_N", "baseline_rel_error", "fold_model_rel_error"});
  w.comment(" blind: each pin predicted by the fold of the leave-one-pin-out split that never saw it (fit and "
            "choice on the other pins); F_B full strip [N], relative errors as fractions");
  for (const auto& f : b.folds)
    for (std::size_t k = 0; k < f.final_model.size(); ++k) {
      const auto& p = f.final_model[k];
      w.row({fmt(f.pin_mm), fmt(f.fit_pin_mm), pins_text(f.select_pins), f.model, fmt(p.measured.back_tension_N),
             fmt(p.measured.bending_N, 5), fmt(f.baseline[k].predicted_N, 5), fmt(p.predicted_N, 5),
             fmt(f.baseline[k].rel_error(), 4), fmt(p.rel_error(), 4)});
    }
  w.save(path);
}

void write_model_loop_md(const std::string& path, const std::string& data, const std::vector<modelloop::FbPoint>& points,
                         const sim::DrawBendSpec& s, const modelloop::ModelLoopConfig& cfg,
                         const modelloop::BlindLoopResult& b, const std::string& no_blind) {
  const modelloop::ModelLoopResult& r = b.in_sample;
  std::ostringstream md;
  md << "# Model loop on " << data << "\n\n"
     << points.size() << " measured bending forces F_B (full strip). The points on the " << fmt(cfg.fit_pin)
     << " mm pin train each candidate's members; the points on the other pins choose the model (a candidate is "
        "accepted only if their RMS relative error falls by more than "
     << pct(cfg.min_gain) << "), so their error is in-sample, not blind. "
     << (b.folds.empty() ? "No blind error: " + no_blind + "."
                         : "The blind errors come from the leave-one-pin-out split: the whole loop (fit and choice) "
                           "is run once per pin without that pin, and only then predicts it.")
     << " FE: half strip, frictionless pin, element length " << fmt(s.element_length) << " mm, " << s.across
     << " across, " << fmt(s.speed) << " mm/s, mass scaling " << fmt(s.mass_scaling) << ".\n\n"
     << "## Summary\n\n"
     << "- **Chosen model:** " << r.final_model.model << " (the loop on every pin)\n";
  if (b.folds.empty())
    md << "- **Blind RMS error of F_B:** none (" << no_blind << ")\n";
  else
    md << "- **Blind RMS error of F_B (each pin predicted by the fold that left it out):** " << pct(blind_rms(b, true))
       << " (the isotropic baseline: " << pct(blind_rms(b, false)) << ")\n";
  md << "- **In-sample, not blind:** fit pin " << pct(r.final_model.fit_rms) << " (fitted; baseline "
     << pct(r.baseline.fit_rms) << "), choice pins " << pct(r.final_model.held_rms) << ", largest "
     << pct(r.final_model.held_max) << " (they chose the model; baseline " << pct(r.baseline.held_rms) << ")\n"
     << "- " << b.runs << " FE runs, " << fmt_fixed(b.run_wall_s, 0) << " s of run wall time\n\n";
  if (!b.folds.empty()) {
    md << "## Blind: leave one pin out\n\n"
          "| left-out pin [mm] | fit on [mm] | chose on [mm] | the fold's model | F_X [N] | measured F_B [N] | "
          "baseline [N] | fold's model [N] | error |\n|---:|---:|---|---|---:|---:|---:|---:|---:|\n";
    for (const auto& f : b.folds)
      for (std::size_t k = 0; k < f.final_model.size(); ++k) {
        const auto& p = f.final_model[k];
        md << "| " << fmt(f.pin_mm) << " | " << fmt(f.fit_pin_mm) << " | " << pins_text(f.select_pins) << " | "
           << f.model << " | " << fmt(p.measured.back_tension_N) << " | " << fmt(p.measured.bending_N, 4) << " | "
           << fmt_fixed(f.baseline[k].predicted_N, 1) << " | " << fmt_fixed(p.predicted_N, 1) << " | "
           << pct(p.rel_error()) << " |\n";
      }
    md << "\n";
  }
  md << "## In-sample: the loop on every pin (not blind)\n\n"
        "| pin [mm] | F_X [N] | measured F_B [N] | baseline [N] | chosen [N] | error | role |\n"
        "|---:|---:|---:|---:|---:|---:|---|\n";
  for (std::size_t k = 0; k < r.final_model.points.size(); ++k) {
    const auto& p = r.final_model.points[k];
    md << "| " << fmt(p.measured.pin_mm) << " | " << fmt(p.measured.back_tension_N) << " | "
       << fmt(p.measured.bending_N, 4) << " | " << fmt_fixed(r.baseline.points[k].predicted_N, 1) << " | "
       << fmt_fixed(p.predicted_N, 1) << " | " << pct(p.rel_error()) << " | "
       << (p.held_out ? "chose the model" : "fit") << " |\n";
  }
  md << "\n## What was tried (in-sample)\n\nRelative errors of F_B; each member trained on the fit pin, the decision "
        "on the choice pins.\n\n| candidate | member | fit RMS | choice-pin RMS | choice-pin max | decision |\n"
        "|---|---|---:|---:|---:|---|\n"
     << "| baseline | " << r.baseline.model << " | " << pct(r.baseline.fit_rms) << " | " << pct(r.baseline.held_rms)
     << " | " << pct(r.baseline.held_max) << " | |\n";
  for (const auto& st : r.steps)
    md << "| " << st.candidate << " | " << st.member << " | " << pct(st.eval.fit_rms) << " | "
       << pct(st.eval.held_rms) << " | " << pct(st.eval.held_max) << " | " << st.decision << " |\n";
  md << "\n## Files\n\n- `chosen_model.toml`: the chosen model's `[material]` table (`drawbend drawbend-deck "
        "--material chosen_model.toml` runs it)\n"
        "- `baseline.csv`, `final.csv`: every point, measured and predicted (in-sample)\n"
     << (b.folds.empty() ? "" : "- `blind.csv`: every point predicted by the fold that left its pin out\n")
     << "- `steps.csv`: the table above as numbers\n"
        "- `inputs/`: a copy of the data (`data.csv`) and the options in effect (`options.toml`)\n"
        "- `runs/fb_<hash>/`: one folder per FE case (deck, history, `result.toml` with F_X, F_Y and F_B)\n";
  write_file_atomic(path, md.str());
}

void print_answer(const modelloop::BlindLoopResult& b, const std::string& no_blind) {
  const modelloop::ModelLoopResult& r = b.in_sample;
  std::cout << "model: " << r.final_model.model << "\n";
  for (std::size_t k = 0; k < r.final_model.points.size(); ++k) {
    const auto& p = r.final_model.points[k];
    std::cout << "  pin " << fmt(p.measured.pin_mm) << " mm, F_X " << fmt(p.measured.back_tension_N) << " N: measured "
              << fmt(p.measured.bending_N, 4) << " N, baseline " << fmt_fixed(r.baseline.points[k].predicted_N, 1)
              << " N, now " << fmt_fixed(p.predicted_N, 1) << " N" << (p.held_out ? " (chose the model)" : " (fit)")
              << "\n";
  }
  if (b.folds.empty())
    std::cout << "blind error: none (" << no_blind << ")\n";
  else
    std::cout << "blind RMS error of F_B (leave one pin out): " << pct(blind_rms(b, true)) << " (baseline "
              << pct(blind_rms(b, false)) << ")\n";
  std::cout << b.runs << " FE runs, " << fmt_fixed(b.run_wall_s, 0) << " s of run wall time\n";
}

}  // namespace drawbend::cli

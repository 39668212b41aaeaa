#pragma once
// What `drawbend model-loop` (cli/model_loop_cmd.cpp) leaves for the user:
// OUT/model_loop.md, OUT/blind.csv and the answer on standard output.
//
// Two kinds of error, never mixed (issue 51):
//   blind      each pin predicted by the fold of the leave-one-pin-out split
//              that never saw it (modelloop::run_model_loop_blind; needs
//              measured points on 3 or more pins);
//   in-sample  the loop on every pin: the fit pin's error was fitted to and the
//              other pins' error chose the model (accepted or rejected each
//              candidate), so neither is agreement.
// Relative errors of F_B (full strip); forces N, lengths mm.
#include <string>
#include <vector>

#include "modelloop/model_loop.hpp"

namespace drawbend::cli {

/// The RMS relative error of F_B over every fold's left-out points: the
/// baseline's (`final_model` false) or the folds' final models' (true).
double blind_rms(const modelloop::BlindLoopResult& b, bool final_model);

/// OUT/blind.csv: one row per left-out point (pin, the fold's fit and choice
/// pins, its model, measured, baseline and predicted F_B, relative errors).
void save_blind_csv(const modelloop::BlindLoopResult& b, const std::string& path);

/// OUT/model_loop.md.  `no_blind` says why there are no folds (empty when
/// there are).
void write_model_loop_md(const std::string& path, const std::string& data, const std::vector<modelloop::FbPoint>& points,
                         const sim::DrawBendSpec& s, const modelloop::ModelLoopConfig& cfg,
                         const modelloop::BlindLoopResult& b, const std::string& no_blind);

/// The chosen model, every point (measured, baseline, now, its role) and the
/// blind errors, on standard output.
void print_answer(const modelloop::BlindLoopResult& b, const std::string& no_blind);

}  // namespace drawbend::cli

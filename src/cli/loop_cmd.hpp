#pragma once
// `drawbend loop` and `drawbend synth` (see loop_cmd.cpp).
namespace drawbend::cli {
int loop_main(int argc, char** argv);   ///< argv[0] = "loop"
int synth_main(int argc, char** argv);  ///< argv[0] = "synth"
int export_main(int argc, char** argv);  ///< argv[0] = "export" (export_cmd.cpp)
/// `drawbend model-loop` (model_loop_cmd.cpp); argv[0] = the command, `name` its name in messages.
int model_loop_command(int argc, char** argv, const char* name = "drawbend model-loop");
}  // namespace drawbend::cli

#pragma once
// `drawbend loop` and `drawbend synth` (see loop_cmd.cpp).
namespace drawbend::cli {
int loop_main(int argc, char** argv);   ///< argv[0] = "loop"
int synth_main(int argc, char** argv);  ///< argv[0] = "synth"
int export_main(int argc, char** argv);  ///< argv[0] = "export" (export_cmd.cpp)
}  // namespace drawbend::cli

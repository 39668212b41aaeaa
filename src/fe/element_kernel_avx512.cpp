// The element kernel compiled for AVX-512 (eight elements side by side, eight
// doubles per instruction), with -mavx512f -mno-fma -ffp-contract=off: the same
// bits as the baseline kernel (core/lanes.hpp).  Built only where the compiler
// targets x86-64 (src/CMakeLists.txt); the solver calls it only on a CPU with
// AVX-512F.
#include "fe/element_kernel.hpp"

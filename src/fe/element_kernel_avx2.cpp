// The element kernel compiled for AVX2 (four doubles per instruction), with
// -mavx2 -ffp-contract=off and no FMA: the same bits as the baseline kernel
// (core/lanes.hpp).  Built only where the compiler targets x86-64
// (src/CMakeLists.txt); the solver calls it only on a CPU with AVX2.
#include "fe/element_kernel.hpp"

// The element kernel for the x86-64 baseline (SSE2: two doubles per
// instruction; the four lanes of a block take two).  The AVX2 build of the
// same source is element_kernel_avx2.cpp.
#include "fe/element_kernel.hpp"

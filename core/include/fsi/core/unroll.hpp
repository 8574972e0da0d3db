#pragma once
// FSI_UNROLL before a loop over the D components of a vector (or the entries of a D x D matrix)
// in a pair loop: unrolled completely, so the small arrays stay in registers. GCC unrolls such a
// loop by itself only when it stands alone; a nest of them in a pair loop it leaves rolled, with
// the arrays on the stack (the 2-D SPH momentum loop: 59 % more instructions, docs/fluid_sph.md).
#define FSI_UNROLL _Pragma("GCC unroll 9")

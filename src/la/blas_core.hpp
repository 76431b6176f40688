#pragma once
/// @file OpenBLAS's kernels for this CPU, chosen when OpenBLAS cannot choose them itself.
///
/// Debian's OpenBLAS (DYNAMIC_ARCH) picks its kernels from the CPU's model number when the
/// library loads. Version 0.3.21 does not know recent Xeons (family 6, model 207 on the
/// machines feticon is measured on) and falls back to the SSE3 kernels of the Prescott
/// Pentium 4: CHOLMOD's supernodal factorizations, dense blocks and LAPACK then run at about
/// half speed (docs/benchmarks.md, "OpenBLAS's kernels"). Its documented remedy is the
/// environment variable OPENBLAS_CORETYPE, read when the library loads, that is before
/// main(); so main() asks which kernels were taken and, if it was that fallback on a CPU
/// with AVX2, runs itself again with the variable set. Other BLAS libraries, OpenBLAS's own
/// choices and a user's OPENBLAS_CORETYPE are left alone.

#include <string>

namespace feticon::la
{
/// The kernels OpenBLAS runs with ("SkylakeX", "Haswell", ...), or "" when the BLAS loaded
/// is not OpenBLAS.
std::string blas_core();

/// The OPENBLAS_CORETYPE to run with, or "" to run as loaded: OpenBLAS fell back to
/// Prescott, OPENBLAS_CORETYPE is not set, the process is not under Valgrind, and the CPU
/// (and operating system) has AVX-512 (then "SkylakeX") or AVX2 with FMA ("Haswell").
std::string better_blas_core();

/// If better_blas_core() names kernels: sets OPENBLAS_CORETYPE and replaces the process by a
/// new run of the same executable with the same arguments. Call first in main(), before any
/// thread or MPI. Returns only if no new run was needed or execv failed (the run then goes on
/// with the fallback kernels).
void rerun_with_better_blas_core(char** argv);
} // namespace feticon::la

#include "la/blas_core.hpp"

#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>

namespace feticon::la
{
std::string blas_core()
{
  // Looked up, not linked: the BLAS behind libblas.so.3 is the system's choice.
  using CoreName = char* (*)();
  const auto core_name = reinterpret_cast<CoreName>(dlsym(RTLD_DEFAULT, "openblas_get_corename"));
  if (core_name == nullptr)
    return "";
  const char* name = core_name();
  return name ? name : "";
}

std::string better_blas_core()
{
  if (std::getenv("OPENBLAS_CORETYPE") != nullptr || blas_core() != "Prescott")
    return "";
  // Under Valgrind (its preload library is in LD_PRELOAD) a new run would leave the tool,
  // which follows an exec only with --trace-children=yes: such runs keep what OpenBLAS chose
  // for Valgrind's emulated CPU (Haswell's kernels on this machine, so no rerun arises here).
  if (const char* preload = std::getenv("LD_PRELOAD"); preload && std::strstr(preload, "vgpreload"))
    return "";
  // libgcc's checks include the operating system's support of the registers (XGETBV).
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512cd") && __builtin_cpu_supports("avx512bw") &&
      __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512vl"))
    return "SkylakeX";
  if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"))
    return "Haswell";
  return "";
}

void rerun_with_better_blas_core(char** argv)
{
  const std::string core = better_blas_core();
  if (core.empty())
    return;
  if (setenv("OPENBLAS_CORETYPE", core.c_str(), 1) != 0)
    return;
  execv("/proc/self/exe", argv);
  unsetenv("OPENBLAS_CORETYPE"); // execv failed: this process keeps the kernels it has
}
} // namespace feticon::la

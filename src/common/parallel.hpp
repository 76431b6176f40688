#pragma once
/// @file Threads inside one process (rank): the loops over a rank's subdomains run on a small
/// pool of threads, and BLAS (OpenBLAS under CHOLMOD) runs single-threaded inside them.
///
/// Why subdomains and not BLAS: the subdomain solves in every F application are supernodal
/// triangular solves (dtrsv), which OpenBLAS threads poorly; with its threads on, 40 % of the
/// CPU time of a 1M-DOF Hertz solve went to the kernel (sched_yield of spinning workers,
/// docs/profile.md). One BLAS thread per subdomain solve also makes every subdomain's
/// arithmetic the same whatever the thread and rank counts, so results stay bitwise
/// independent of both (docs/distributed.md).
///
/// Why our own pool and not OpenMP: libgomp's workers spin at the end of a loop; with two
/// processes on two cores (CTest -j2, two users' jobs) each spinning thread held the core the
/// other process needed (docs/measurements.md). These workers sleep on a
/// condition variable.
///
/// Threads per rank: OMP_NUM_THREADS if set (the usual knob of HPC batch systems), else the
/// cores of the node divided by the ranks on it (par::Environment); without MPI, all cores.

#include <cstdint>
#include <functional>
#include <limits>

namespace feticon
{
/// Sets the threads of parallel_for (at least 1; OMP_NUM_THREADS overrides), BLAS to one
/// thread and OpenMP (inside CHOLMOD and Gmsh) to no teams at all. Call before the first
/// parallel_for.
void set_threads(int threads);
/// Threads parallel_for uses.
int threads();
/// Cores of this machine (std::thread::hardware_concurrency, at least 1).
int hardware_cores();

/// BLAS threads inside the scope (one large factorization, e.g. a direct reference solve,
/// where BLAS is the only parallelism); back to one thread after it.
class ScopedBlasThreads
{
public:
  explicit ScopedBlasThreads(int threads);
  ~ScopedBlasThreads();
  ScopedBlasThreads(const ScopedBlasThreads&) = delete;
  ScopedBlasThreads& operator=(const ScopedBlasThreads&) = delete;
};

/// Below this much work (degrees of freedom of the subdomains in the loop) a loop runs
/// serially: waking the workers costs more than it saves (docs/measurements.md).
constexpr int64_t min_parallel_work = 20000;
/// The work to pass for loops that assemble, factorize or form dense blocks: each iteration
/// costs milliseconds even on small subdomains, so they always use the threads.
constexpr int64_t setup_work = std::numeric_limits<int64_t>::max();

/// body(i) for i in [first, end), spread over threads() threads (the caller is one of
/// them) when `work` >= min_parallel_work; indices are handed out one at a time, since
/// subdomains differ in cost. Iterations must write disjoint data. The exception of the
/// smallest index that threw is rethrown in the caller after all iterations ended (the same
/// one whatever the threads' timing). A parallel_for inside a
/// body runs serially.
void parallel_for(int32_t first, int32_t end, int64_t work, const std::function<void(int32_t)>& body);

/// body(begin, end) for the consecutive ranges of at most `chunk` indices that [0, n) splits
/// into, on the threads (as parallel_for with setup_work): for loops over faces, nodes or
/// cells whose items cost microseconds each and write their own results.
void parallel_for_chunks(size_t n, size_t chunk, const std::function<void(size_t, size_t)>& body);
} // namespace feticon

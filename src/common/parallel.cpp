#include "common/parallel.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstdlib>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace feticon
{
namespace
{
/// OpenBLAS is found at run time: CHOLMOD links the generic libblas, which Debian's
/// alternatives may point to OpenBLAS (threaded) or to the reference BLAS (no threads).
/// One thread also stops OpenBLAS's idle server threads: it starts them when it is loaded,
/// and each spins (sched_yield) for about 0.1 s before it sleeps, on the core our workers
/// need (docs/measurements.md). A
/// later call with more threads starts them again at the next BLAS call.
void set_blas_threads(int n)
{
  if (auto* set = reinterpret_cast<void (*)(int)>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads")))
    set(n);
  if (n == 1)
    if (auto* shutdown = reinterpret_cast<int (*)()>(dlsym(RTLD_DEFAULT, "blas_thread_shutdown_")))
      shutdown();
}

/// No OpenMP teams: CHOLMOD 5.12 zeroes its supernodal factor in an OpenMP loop with
/// num_threads(4) (t_cholmod_super_numeric.c); called from our workers, every worker started
/// its own team, 8 threads on 2 cores spinning against ours. Gmsh, the other OpenMP user,
/// meshes on one thread (mesh/cross_section.cpp). libgomp (GCC 12) keeps the setting per
/// thread: called on the main thread and on every worker. Found at run time like OpenBLAS:
/// feticon itself does not link libgomp.
void serialize_openmp()
{
  if (auto* set = reinterpret_cast<void (*)(int)>(dlsym(RTLD_DEFAULT, "omp_set_max_active_levels")))
    set(0);
}

int threads_from_environment()
{
  const char* value = std::getenv("OMP_NUM_THREADS");
  const int n = value ? std::atoi(value) : 0;
  return std::max(n, 0);
}

thread_local bool t_inside_loop = false;

/// Workers that sleep between loops. One loop at a time (the caller waits for it).
class ThreadPool
{
public:
  explicit ThreadPool(int workers)
  {
    for (int w = 0; w < workers; ++w)
      _workers.emplace_back([this] { work(); });
  }
  ~ThreadPool()
  {
    {
      std::lock_guard lock(_mutex);
      _stop = true;
    }
    _wake.notify_all();
    for (auto& t : _workers)
      t.join();
  }
  int size() const { return static_cast<int>(_workers.size()) + 1; }

  void run(int32_t first, int32_t end, const std::function<void(int32_t)>& body)
  {
    {
      std::lock_guard lock(_mutex);
      _body = &body;
      _next.store(first);
      _end = end;
      _error = nullptr;
      _busy = static_cast<int>(_workers.size());
      ++_generation;
    }
    _wake.notify_all();
    take_indices();
    std::unique_lock lock(_mutex);
    _done.wait(lock, [this] { return _busy == 0; });
    _body = nullptr;
    if (_error)
      std::rethrow_exception(_error);
  }

private:
  void take_indices()
  {
    t_inside_loop = true;
    for (int32_t i = _next.fetch_add(1); i < _end; i = _next.fetch_add(1))
    {
      try
      {
        (*_body)(i);
      }
      catch (...)
      {
        // The error of the smallest index, whichever thread met it first: the same message
        // run after run (an inverted element names the same element).
        std::lock_guard lock(_mutex);
        if (!_error || i < _error_index)
        {
          _error = std::current_exception();
          _error_index = i;
        }
      }
    }
    t_inside_loop = false;
  }

  void work()
  {
    serialize_openmp(); // libgomp keeps the setting per thread
    uint64_t seen = 0;
    for (;;)
    {
      {
        std::unique_lock lock(_mutex);
        _wake.wait(lock, [&] { return _stop || _generation != seen; });
        if (_stop)
          return;
        seen = _generation;
      }
      take_indices();
      {
        std::lock_guard lock(_mutex);
        --_busy;
      }
      _done.notify_one();
    }
  }

  std::vector<std::thread> _workers;
  std::mutex _mutex;
  std::condition_variable _wake, _done;
  const std::function<void(int32_t)>* _body = nullptr;
  std::atomic<int32_t> _next{0};
  int32_t _end = 0;
  int _busy = 0;
  uint64_t _generation = 0;
  bool _stop = false;
  std::exception_ptr _error;
  int32_t _error_index = 0; ///< the iteration that threw _error
};

int g_threads = 0; // 0: not set, all cores
std::unique_ptr<ThreadPool> g_pool;
std::once_flag g_blas_once;

int configured_threads()
{
  const int from_environment = threads_from_environment();
  if (from_environment > 0)
    return from_environment;
  return g_threads > 0 ? g_threads : hardware_cores();
}

ThreadPool* pool()
{
  std::call_once(g_blas_once, [] { set_blas_threads(1); });
  const int n = configured_threads();
  if (n <= 1)
    return nullptr;
  if (!g_pool || g_pool->size() != n)
    g_pool = std::make_unique<ThreadPool>(n - 1);
  return g_pool.get();
}
} // namespace

int hardware_cores() { return std::max(1, static_cast<int>(std::thread::hardware_concurrency())); }

void set_threads(int threads)
{
  g_threads = std::max(1, threads);
  set_blas_threads(1);
  serialize_openmp();
}

int threads() { return configured_threads(); }

void parallel_for(int32_t first, int32_t end, int64_t work, const std::function<void(int32_t)>& body)
{
  ThreadPool* p = t_inside_loop || end - first <= 1 || work < min_parallel_work ? nullptr : pool();
  if (!p)
  {
    for (int32_t i = first; i < end; ++i)
      body(i);
    return;
  }
  p->run(first, end, body);
}

ScopedBlasThreads::ScopedBlasThreads(int threads) { set_blas_threads(std::max(1, threads)); }

ScopedBlasThreads::~ScopedBlasThreads() { set_blas_threads(1); }
void parallel_for_chunks(size_t n, size_t chunk, const std::function<void(size_t, size_t)>& body)
{
  const auto n_chunks = static_cast<int32_t>((n + chunk - 1) / chunk);
  parallel_for(0, n_chunks, setup_work, [&](int32_t k) {
    const size_t begin = static_cast<size_t>(k) * chunk;
    body(begin, std::min(n, begin + chunk));
  });
}
} // namespace feticon

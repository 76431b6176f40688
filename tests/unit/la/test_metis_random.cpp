/// la::ThreadPrivateRandom (metis_random.hpp): METIS's rand() / srand() private to a thread.
/// References: glibc's own generator (random() / srandom(), which are rand() / srand() in
/// glibc) for the sequences, and a serial factorization of the same matrix for the orderings
/// CHOLMOD gets from METIS when two threads factorize at once.

#include "la/cholmod.hpp"
#include "la/metis_random.hpp"
#include "la_test_matrices.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <thread>
#include <vector>

namespace feticon::la
{
namespace
{
std::vector<int> draws(unsigned int seed, int n)
{
  srand(seed);
  std::vector<int> out;
  for (int i = 0; i < n; ++i)
    out.push_back(rand());
  return out;
}

std::vector<int> glibc_draws(unsigned int seed, int n)
{
  srandom(seed);
  std::vector<int> out;
  for (int i = 0; i < n; ++i)
    out.push_back(static_cast<int>(random()));
  return out;
}

using test::grid_system;
} // namespace

TEST(MetisRandom, TheExecutableProvidesThePrivateDraws)
{
  // CMakeLists.txt exports rand and srand from every executable linking feticon_la; without
  // that the analyses are serialized (correct, but slower), so a build that loses it fails here.
  EXPECT_TRUE(thread_private_random_available());
}

TEST(MetisRandom, OutsideAScopeTheDrawsAreGlibcs)
{
  const std::vector<int> reference = glibc_draws(4321, 20);
  EXPECT_EQ(draws(4321, 20), reference);
}

TEST(MetisRandom, InAScopeEachThreadDrawsGlibcsSequenceAlone)
{
  const std::vector<int> reference = glibc_draws(4321, 2000);
  std::vector<std::vector<int>> seen(4);
  std::vector<std::thread> threads;
  for (auto& out : seen)
    threads.emplace_back([&out] {
      const ThreadPrivateRandom scope;
      for (int repeat = 0; repeat < 20; ++repeat) // interleaved with the other threads
        out = draws(4321, 2000);
    });
  for (auto& thread : threads)
    thread.join();
  for (const auto& out : seen)
    EXPECT_EQ(out, reference);
  // The scope ended with its thread: this thread's draws are the process's generator again.
  EXPECT_EQ(draws(7, 5), glibc_draws(7, 5));
}

TEST(MetisRandom, ConcurrentFactorizationsSolveAsTheSerialOne)
{
  const SparseMatrix A = grid_system(12);
  const Vector b = Vector::LinSpaced(A.rows(), -1.0, 2.0);
  CholmodFactor serial;
  serial.factorize(A, "grid");
  const Vector reference = serial.solve(b);
  std::vector<Vector> solutions(8);
  std::vector<std::thread> threads;
  for (int t = 0; t < 2; ++t)
    threads.emplace_back([&, t] {
      for (size_t k = static_cast<size_t>(t); k < solutions.size(); k += 2)
      {
        CholmodFactor factor;
        factor.factorize(A, "grid");
        solutions[k] = factor.solve(b);
      }
    });
  for (auto& thread : threads)
    thread.join();
  // The same ordering gives the same factor and the same round-off: equal to the last bit.
  for (const Vector& x : solutions)
    EXPECT_EQ((x - reference).cwiseAbs().maxCoeff(), 0.0);
}
} // namespace feticon::la

#pragma once
/// Matrices shared by the tests of la/.

#include "la/types.hpp"

#include <vector>

namespace feticon::la::test
{
/// 3 unknowns per node of an m^3 grid coupled to the 26 neighbours, diagonally dominant: a
/// 3D elasticity-like pattern that CHOLMOD factorizes supernodally and, from m = 12 on,
/// orders with METIS.
inline SparseMatrix grid_system(int m)
{
  std::vector<Triplet> t;
  auto id = [m](int i, int j, int k) { return (i * m + j) * m + k; };
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j)
      for (int k = 0; k < m; ++k)
      {
        const int a = id(i, j, k);
        for (int c = 0; c < 3; ++c)
          for (int d = 0; d < 3; ++d)
            t.emplace_back(3 * a + c, 3 * a + d, c == d ? 27.0 : 2.7);
        for (int di = -1; di <= 1; ++di)
          for (int dj = -1; dj <= 1; ++dj)
            for (int dk = -1; dk <= 1; ++dk)
            {
              const int ii = i + di, jj = j + dj, kk = k + dk;
              if ((di == 0 && dj == 0 && dk == 0) || ii < 0 || jj < 0 || kk < 0 || ii >= m || jj >= m || kk >= m)
                continue;
              for (int c = 0; c < 3; ++c)
                for (int d = 0; d < 3; ++d)
                  t.emplace_back(3 * a + c, 3 * id(ii, jj, kk) + d, c == d ? -0.9 : -0.05);
            }
      }
  SparseMatrix A(3 * m * m * m, 3 * m * m * m);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}
} // namespace feticon::la::test

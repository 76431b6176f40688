#pragma once
/// @file Reductions of vectors whose entries may be spread over MPI ranks.
///
/// Solvers (qp/) see a vector as its local entries; every dot product, norm or minimum goes
/// through a VectorSpace. The local entries are grouped into blocks (in FETI: the dual rows
/// owned by one subdomain, or one subdomain's primal unknowns). A sum is formed per block in
/// local index order, then the block partials of all ranks are added in global block order.
/// Blocks never straddle ranks, so a result does not depend on how many ranks share the
/// blocks: iteration counts and iterates are bitwise the same on 1, 2 or 4 ranks.
///
/// Usage:
///   const auto [pq, gp] = la::reduce_sum<2>(space, [&](Index i, double* s)
///                                           { s[0] += p[i] * q[i]; s[1] += g[i] * p[i]; });

#include "la/types.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace feticon::la
{
class VectorSpace
{
public:
  virtual ~VectorSpace() = default;
  /// Number of local entries.
  virtual Index size() const = 0;
  /// Local blocks, each a list of local indices, in increasing global block order.
  virtual const std::vector<std::vector<Index>>& blocks() const = 0;
  /// Global index of local entry i (tie-breaking and index-dependent start vectors).
  virtual int64_t global_index(Index i) const = 0;
  /// Totals over all ranks of `k` quantities from their per-block partials
  /// (partials[b * k + j] for local block b), added in global block order.
  virtual void combine(std::span<const double> partials, int k, double* totals) const = 0;
  /// Smallest `value` over all ranks, ties to the smallest global index; returns the
  /// minimum and the local index of the winner if it is on this rank, else -1.
  virtual std::pair<double, Index> min_location(double value, Index local_index) const = 0;
  /// Maximum over all ranks (exact).
  virtual double max(double value) const = 0;
};

/// All entries local, one block: the serial default of the solvers.
class SerialSpace : public VectorSpace
{
public:
  explicit SerialSpace(Index n);
  Index size() const override { return _n; }
  const std::vector<std::vector<Index>>& blocks() const override { return _blocks; }
  int64_t global_index(Index i) const override { return i; }
  void combine(std::span<const double> partials, int k, double* totals) const override;
  std::pair<double, Index> min_location(double value, Index local_index) const override { return {value, local_index}; }
  double max(double value) const override { return value; }

private:
  Index _n;
  std::vector<std::vector<Index>> _blocks;
};

/// Sums K quantities over all entries: term(i, s) adds entry i's contributions to s[0..K).
template <int K, class Term>
std::array<double, K> reduce_sum(const VectorSpace& space, Term&& term)
{
  const auto& blocks = space.blocks();
  std::vector<double> partials(K * blocks.size(), 0.0);
  for (size_t b = 0; b < blocks.size(); ++b)
    for (const Index i : blocks[b])
      term(i, &partials[K * b]);
  std::array<double, K> totals{};
  space.combine(partials, K, totals.data());
  return totals;
}

inline double dot(const VectorSpace& space, const Vector& a, const Vector& b)
{
  return reduce_sum<1>(space, [&](Index i, double* s) { s[0] += a[i] * b[i]; })[0];
}

inline double norm(const VectorSpace& space, const Vector& a) { return std::sqrt(dot(space, a, a)); }
} // namespace feticon::la

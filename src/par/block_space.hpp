#pragma once
/// @file la::VectorSpace over an MPI communicator: blocks owned by ranks in increasing
/// global block order (rank r holds blocks before those of rank r + 1).

#include "la/vector_space.hpp"
#include "par/communicator.hpp"

namespace feticon::par
{
class BlockSpace : public la::VectorSpace
{
public:
  /// @param blocks       local indices of each local block, in increasing global block order
  /// @param global_index global index of every local entry, increasing with the local index
  BlockSpace(Communicator comm, std::vector<std::vector<la::Index>> blocks, std::vector<int64_t> global_index);

  la::Index size() const override { return static_cast<la::Index>(_global_index.size()); }
  const std::vector<std::vector<la::Index>>& blocks() const override { return _blocks; }
  int64_t global_index(la::Index i) const override { return _global_index[i]; }
  void combine(std::span<const double> partials, int k, double* totals) const override;
  std::pair<double, la::Index> min_location(double value, la::Index local_index) const override;
  double max(double value) const override { return _comm.max(value); }
  const Communicator& comm() const { return _comm; }

private:
  Communicator _comm;
  std::vector<std::vector<la::Index>> _blocks;
  std::vector<int64_t> _global_index;
};
} // namespace feticon::par

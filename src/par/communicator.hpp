#pragma once
/// @file The MPI communicator the distributed FETI engine works on (PETSc's PetscSF and
/// MPI_Comm wrappers play this role there).
///
/// Everything feticon exchanges is one of three patterns:
///   - all_gather: every rank contributes a slice, every rank receives the concatenation in
///     rank order (coarse vectors, per-block partial sums, small surface data);
///   - exchange: point-to-point buffers with the neighbouring ranks only (dual multipliers
///     shared by subdomains on different ranks);
///   - max/min/sum of exact quantities (integers, maxima).
/// Floating-point sums over ranks are never formed by MPI_Allreduce: its order depends on
/// the number of ranks. Callers gather per-block partial sums and add them in block order,
/// so every result is bitwise independent of the rank count (la/vector_space.hpp).
/// A communicator of size 1 makes no MPI call on these paths.

#include <mpi.h>

#include <cstdint>
#include <vector>

namespace feticon::par
{
/// Ranks of MPI_COMM_WORLD on this rank's node (they share its memory); 1 without MPI.
int ranks_on_this_node();

/// MPI_Init / MPI_Finalize for the lifetime of main(), when an MPI launcher started the
/// process (mpirun, mpiexec, srun: they set OMPI_COMM_WORLD_SIZE, PMIX_RANK or PMI_RANK). A
/// process started alone runs serial without MPI: OpenMPI's singleton start costs a large
/// part of a small contact run (docs/measurements.md), and one rank needs no communication
/// (Communicator::world() is then Communicator::self()).
class Environment
{
public:
  Environment(int& argc, char**& argv);
  ~Environment();
  Environment(const Environment&) = delete;
  Environment& operator=(const Environment&) = delete;
};

class Communicator
{
public:
  /// MPI_COMM_WORLD if MPI is initialized, else a serial communicator (rank 0 of 1), so
  /// library code and unit tests run without MPI_Init.
  static Communicator world();
  /// A serial communicator (rank 0 of 1) that never calls MPI.
  static Communicator self();

  int rank() const { return _rank; }
  int size() const { return _size; }
  bool serial() const { return _size == 1; }

  /// Concatenation over ranks (rank order) of every rank's `local`.
  std::vector<double> all_gather(const std::vector<double>& local) const;
  std::vector<int64_t> all_gather(const std::vector<int64_t>& local) const;
  /// Exact reductions.
  int64_t sum(int64_t value) const;
  double max(double value) const;
  double min(double value) const;

  /// Point-to-point exchange with the given ranks: sends send[k] to ranks[k] and returns
  /// what ranks[k] sent here (its size must be recv_sizes[k]). Ranks must agree on the
  /// pattern (both sides derive it from the same replicated data).
  std::vector<std::vector<double>> exchange(const std::vector<int>& ranks, const std::vector<std::vector<double>>& send,
                                            const std::vector<size_t>& recv_sizes) const;

  /// Waits until every rank has arrived.
  void barrier() const;

  /// Ends every rank with exit code `code` (after an error on this rank was printed).
  [[noreturn]] void abort(int code) const;

private:
  Communicator(MPI_Comm comm, int rank, int size) : _comm(comm), _rank(rank), _size(size) {}
  MPI_Comm _comm;
  int _rank;
  int _size;
};
} // namespace feticon::par

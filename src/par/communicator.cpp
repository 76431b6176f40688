#include "par/communicator.hpp"

#include "common/error.hpp"
#include "common/parallel.hpp"

#include <algorithm>
#include <cstdlib>

namespace feticon::par
{
namespace
{
template <class T>
std::vector<T> gather_impl(MPI_Comm comm, int size, const std::vector<T>& local, MPI_Datatype type)
{
  if (size == 1)
    return local;
  const int count = static_cast<int>(local.size());
  std::vector<int> counts(size), displacements(size, 0);
  MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  for (int r = 1; r < size; ++r)
    displacements[r] = displacements[r - 1] + counts[r - 1];
  std::vector<T> out(static_cast<size_t>(displacements.back() + counts.back()));
  MPI_Allgatherv(local.data(), count, type, out.data(), counts.data(), displacements.data(), type, comm);
  return out;
}
/// Ranks of MPI_COMM_WORLD sharing this rank's node (1 without MPI), set by Environment.
int node_ranks = 1;
} // namespace

int ranks_on_this_node() { return node_ranks; }

Environment::Environment(int& argc, char**& argv)
{
  const bool launched = std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMIX_RANK") || std::getenv("PMI_RANK");
  if (!launched)
  {
    set_threads(hardware_cores());
    return;
  }
  MPI_Init(&argc, &argv);
  // Threads per rank: the node's cores shared among the ranks on it (common/parallel.hpp;
  // OMP_NUM_THREADS overrides). Subdomain loops are threaded, BLAS single-threaded, so the
  // arithmetic of every subdomain is the same for any rank and thread count.
  MPI_Comm node;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
  int ranks_on_node = 1;
  MPI_Comm_size(node, &ranks_on_node);
  MPI_Comm_free(&node);
  node_ranks = std::max(1, ranks_on_node);
  set_threads(hardware_cores() / std::max(1, ranks_on_node));
}

Environment::~Environment()
{
  int initialized = 0, finalized = 0;
  MPI_Initialized(&initialized);
  MPI_Finalized(&finalized);
  if (initialized && !finalized)
    MPI_Finalize();
}

Communicator Communicator::world()
{
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (!initialized)
    return self();
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  return {MPI_COMM_WORLD, rank, size};
}

Communicator Communicator::self() { return {MPI_COMM_NULL, 0, 1}; }

std::vector<double> Communicator::all_gather(const std::vector<double>& local) const
{
  return gather_impl(_comm, _size, local, MPI_DOUBLE);
}

std::vector<int64_t> Communicator::all_gather(const std::vector<int64_t>& local) const
{
  return gather_impl(_comm, _size, local, MPI_INT64_T);
}

int64_t Communicator::sum(int64_t value) const
{
  if (_size > 1)
    MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_INT64_T, MPI_SUM, _comm);
  return value;
}

double Communicator::max(double value) const
{
  if (_size > 1)
    MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, MPI_MAX, _comm);
  return value;
}

double Communicator::min(double value) const
{
  if (_size > 1)
    MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, MPI_MIN, _comm);
  return value;
}

std::vector<std::vector<double>> Communicator::exchange(const std::vector<int>& ranks,
                                                        const std::vector<std::vector<double>>& send,
                                                        const std::vector<size_t>& recv_sizes) const
{
  FETICON_ASSERT(send.size() == ranks.size() && recv_sizes.size() == ranks.size(), "exchange pattern sizes");
  std::vector<std::vector<double>> recv(ranks.size());
  if (ranks.empty())
    return recv;
  std::vector<MPI_Request> requests;
  requests.reserve(2 * ranks.size());
  constexpr int tag = 17;
  for (size_t k = 0; k < ranks.size(); ++k)
  {
    recv[k].resize(recv_sizes[k]);
    requests.emplace_back();
    MPI_Irecv(recv[k].data(), static_cast<int>(recv_sizes[k]), MPI_DOUBLE, ranks[k], tag, _comm, &requests.back());
  }
  for (size_t k = 0; k < ranks.size(); ++k)
  {
    requests.emplace_back();
    MPI_Isend(send[k].data(), static_cast<int>(send[k].size()), MPI_DOUBLE, ranks[k], tag, _comm, &requests.back());
  }
  MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
  return recv;
}

void Communicator::barrier() const
{
  if (_size > 1)
    MPI_Barrier(_comm);
}

void Communicator::abort(int code) const
{
  if (_size > 1)
    MPI_Abort(_comm, code);
  std::exit(code);
}
} // namespace feticon::par

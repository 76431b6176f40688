#pragma once
/// @file Where the dual unknowns live under MPI, apart from any operator on them (cf. deal.II's
/// Utilities::MPI::Partitioner, DOLFINx's IndexMap): for the constraint rows touching a rank's
/// subdomains, which rank owns each row, where its value sits in the rank's vectors, and the
/// two neighbour exchanges every B-type product needs.
///
///   - a row is owned by the lowest subdomain it touches; a rank's dual vector holds the rows
///     its subdomains own, in increasing global id (on one rank: all rows);
///   - rows touching a rank's subdomains but owned elsewhere are ghosts: extended() copies the
///     owners' values to them (slots n_dual() ...), the start of B' lambda;
///   - sum_contributions() sends each owned subdomain's contribution to a row (the end of a
///     B x product) to the row's owner, which adds them in increasing subdomain order, from 0.
///     With that order, and the block reductions of la/vector_space.hpp, every result is
///     bitwise independent of the number of ranks.

#include "decomposition/constraint_rows.hpp"
#include "decomposition/decomposition.hpp"
#include "par/block_space.hpp"

#include <functional>
#include <map>
#include <memory>
#include <vector>

namespace feticon::dual
{
class DualLayout
{
public:
  /// @param decomposition the subdomains and their ranks (kept by reference)
  /// @param rows          the constraint rows touching this rank's subdomains (all rows on
  ///                      one rank), with global ids; they are the layout's "kept" rows
  DualLayout(const decomposition::Decomposition& decomposition, const decomposition::ConstraintRows& rows);

  /// Size of this rank's dual vector (its owned rows) and of the whole dual.
  int64_t n_dual() const { return static_cast<int64_t>(_owned.size()); }
  int64_t n_dual_global() const { return _n_dual_global; }
  /// Global row id of owned row i and its index among the kept rows.
  int64_t row_id(la::Index i) const { return _kept_id[_owned[i]]; }
  int64_t row_index(la::Index i) const { return _owned[i]; }
  /// The owned entries of a vector given for every kept row (e.g. rows.c_vector()).
  la::Vector owned(const la::Vector& per_row) const;
  /// Reductions over dual vectors (blocks: the rows owned by one subdomain).
  const la::VectorSpace& space() const { return *_space; }
  const par::Communicator& comm() const { return _comm; }
  const decomposition::Decomposition& decomposition() const { return _decomp; }

  /// Kept rows: their number, global ids, the subdomains each touches (increasing) and its
  /// slot in extended vectors.
  int64_t n_kept() const { return static_cast<int64_t>(_kept_id.size()); }
  int64_t kept_id(int64_t i) const { return _kept_id[i]; }
  const std::vector<int32_t>& touching(int64_t i) const { return _touch[i]; }
  int64_t slot(int64_t i) const { return _slot[i]; }
  /// The kept rows touching owned subdomain s, in increasing index: the rows of its B_s.
  const std::vector<int64_t>& rows_of_subdomain(int32_t s) const { return _sub_rows[s - _decomp.first_owned()]; }
  /// The ranks this rank exchanges dual values with, increasing.
  const std::vector<int>& neighbour_ranks() const { return _ghosts.ranks; }

  /// Owned values followed by the ghost values received from their owners (entries outside
  /// `mask`, one flag per owned row, as 0).
  la::Vector extended(const la::Vector& lambda, const std::vector<char>* mask = nullptr) const;
  /// The values of owned subdomain s's rows (rows_of_subdomain) from an extended vector.
  la::Vector rows_of(int32_t s, const la::Vector& extended) const;
  /// The owned result sum over s of local(s), where local(s) holds one value per row of owned
  /// subdomain s, summed per row in increasing subdomain order across ranks. `work`: the cost
  /// of all local(s) in parallel_for's units, which decides whether they run on the threads.
  la::Vector sum_contributions(const std::function<la::Vector(int32_t)>& local, int64_t work) const;

private:
  // The steps of the constructor.
  /// _touch, the owned rows and the ghosts' slots after them, the kept rows' ids, n_dual_global.
  void assign_rows(const decomposition::ConstraintRows& rows);
  /// The dual space: one block of owned rows per owned subdomain.
  void make_space();
  /// The kept rows and slots of every owned subdomain, and where its contributions start.
  void list_subdomain_rows();
  /// Local row of kept row i in owned subdomain s.
  int64_t position(int64_t i, int32_t s) const;
  /// The ranks this rank shares rows with, numbered in rank order, and both exchanges sized for them.
  std::map<int, size_t> number_neighbours();
  /// What each exchange sends and receives: owned values to the ghosts' ranks, contributions
  /// to the rows' owners in increasing (row id, subdomain) order.
  void list_exchanges(const decomposition::ConstraintRows& rows, const std::map<int, size_t>& neighbour);
  /// Per owned row, where its contributions sit among the local and the received ones.
  void list_sum_sources(const std::map<int, size_t>& neighbour);

  const decomposition::Decomposition& _decomp;
  par::Communicator _comm;
  int64_t _n_dual_global = 0;
  std::vector<int64_t> _owned;   ///< owned rows (indices into the kept rows)
  std::vector<int64_t> _kept_id; ///< global id of every kept row
  std::unique_ptr<par::BlockSpace> _space;
  std::vector<std::vector<int32_t>> _touch;
  std::vector<int64_t> _slot;
  /// Per owned subdomain (indexed s - first owned): its kept rows and their slots.
  std::vector<std::vector<int64_t>> _sub_rows;
  std::vector<std::vector<int64_t>> _sub_slots;
  std::vector<int64_t> _contribution_start; ///< start of subdomain s's values among contributions
  /// Per neighbour rank, the indices sent and the slots received.
  struct Exchange
  {
    std::vector<int> ranks;
    std::vector<std::vector<int64_t>> send;
    std::vector<std::vector<int64_t>> recv;
  };
  Exchange _ghosts; ///< owned values to the ranks that hold them as ghosts
  /// Contributions to their rows' owners; per owned row the positions (local, or n_local +
  /// received) to add, in increasing subdomain order.
  Exchange _to_owner;
  std::vector<int64_t> _sum_start, _sum_source;
  int64_t _n_contributions = 0; ///< local contributions + received ones
};
} // namespace feticon::dual

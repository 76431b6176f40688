#include "dual/constraint_scaling.hpp"

#include "common/log.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <tuple>

namespace feticon::dual
{
namespace
{
/// ||(B B')_CC^{-1}|| from below: 30 inverse power iterations from a fixed start (the block is
/// small and factorized, so this costs 30 triangular solves).
double largest_eigenvalue_of_inverse(const Eigen::SimplicialLLT<la::SparseMatrix>& llt, la::Index n)
{
  la::Vector v(n);
  for (la::Index i = 0; i < n; ++i) // fixed, and not orthogonal to any sign pattern
    v(i) = 1.0 + 0.5 * std::sin(1.0 + static_cast<double>(i));
  double estimate = 0;
  for (int k = 0; k < 30; ++k)
  {
    const double norm = v.norm();
    v = llt.solve(la::Vector(v / norm));
    estimate = v.norm();
  }
  return estimate;
}
} // namespace

ConstraintScaling::ConstraintScaling(const FetiOperators& feti, int64_t n_equality, const std::vector<char>& held)
    : _feti(feti)
{
  const auto is_contact = [n_equality](int64_t id) { return id >= n_equality; };
  std::vector<int64_t> local_keys;
  std::vector<double> local_values;
  for (const FetiOperators::GramEntry& e : feti.gram_entries(is_contact))
  {
    local_keys.insert(local_keys.end(), {e.row, e.col, e.subdomain});
    local_values.push_back(e.value);
  }
  const par::Communicator& comm = feti.comm();
  const std::vector<int64_t> keys = comm.all_gather(local_keys);
  const std::vector<double> values = comm.all_gather(local_values);
  // Summed in (row, column, subdomain) order: the block is bitwise the same for any number
  // of ranks, and so are the iterates.
  std::vector<size_t> order(values.size());
  std::iota(order.begin(), order.end(), size_t{0});
  const auto key = [&](size_t k) { return std::tie(keys[3 * k], keys[3 * k + 1], keys[3 * k + 2]); };
  std::ranges::sort(order, [&](size_t a, size_t b) { return key(a) < key(b); });
  for (size_t k = 0; k < values.size(); ++k)
    _ids.push_back(keys[3 * k]);
  std::ranges::sort(_ids);
  _ids.erase(std::unique(_ids.begin(), _ids.end()), _ids.end());
  if (_ids.empty())
    return;
  const auto position = [this](int64_t id) {
    return static_cast<la::Index>(std::ranges::lower_bound(_ids, id) - _ids.begin());
  };

  std::vector<int64_t> local_held;
  for (size_t i = 0; i < held.size(); ++i)
    if (held[i])
      local_held.push_back(feti.row_id(static_cast<la::Index>(i)));
  std::vector<int64_t> held_ids = comm.all_gather(local_held);
  std::ranges::sort(held_ids);
  const auto is_held = [&](int64_t id) { return std::ranges::binary_search(held_ids, id); };

  std::vector<la::Triplet> triplets;
  triplets.reserve(values.size() + _ids.size());
  for (const size_t k : order)
    if (!is_held(keys[3 * k]) && !is_held(keys[3 * k + 1]))
      triplets.emplace_back(position(keys[3 * k]), position(keys[3 * k + 1]), values[k]);
  // Equality-equality entries are not among the gathered ones: B_E B_E' = I; held rows are
  // the identity.
  for (const int64_t id : _ids)
    if (!is_contact(id) || is_held(id))
      triplets.emplace_back(position(id), position(id), 1.0);
  const auto n = static_cast<la::Index>(_ids.size());
  la::SparseMatrix block(n, n);
  block.setFromTriplets(triplets.begin(), triplets.end());
  _llt.compute(block);
  _factorized = _llt.info() == Eigen::Success;
  if (!_factorized)
  {
    log::warning("constraint rows are linearly dependent ((B B')_CC is singular): the FETI preconditioner is used "
                 "without the (B B')^-1 scaling");
    _ids.clear();
    return;
  }
  // Nearly dependent rows factorize, but Y then amplifies their near-null combination by the
  // inverse of a tiny eigenvalue, and the preconditioned QP stalls: a friction row that
  // repeated symmetry supports up to 0.17 % of its norm gave 2.5e6 and 20 000 MPGP steps
  // without progress, against 1 493 steps without the scaling (docs/friction.md).
  const double amplification = largest_eigenvalue_of_inverse(_llt, n);
  if (amplification > max_amplification)
  {
    // One line for every outer iteration that meets it (log::warning counts a repeated line):
    // the figures that change from one to the next (hertz_axi with friction: 13 lines, the
    // eigenvalue from 8e-10 to 6e-17) stay out of it.
    std::ostringstream line;
    line << "constraint rows are nearly dependent (an eigenvalue of (B B')_CC below " << 1 / max_amplification
         << "): the FETI preconditioner is used without the (B B')^-1 scaling";
    log::warning(line.str());
    _factorized = false;
    _ids.clear();
    return;
  }

  for (la::Index i = 0; i < feti.n_dual(); ++i)
  {
    const int64_t id = feti.row_id(i);
    if (std::ranges::binary_search(_ids, id))
    {
      _owned_rows.push_back(i);
      _owned_positions.push_back(position(id));
    }
  }
  _gathered_positions = comm.all_gather(_owned_positions);
}

la::Vector ConstraintScaling::apply(const la::Vector& lambda) const
{
  la::Vector out = lambda;
  if (_ids.empty())
    return out;
  std::vector<double> owned_values;
  owned_values.reserve(_owned_rows.size());
  for (const la::Index i : _owned_rows)
    owned_values.push_back(lambda(i));
  const std::vector<double> gathered = _feti.comm().all_gather(owned_values);
  la::Vector block_values(static_cast<la::Index>(_ids.size()));
  for (size_t k = 0; k < gathered.size(); ++k)
    block_values(static_cast<la::Index>(_gathered_positions[k])) = gathered[k];
  const la::Vector solved = _llt.solve(block_values);
  for (size_t k = 0; k < _owned_rows.size(); ++k)
    out(_owned_rows[k]) = solved(_owned_positions[k]);
  return out;
}
} // namespace feticon::dual

#include "dual/multiplier_memory.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <utility>

namespace feticon::dual
{
qp::QpState MultiplierMemory::warm_start(const FetiOperators& feti, int64_t n_equality,
                                         const std::vector<int64_t>& contact_key, int n_tangents) const
{
  qp::QpState warm = _state;
  if (_owned.size() == 0 && _restart_equality.size() == 0 && _contact.empty())
    return warm; // the first solve of the run starts at 0
  FETICON_CHECK(_restart_equality.size() == 0 || _restart_equality.size() == n_equality,
                "restart: the checkpoint holds " << _restart_equality.size()
                                                 << " equality multipliers, this problem has " << n_equality
                                                 << " equality rows (other supports or linear equations?)");
  const la::Index m = feti.n_dual();
  const int64_t n_contact = static_cast<int64_t>(contact_key.size());
  warm.x = la::Vector::Zero(m);
  for (la::Index i = 0; i < m; ++i)
  {
    const int64_t id = feti.row_id(i);
    if (id < n_equality)
    {
      if (!_equality_forgotten)
        warm.x(i) = _restart_equality.size() > 0 ? _restart_equality(id) : _owned(i);
    }
    else if (id < n_equality + n_contact)
    {
      if (const auto it = _contact.find(contact_key[id - n_equality]); it != _contact.end())
        warm.x(i) = it->second;
    }
    else if (n_tangents > 0)
    {
      const int64_t j = id - n_equality - n_contact;
      if (const auto it = _tangential.find(contact_key[j / n_tangents]); it != _tangential.end())
        warm.x(i) = it->second[j % n_tangents];
    }
  }
  return warm;
}

la::Vector MultiplierMemory::remember(const FetiOperators& feti, const DualSolution& solution, int64_t n_equality,
                                      const std::vector<int64_t>& contact_key, int n_tangents, la::Vector* tangential)
{
  _owned = solution.state.x;
  _restart_equality.resize(0);
  _equality_forgotten = false;
  _state = solution.state;
  _state.x.resize(0);
  const int64_t n_contact = static_cast<int64_t>(contact_key.size());
  la::Vector contact_lambda = multipliers_by_id(feti, solution.state.x, n_equality, n_equality + n_contact);
  _contact.clear();
  for (int64_t j = 0; j < n_contact; ++j)
    _contact[contact_key[j]] = contact_lambda(j);
  _tangential.clear();
  if (tangential)
    tangential->resize(0);
  if (n_tangents > 0)
  {
    const int64_t begin = n_equality + n_contact;
    la::Vector t = multipliers_by_id(feti, solution.state.x, begin, begin + n_tangents * n_contact);
    for (int64_t j = 0; j < n_contact; ++j)
      for (int k = 0; k < n_tangents; ++k)
        _tangential[contact_key[j]][k] = t(n_tangents * j + k);
    if (tangential)
      *tangential = std::move(t);
  }
  return contact_lambda;
}

void MultiplierMemory::restore(qp::QpState state, const std::vector<int64_t>& contact_key,
                               const std::vector<double>& contact_lambda, const std::vector<double>& tangential)
{
  _owned.resize(0);
  _restart_equality = std::move(state.x);
  _equality_forgotten = false;
  _contact.clear();
  _tangential.clear();
  FETICON_CHECK(tangential.empty() || tangential.size() == 2 * contact_key.size(),
                "restart: the checkpoint holds " << tangential.size() << " tangential multipliers for "
                                                 << contact_key.size() << " contact rows");
  for (size_t j = 0; j < contact_key.size() && !tangential.empty(); ++j)
    _tangential[contact_key[j]] = {tangential[2 * j], tangential[2 * j + 1]};
  for (size_t j = 0; j < contact_key.size(); ++j)
    _contact[contact_key[j]] = contact_lambda[j];
  _state = std::move(state);
  _state.x.resize(0);
}

std::set<int64_t> MultiplierMemory::positive_keys(const std::map<int64_t, double>& contact, double floor)
{
  double largest = 0;
  for (const auto& [key, value] : contact)
    largest = std::max(largest, value);
  std::set<int64_t> active;
  for (const auto& [key, value] : contact)
    if (value > std::max(1e-12 * largest, floor))
      active.insert(key);
  return active;
}

la::Vector multipliers_by_id(const FetiOperators& feti, const la::Vector& lambda, int64_t id_begin, int64_t id_end)
{
  std::vector<int64_t> ids;
  std::vector<double> values;
  for (la::Index i = 0; i < feti.n_dual(); ++i)
    if (feti.row_id(i) >= id_begin && feti.row_id(i) < id_end)
    {
      ids.push_back(feti.row_id(i));
      values.push_back(lambda(i));
    }
  const std::vector<int64_t> all_ids = feti.comm().all_gather(ids);
  const std::vector<double> all_values = feti.comm().all_gather(values);
  la::Vector out = la::Vector::Zero(id_end - id_begin);
  for (size_t k = 0; k < all_ids.size(); ++k)
    out(all_ids[k] - id_begin) = all_values[k];
  return out;
}
} // namespace feticon::dual

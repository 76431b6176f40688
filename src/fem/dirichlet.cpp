#include "fem/dirichlet.hpp"

#include "common/error.hpp"
#include "la/submatrix.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace feticon::fem
{
std::pair<int64_t, double> held_dof(const mesh::Mesh& mesh, const NodeFrames* frames, int32_t node, int component,
                                    double value)
{
  if (frames && frames->index_of(node) >= 0)
    return frames->held(mesh.n_nodes(), node, component, value);
  return {3 * int64_t{node} + component, value};
}

ConstrainedDofs collect_dirichlet(const mesh::Mesh& mesh, const std::vector<DirichletCondition>& conditions,
                                  double scale, const NodeFrames* frames)
{
  std::map<int64_t, double> prescribed;
  for (const DirichletCondition& condition : conditions)
  {
    const auto& nodes = mesh.node_set(condition.set);
    FETICON_CHECK(!nodes.empty(), "Dirichlet condition on the empty node set '" << condition.set << "'");
    for (int32_t node : nodes)
      for (int i = 0; i < 3; ++i)
      {
        if (!condition.value[i])
          continue;
        const auto [dof, v] = held_dof(mesh, frames, node, i, *condition.value[i] * scale);
        auto [it, inserted] = prescribed.emplace(dof, v);
        FETICON_CHECK(inserted || std::abs(it->second - v) <= 1e-14 * (1 + std::abs(v)),
                      "node " << node << " of set '" << condition.set
                              << "' has two different prescribed values for component " << i
                              << (frames && frames->index_of(node) >= 0 ? " (of its local axes)" : ""));
      }
  }
  return to_constrained_dofs(prescribed);
}

ConstrainedDofs to_constrained_dofs(const std::map<int64_t, double>& prescribed)
{
  ConstrainedDofs out;
  out.values.resize(static_cast<la::Index>(prescribed.size()));
  for (const auto& [dof, value] : prescribed)
  {
    out.values(static_cast<la::Index>(out.dofs.size())) = value;
    out.dofs.push_back(dof);
  }
  return out;
}

DirichletElimination::DirichletElimination(int64_t n_dofs, const ConstrainedDofs& constrained)
    : _n_dofs(n_dofs), _free_index(n_dofs, -1), _constrained(constrained)
{
  std::vector<char> is_constrained(n_dofs, 0);
  for (int64_t dof : constrained.dofs)
  {
    FETICON_CHECK(dof >= 0, "constrained DOF " << dof << " out of range");
    // Held DOFs past the global ones are supports along local axes (fem/node_frames.hpp).
    FETICON_CHECK(dof < n_dofs,
                  "a support acts along a node's local axis (*TRANSFORM) or on a coupling's reference "
                  "node, which the direct solves do not take: use method smalbe or dual_penalty");
    is_constrained[dof] = 1;
  }
  for (int64_t dof = 0; dof < n_dofs; ++dof)
    if (!is_constrained[dof])
    {
      _free_index[dof] = static_cast<int32_t>(_free.size());
      _free.push_back(dof);
    }
}

la::SparseMatrix DirichletElimination::reduce_matrix(const la::SparseMatrix& K) const
{
  return la::principal_submatrix(K, _free_index, static_cast<int32_t>(n_free()));
}

la::Vector DirichletElimination::reduce_rhs(const la::SparseMatrix& K, const la::Vector& f) const
{
  const la::Vector full = f - K * prescribed();
  return restrict(full);
}

la::Vector DirichletElimination::expand(const la::Vector& u_free) const
{
  la::Vector full = prescribed();
  for (int64_t i = 0; i < n_free(); ++i)
    full(_free[i]) = u_free(i);
  return full;
}

la::Vector DirichletElimination::restrict(const la::Vector& full) const
{
  la::Vector out(n_free());
  for (int64_t i = 0; i < n_free(); ++i)
    out(i) = full(_free[i]);
  return out;
}

la::Vector DirichletElimination::prescribed() const
{
  la::Vector full = la::Vector::Zero(_n_dofs);
  for (size_t i = 0; i < _constrained.dofs.size(); ++i)
    full(_constrained.dofs[i]) = _constrained.values(static_cast<la::Index>(i));
  return full;
}
} // namespace feticon::fem

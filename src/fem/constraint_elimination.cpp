#include "fem/constraint_elimination.hpp"

#include "common/error.hpp"
#include "fem/linear_equations.hpp"

#include <cmath>
#include <map>
#include <set>

namespace feticon::fem
{
namespace
{
/// u_p = sum_j terms[j] u_j + constant, over independent DOFs j.
struct Expression
{
  std::map<int64_t, double> terms;
  double constant = 0;
};

/// The equation in independent DOFs: per DOF its coefficient and the magnitude of what was
/// summed into it; `rhs` less the dependent DOFs' constants.
std::map<int64_t, std::pair<double, double>> substitute_dependent(const ReducedEquation& equation,
                                                                  const std::map<int64_t, Expression>& dependent,
                                                                  double& rhs)
{
  // The equation in independent DOFs: the dependent ones substituted, with the magnitude of
  // what was summed into each coefficient (cancellation to round-off of it is a zero).
  std::map<int64_t, std::pair<double, double>> terms;
  for (size_t k = 0; k < equation.dofs.size(); ++k)
  {
    const int64_t dof = equation.dofs[k];
    const double a = equation.coefficients[k];
    if (const auto it = dependent.find(dof); it != dependent.end())
    {
      for (const auto& [j, x] : it->second.terms)
      {
        terms[j].first += a * x;
        terms[j].second += std::abs(a * x);
      }
      rhs -= a * it->second.constant;
    }
    else
    {
      terms[dof].first += a;
      terms[dof].second += std::abs(a);
    }
  }
  return terms;
}

/// The new dependent DOF `pivot` = x replaces the pivot in the expressions of the earlier ones.
void substitute_pivot(int64_t pivot, const Expression& x, std::map<int64_t, Expression>& dependent,
                      std::map<int64_t, std::set<int64_t>>& used_by)
{
  // The earlier dependent DOFs that used the pivot now use its expression.
  if (const auto users = used_by.find(pivot); users != used_by.end())
  {
    for (const int64_t d : users->second)
    {
      Expression& y = dependent.at(d);
      const auto it = y.terms.find(pivot);
      if (it == y.terms.end())
        continue;
      const double y_pivot = it->second;
      y.terms.erase(it);
      for (const auto& [j, xj] : x.terms)
      {
        y.terms[j] += y_pivot * xj;
        used_by[j].insert(d);
      }
      y.constant += y_pivot * x.constant;
    }
    used_by.erase(pivot);
  }
}

/// Gaussian elimination of the equations, one dependent DOF (the pivot) per equation: the
/// expressions of the dependent DOFs in the independent ones.
std::map<int64_t, Expression> eliminate_equations(const std::vector<ReducedEquation>& reduced,
                                                  const std::vector<LinearEquation>& equations, const mesh::Mesh* mesh)
{
  std::map<int64_t, Expression> dependent;
  std::map<int64_t, std::set<int64_t>> used_by; // independent DOF -> dependent DOFs whose expression has it
  for (size_t e = 0; e < reduced.size(); ++e)
  {
    double rhs = reduced[e].rhs;
    const std::map<int64_t, std::pair<double, double>> terms = substitute_dependent(reduced[e], dependent, rhs);
    // Pivot: the largest coefficient (the first of equal ones).
    int64_t pivot = -1;
    double largest = 0, magnitude = 0;
    for (const auto& [dof, term] : terms)
    {
      magnitude = std::max(magnitude, term.second);
      if (std::abs(term.first) > largest)
      {
        largest = std::abs(term.first);
        pivot = dof;
      }
    }
    FETICON_CHECK(pivot >= 0 && largest > equation_dependence_tolerance * magnitude,
                  dependent_equation_message(equations, e, mesh));
    const double a_pivot = terms.at(pivot).first;
    Expression x;
    for (const auto& [dof, term] : terms)
      if (dof != pivot && std::abs(term.first) > 1e-14 * term.second)
        x.terms[dof] = -term.first / a_pivot;
    x.constant = rhs / a_pivot;
    substitute_pivot(pivot, x, dependent, used_by);
    for (const auto& [j, xj] : x.terms)
      used_by[j].insert(pivot);
    dependent.emplace(pivot, std::move(x));
  }
  return dependent;
}
} // namespace

ConstraintElimination::ConstraintElimination(int64_t n_dofs, const ConstrainedDofs& prescribed,
                                             const std::vector<LinearEquation>& equations, const mesh::Mesh* mesh)
    : _n_dofs(n_dofs), _dirichlet(n_dofs, prescribed), _with_equations(!equations.empty())
{
  if (!_with_equations)
    return;
  const std::vector<ReducedEquation> reduced = reduce_equations(equations, n_dofs, prescribed, {}, mesh);
  const std::map<int64_t, Expression> dependent = eliminate_equations(reduced, equations, mesh);

  // Columns of T: the DOFs neither prescribed nor dependent, in increasing order.
  std::vector<char> kind(_n_dofs, 0); // 1 prescribed, 2 dependent
  _g = la::Vector::Zero(_n_dofs);
  for (size_t k = 0; k < prescribed.dofs.size(); ++k)
  {
    kind[prescribed.dofs[k]] = 1;
    _g(prescribed.dofs[k]) = prescribed.values(static_cast<la::Index>(k));
  }
  for (const auto& [dof, x] : dependent)
  {
    kind[dof] = 2;
    _g(dof) = x.constant;
  }
  std::vector<int32_t> column(_n_dofs, -1);
  for (int64_t dof = 0; dof < _n_dofs; ++dof)
    if (kind[dof] == 0)
    {
      column[dof] = static_cast<int32_t>(_independent.size());
      _independent.push_back(dof);
    }
  std::vector<la::Triplet> triplets;
  for (const int64_t dof : _independent)
    triplets.emplace_back(static_cast<int>(dof), column[dof], 1.0);
  for (const auto& [dof, x] : dependent)
    for (const auto& [j, xj] : x.terms)
      if (xj != 0.0)
        triplets.emplace_back(static_cast<int>(dof), column[j], xj);
  _T.resize(static_cast<la::Index>(_n_dofs), static_cast<la::Index>(_independent.size()));
  _T.setFromTriplets(triplets.begin(), triplets.end());
  _Tt = _T.transpose();
}

int64_t ConstraintElimination::n_free() const
{
  return _with_equations ? static_cast<int64_t>(_independent.size()) : _dirichlet.n_free();
}

la::SparseMatrix ConstraintElimination::reduce_matrix(const la::SparseMatrix& K) const
{
  if (!_with_equations)
    return _dirichlet.reduce_matrix(K);
  const la::SparseMatrix KT = K * _T;
  return _Tt * KT;
}

la::Vector ConstraintElimination::reduce_rhs(const la::SparseMatrix& K, const la::Vector& f) const
{
  if (!_with_equations)
    return _dirichlet.reduce_rhs(K, f);
  return _Tt * (f - K * _g);
}

la::Vector ConstraintElimination::reduce_force(const la::Vector& r) const
{
  if (!_with_equations)
    return _dirichlet.restrict(r);
  return _Tt * r;
}

la::Vector ConstraintElimination::expand(const la::Vector& v) const
{
  if (!_with_equations)
    return _dirichlet.expand(v);
  return _T * v + _g;
}

void ConstraintElimination::impose(la::Vector& u) const
{
  FETICON_ASSERT(u.size() == _n_dofs, "vector size");
  if (!_with_equations)
  {
    u = _dirichlet.expand(_dirichlet.restrict(u));
    return;
  }
  la::Vector v(static_cast<la::Index>(_independent.size()));
  for (size_t k = 0; k < _independent.size(); ++k)
    v(static_cast<la::Index>(k)) = u(_independent[k]);
  u = expand(v);
}
} // namespace feticon::fem

#include "decomposition/constraint_rows.hpp"

#include "common/error.hpp"
#include "fem/linear_equations.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>

namespace feticon::decomposition
{
void ConstraintRows::add_row(std::span<const RowEntry> entries, double c, int64_t id)
{
  FETICON_ASSERT(_ids.empty() || id > _ids.back(), "row ids must increase");
  _entries.insert(_entries.end(), entries.begin(), entries.end());
  _offsets.push_back(static_cast<int64_t>(_entries.size()));
  _c.push_back(c);
  _ids.push_back(id);
}

void ConstraintRows::append(const ConstraintRows& other, int64_t id_offset)
{
  for (int64_t i = 0; i < other.n_rows(); ++i)
    add_row(other.row(i), other._c[i], other._ids[i] + id_offset);
}

namespace
{
bool touches_owned(const Decomposition& decomposition, std::span<const RowEntry> entries)
{
  for (const RowEntry& e : entries)
    if (decomposition.owns(e.subdomain))
      return true;
  return false;
}
} // namespace

std::span<const RowEntry> ConstraintRows::row(int64_t i) const
{
  return {_entries.data() + _offsets[i], static_cast<size_t>(_offsets[i + 1] - _offsets[i])};
}

la::Vector ConstraintRows::c_vector() const
{
  return Eigen::Map<const la::Vector>(_c.data(), static_cast<la::Index>(_c.size()));
}

namespace
{
/// Groups of equations linked by shared DOFs (union-find), each as increasing equation
/// indices, the groups in the order of their first equation.
std::vector<std::vector<size_t>> equation_groups(const std::vector<fem::ReducedEquation>& equations)
{
  std::vector<size_t> parent(equations.size());
  for (size_t e = 0; e < parent.size(); ++e)
    parent[e] = e;
  const auto root = [&](size_t e) {
    while (parent[e] != e)
      e = parent[e] = parent[parent[e]];
    return e;
  };
  std::map<int64_t, size_t> first_user;
  for (size_t e = 0; e < equations.size(); ++e)
    for (const int64_t dof : equations[e].dofs)
      if (const auto [it, added] = first_user.emplace(dof, e); !added)
      {
        const size_t a = root(it->second), b = root(e);
        parent[std::max(a, b)] = std::min(a, b);
      }
  std::map<size_t, std::vector<size_t>> by_root;
  for (size_t e = 0; e < equations.size(); ++e)
    by_root[root(e)].push_back(e);
  std::vector<std::vector<size_t>> out;
  for (auto& [r, group] : by_root)
    out.push_back(std::move(group));
  return out;
}

/// "the support of node 12 along a local axis (*TRANSFORM)" or "a support on a coupling's
/// reference node": a held combination (all on one node: a frame's axis), for messages.
std::string held_support_name(const fem::DofCombination& combination)
{
  const bool one_node =
      std::ranges::all_of(combination.dofs, [&](int64_t d) { return d / 3 == combination.dofs.front() / 3; });
  if (one_node && !combination.dofs.empty())
    return "the support of node " + std::to_string(combination.dofs.front() / 3) + " along a local axis (*TRANSFORM)";
  return "a support on a coupling's reference node";
}

/// The rows of the linear equations (build_equality_rows' comment): per equation, the global
/// DOFs and coefficients of the orthonormalized row before the split over copies, and c.
struct EquationRow
{
  std::vector<int64_t> dofs;
  std::vector<double> values;
  double c = 0;
};

/// The supports of held DOFs past the global ones (along local axes, fem/node_frames.hpp; on
/// reference nodes, fem/coupling.hpp) as equations sum_k a_k u_k = value over the global DOFs
/// of their combinations: those prescribed (`prescribed`, NaN where free) move to the
/// right-hand side, as an equation's terms on them do.
std::vector<fem::ReducedEquation> held_combination_equations(const mesh::Mesh& mesh,
                                                             const fem::ConstrainedDofs& dirichlet,
                                                             const std::vector<fem::DofCombination>& held,
                                                             const std::array<bool, 3>& eliminated,
                                                             const std::vector<double>& prescribed)
{
  std::vector<fem::ReducedEquation> out;
  for (size_t k = 0; k < dirichlet.dofs.size(); ++k)
  {
    const int64_t dof = dirichlet.dofs[k];
    if (dof < 3 * int64_t{mesh.n_nodes()})
      continue;
    const fem::DofCombination& combination = held.at(static_cast<size_t>(dof - 3 * int64_t{mesh.n_nodes()}));
    fem::ReducedEquation& eq = out.emplace_back();
    eq.rhs = dirichlet.values(static_cast<la::Index>(k)) + combination.offset;
    for (size_t t = 0; t < combination.dofs.size(); ++t)
    {
      const int64_t global = combination.dofs[t];
      if (eliminated[global % 3])
        continue;
      if (!std::isnan(prescribed[global]))
        eq.rhs -= combination.coefficients[t] * prescribed[global];
      else
      {
        eq.dofs.push_back(global);
        eq.coefficients.push_back(combination.coefficients[t]);
      }
    }
    FETICON_CHECK(!eq.dofs.empty(),
                  held_support_name(combination) << " is held, and supports hold every global DOF it combines");
  }
  return out;
}

/// The equation rows, orthonormalized (build_equality_rows' comment): `reduced` as
/// fem::reduce_equations gives them; `dependent(e)` is the message for row e, linearly
/// dependent on the supports and the rows before it.
std::vector<EquationRow> orthonormal_equation_rows(const Decomposition& decomposition,
                                                   const std::vector<fem::ReducedEquation>& reduced,
                                                   const std::function<std::string(size_t)>& dependent)
{
  std::vector<EquationRow> out(reduced.size());
  for (const std::vector<size_t>& group : equation_groups(reduced))
  {
    std::vector<int64_t> dofs;
    for (const size_t e : group)
      dofs.insert(dofs.end(), reduced[e].dofs.begin(), reduced[e].dofs.end());
    std::sort(dofs.begin(), dofs.end());
    dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
    // The split row of a DOF with p copies has a/p on each: its inner products are those of
    // a / sqrt(p), the columns of X.
    la::Vector root_copies(static_cast<la::Index>(dofs.size()));
    for (size_t k = 0; k < dofs.size(); ++k)
      root_copies(static_cast<la::Index>(k)) =
          std::sqrt(static_cast<double>(decomposition.copies(static_cast<int32_t>(dofs[k] / 3)).size()));
    const auto n_dofs = static_cast<la::Index>(dofs.size());
    const auto n_equations = static_cast<la::Index>(group.size());
    la::Matrix X = la::Matrix::Zero(n_dofs, n_equations);
    la::Vector c(n_equations);
    for (la::Index j = 0; j < n_equations; ++j)
    {
      const fem::ReducedEquation& eq = reduced[group[j]];
      for (size_t k = 0; k < eq.dofs.size(); ++k)
      {
        const auto row = std::lower_bound(dofs.begin(), dofs.end(), eq.dofs[k]) - dofs.begin();
        X(row, j) = eq.coefficients[k] / root_copies(row);
      }
      c(j) = eq.rhs;
    }
    // X = Q R by Gram-Schmidt with reorthogonalization (CGS2, which keeps Q orthonormal to
    // round-off): column j of Q combines equations 1..j (R upper triangular, R_jj > 0: the sign
    // of the equation as written), exactly zero off their DOFs, and c' = R^{-T} c. R_jj is the
    // distance of equation j from the span of the ones before it.
    la::Matrix Q(n_dofs, n_equations);
    la::Matrix R = la::Matrix::Zero(n_equations, n_equations);
    for (la::Index j = 0; j < n_equations; ++j)
    {
      la::Vector v = X.col(j);
      for (int pass = 0; pass < 2; ++pass)
        for (la::Index i = 0; i < j; ++i)
        {
          const double r = Q.col(i).dot(v);
          v -= r * Q.col(i);
          R(i, j) += r;
        }
      R(j, j) = v.norm();
      FETICON_CHECK(R(j, j) > fem::equation_dependence_tolerance * X.col(j).norm(), dependent(group[j]));
      Q.col(j) = v / R(j, j);
    }
    const la::Vector c_orthonormal = R.transpose().triangularView<Eigen::Lower>().solve(c);
    for (la::Index j = 0; j < n_equations; ++j)
    {
      EquationRow& row = out[group[j]];
      for (la::Index k = 0; k < n_dofs; ++k)
        if (Q(k, j) != 0.0)
        {
          row.dofs.push_back(dofs[k]);
          row.values.push_back(Q(k, j) * root_copies(k)); // back from a / sqrt(p) to a
        }
      row.c = c_orthonormal(j);
    }
  }
  return out;
}

/// Entries of a row over global DOFs split over the copies of each node, a / p on each of the
/// p copies (build_equality_rows' comment).
void split_over_copies(const Decomposition& decomposition, const std::vector<int64_t>& dofs,
                       const std::vector<double>& values, std::vector<RowEntry>& entries)
{
  entries.clear();
  for (size_t k = 0; k < dofs.size(); ++k)
  {
    const auto& copies = decomposition.copies(static_cast<int32_t>(dofs[k] / 3));
    const int component = static_cast<int>(dofs[k] % 3);
    const double value = values[k] / static_cast<double>(copies.size());
    for (const NodeCopy& copy : copies)
    {
      const Subdomain& sub = decomposition.subdomain(copy.subdomain);
      entries.push_back({copy.subdomain, sub.active_of_full[3 * copy.local_node + component], value});
    }
  }
}

/// The tie rows (build_equality_rows' comment), appended to `out` from id `first_id` on.
void add_tie_rows(const Decomposition& decomposition, const fem::ConstrainedDofs& dirichlet,
                  const std::vector<fem::LinearEquation>& ties, int64_t first_id, EqualityRows& out)
{
  const mesh::Mesh& mesh = decomposition.mesh();
  std::vector<char> held(3 * static_cast<size_t>(mesh.n_nodes()), 0);
  for (const int64_t dof : dirichlet.dofs)
    if (dof < 3 * int64_t{mesh.n_nodes()})
      held[dof] = 1;
  std::vector<fem::LinearEquation> kept;
  for (const fem::LinearEquation& tie : ties)
    if (!held[3 * static_cast<size_t>(tie.terms.front().node) + tie.terms.front().component])
      kept.push_back(tie);
  std::vector<RowEntry> entries;
  for (const fem::ReducedEquation& row : fem::reduce_equations(kept, 3 * static_cast<int64_t>(mesh.n_nodes()),
                                                               dirichlet, decomposition.eliminated(), &mesh))
  {
    split_over_copies(decomposition, row.dofs, row.coefficients, entries);
    double norm2 = 0;
    for (const RowEntry& e : entries)
      norm2 += e.value * e.value;
    const double scale = 1 / std::sqrt(norm2);
    for (RowEntry& e : entries)
      e.value *= scale;
    if (touches_owned(decomposition, entries))
      out.rows.add_row(entries, row.rhs * scale, first_id + out.n_ties);
    ++out.n_ties;
  }
}
} // namespace

EqualityRows build_equality_rows(const Decomposition& decomposition, const fem::ConstrainedDofs& dirichlet,
                                 const std::vector<fem::LinearEquation>& equations,
                                 const std::vector<fem::LinearEquation>& ties,
                                 const std::vector<fem::DofCombination>& held)
{
  const mesh::Mesh& mesh = decomposition.mesh();
  // Prescribed value per global DOF (NaN where free); the local ones become equation rows.
  std::vector<double> prescribed(3 * static_cast<size_t>(mesh.n_nodes()), std::numeric_limits<double>::quiet_NaN());
  for (size_t k = 0; k < dirichlet.dofs.size(); ++k)
    if (dirichlet.dofs[k] < 3 * int64_t{mesh.n_nodes()})
      prescribed[dirichlet.dofs[k]] = dirichlet.values(static_cast<la::Index>(k));

  EqualityRows out;
  std::vector<RowEntry> entries;
  ConstraintRows dirichlet_rows;
  for (int32_t node = 0; node < mesh.n_nodes(); ++node)
  {
    const auto& copies = decomposition.copies(node);
    for (int i = 0; i < 3; ++i)
    {
      const double value = prescribed[3 * static_cast<size_t>(node) + i];
      if (decomposition.eliminated()[i])
      {
        FETICON_CHECK(std::isnan(value) || value == 0.0,
                      "component " << i << " is eliminated (plane strain) but node " << node << " prescribes " << value
                                   << " for it");
        continue;
      }
      auto dof_of = [&](const NodeCopy& copy) {
        const Subdomain& sub = decomposition.subdomain(copy.subdomain);
        return sub.active_of_full[3 * copy.local_node + i];
      };
      if (!std::isnan(value))
      {
        for (const NodeCopy& copy : copies)
        {
          const RowEntry e{copy.subdomain, dof_of(copy), 1.0};
          if (decomposition.owns(copy.subdomain))
            dirichlet_rows.add_row({&e, 1}, value, out.n_dirichlet);
          ++out.n_dirichlet;
        }
        continue;
      }
      for (size_t q = 1; q < copies.size(); ++q)
      {
        entries.clear();
        const double scale = 1.0 / std::sqrt(static_cast<double>(q * (q + 1)));
        for (size_t t = 0; t < q; ++t)
          entries.push_back({copies[t].subdomain, dof_of(copies[t]), scale});
        entries.push_back({copies[q].subdomain, dof_of(copies[q]), -static_cast<double>(q) * scale});
        if (touches_owned(decomposition, entries))
          out.rows.add_row(entries, 0.0, out.n_gluing);
        ++out.n_gluing;
      }
    }
  }
  out.rows.append(dirichlet_rows, out.n_gluing);

  const int64_t first_equation_id = out.n_gluing + out.n_dirichlet;
  std::vector<fem::ReducedEquation> reduced =
      held_combination_equations(mesh, dirichlet, held, decomposition.eliminated(), prescribed);
  const size_t n_local = reduced.size();
  for (fem::ReducedEquation& eq : fem::reduce_equations(equations, 3 * static_cast<int64_t>(mesh.n_nodes()), dirichlet,
                                                        decomposition.eliminated(), &mesh))
    reduced.push_back(std::move(eq));
  const auto dependent = [&](size_t e) {
    if (e >= n_local)
      return fem::dependent_equation_message(equations, e - n_local, &mesh);
    size_t seen = 0; // the e-th held combination
    for (const int64_t dof : dirichlet.dofs)
      if (dof >= 3 * int64_t{mesh.n_nodes()} && seen++ == e)
        return held_support_name(held.at(static_cast<size_t>(dof - 3 * int64_t{mesh.n_nodes()}))) +
            " is linearly dependent on the supports and equations before it";
    return std::string("a held combination is linearly dependent");
  };
  for (const EquationRow& row : orthonormal_equation_rows(decomposition, reduced, dependent))
  {
    split_over_copies(decomposition, row.dofs, row.values, entries);
    if (touches_owned(decomposition, entries))
      out.rows.add_row(entries, row.c, first_equation_id + out.n_equations);
    ++out.n_equations;
  }
  add_tie_rows(decomposition, dirichlet, ties, first_equation_id + out.n_equations, out);
  return out;
}

ConstraintRows rows_from_global(const Decomposition& decomposition,
                                const Eigen::SparseMatrix<double, Eigen::RowMajor>& B_global, const la::Vector& c)
{
  FETICON_CHECK(B_global.cols() == 3 * decomposition.mesh().n_nodes() && B_global.rows() == c.size(),
                "constraint rows do not match the mesh");
  ConstraintRows rows;
  std::vector<RowEntry> entries;
  for (int r = 0; r < B_global.outerSize(); ++r)
  {
    entries.clear();
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(B_global, r); it; ++it)
    {
      const int32_t node = static_cast<int32_t>(it.col() / 3);
      const int component = static_cast<int>(it.col() % 3);
      const auto& copies = decomposition.copies(node);
      FETICON_CHECK(!copies.empty(), "constraint on node " << node << " outside every subdomain");
      const Subdomain& sub = decomposition.subdomain(copies.front().subdomain);
      const int32_t dof = sub.active_of_full[3 * copies.front().local_node + component];
      // An eliminated component is identically zero, so its entry contributes nothing
      // (in the deformed configuration normals pick up round-off out of plane).
      if (dof < 0)
        continue;
      entries.push_back({copies.front().subdomain, dof, it.value()});
    }
    if (touches_owned(decomposition, entries))
      rows.add_row(entries, c(r), r);
  }
  return rows;
}
} // namespace feticon::decomposition

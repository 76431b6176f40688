#include "decomposition/constraint_rows.hpp"

#include "common/error.hpp"

#include <cmath>

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

EqualityRows build_equality_rows(const Decomposition& decomposition,
                                 const fem::ConstrainedDofs& dirichlet)
{
  const mesh::HexMesh& mesh = decomposition.mesh();
  // Prescribed value per global DOF (NaN where free).
  std::vector<double> prescribed(3 * static_cast<size_t>(mesh.n_nodes()),
                                 std::numeric_limits<double>::quiet_NaN());
  for (size_t k = 0; k < dirichlet.dofs.size(); ++k)
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
                      "component " << i << " is eliminated (plane strain) but node " << node
                                   << " prescribes " << value << " for it");
        continue;
      }
      auto dof_of = [&](const NodeCopy& copy)
      {
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
  return out;
}

ConstraintRows rows_from_global(const Decomposition& decomposition,
                                const Eigen::SparseMatrix<double, Eigen::RowMajor>& B_global,
                                const la::Vector& c)
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

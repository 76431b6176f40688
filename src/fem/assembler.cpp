#include "fem/assembler.hpp"

#include "common/error.hpp"
#include "fem/cell_element.hpp"
#include "fem/plastic_states.hpp"

#include <algorithm>
#include <limits>

namespace feticon::fem
{
namespace
{
/// Node-node adjacency of the cells in local numbering, sorted and unique per node, in
/// compressed form: the neighbours of node n are neighbours[offsets[n], offsets[n + 1]).
NodeAdjacency node_adjacency(const AssemblyDomain& domain)
{
  std::vector<std::vector<int32_t>> lists(domain.n_nodes());
  for (const auto& cell : domain.cell_nodes)
    for (int32_t a : cell)
      for (int32_t b : cell)
        lists[a].push_back(b);
  NodeAdjacency adjacency;
  adjacency.offsets.reserve(lists.size() + 1);
  adjacency.offsets.push_back(0);
  for (auto& list : lists)
  {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
    adjacency.neighbours.insert(adjacency.neighbours.end(), list.begin(), list.end());
    adjacency.offsets.push_back(static_cast<int64_t>(adjacency.neighbours.size()));
    std::vector<int32_t>().swap(list);
  }
  adjacency.neighbours.shrink_to_fit();
  const int64_t nnz = 9 * static_cast<int64_t>(adjacency.neighbours.size());
  FETICON_CHECK(nnz < std::numeric_limits<int>::max(),
                "stiffness has " << nnz << " nonzeros, more than 32-bit indices allow; "
                                 << "use more subdomains");
  return adjacency;
}

/// Zero matrix with the CSC pattern where column 3n+j holds rows 3m+i for every neighbour
/// m of n.
la::SparseMatrix block_pattern(const NodeAdjacency& adjacency)
{
  const int64_t n_nodes = static_cast<int64_t>(adjacency.offsets.size()) - 1;
  const int64_t n_dofs = 3 * n_nodes;
  const int64_t nnz = 9 * static_cast<int64_t>(adjacency.neighbours.size());
  la::SparseMatrix K(n_dofs, n_dofs);
  K.resizeNonZeros(nnz);
  int* outer = K.outerIndexPtr();
  int* inner = K.innerIndexPtr();
  int64_t pos = 0;
  for (int64_t n = 0; n < n_nodes; ++n)
    for (int j = 0; j < 3; ++j)
    {
      outer[3 * n + j] = static_cast<int>(pos);
      for (int64_t k = adjacency.offsets[n]; k < adjacency.offsets[n + 1]; ++k)
        for (int i = 0; i < 3; ++i)
          inner[pos++] = 3 * adjacency.neighbours[k] + i;
    }
  outer[n_dofs] = static_cast<int>(pos);
  std::fill(K.valuePtr(), K.valuePtr() + nnz, 0.0);
  return K;
}

/// Adds the element matrix into K (whose pattern contains it).
template <class Matrix>
void scatter(la::SparseMatrix& K, std::span<const int32_t> local_nodes, const Matrix& Ke)
{
  const int* outer = K.outerIndexPtr();
  const int* inner = K.innerIndexPtr();
  double* values = K.valuePtr();
  const int n = static_cast<int>(local_nodes.size());
  for (int b = 0; b < n; ++b)
  {
    const int col0 = 3 * local_nodes[b];
    const int* begin = inner + outer[col0];
    const int* end = inner + outer[col0 + 1];
    for (int a = 0; a < n; ++a)
    {
      // Columns 3n, 3n+1, 3n+2 share one structure, so one search serves all three.
      const int offset = static_cast<int>(std::lower_bound(begin, end, 3 * local_nodes[a]) - begin);
      FETICON_ASSERT(begin + offset < end && begin[offset] == 3 * local_nodes[a],
                     "element entry outside the sparsity pattern");
      for (int j = 0; j < 3; ++j)
      {
        double* column = values + outer[col0 + j] + offset;
        for (int i = 0; i < 3; ++i)
          column[i] += Ke(3 * a + i, 3 * b + j);
      }
    }
  }
}
/// Adds one cell's force and stiffness (the latter if K is not null).
template <class Vector, class Matrix>
void add_cell(std::span<const int32_t> local, const Vector& fe, const Matrix& Ke, la::Vector* f_int,
              la::SparseMatrix* K)
{
  if (f_int)
    for (size_t a = 0; a < local.size(); ++a)
      f_int->segment<3>(3 * local[a]) += fe.template segment<3>(3 * a);
  if (K)
    scatter(*K, local, Ke);
}
} // namespace

AssemblyDomain make_domain(const mesh::Mesh& mesh, std::vector<int32_t> cells)
{
  AssemblyDomain domain;
  domain.cells = std::move(cells);
  // Work proportional to the domain's cells, never to the mesh: a run makes one domain
  // per subdomain.
  auto& nodes = domain.local_to_global;
  size_t n_entries = 0;
  for (int32_t c : domain.cells)
  {
    FETICON_CHECK(c >= 0 && c < mesh.n_cells(), "cell id " << c << " out of range");
    n_entries += mesh.cells[c].size();
  }
  nodes.reserve(n_entries);
  for (int32_t c : domain.cells)
  {
    FETICON_CHECK(c >= 0 && c < mesh.n_cells(), "cell id " << c << " out of range");
    nodes.insert(nodes.end(), mesh.cells[c].begin(), mesh.cells[c].end());
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  nodes.shrink_to_fit();
  domain.cell_nodes.reserve(domain.cells.size(), n_entries);
  std::vector<int32_t> local;
  for (const int32_t c : domain.cells)
  {
    local.clear();
    for (const int32_t n : mesh.cells[c])
      local.push_back(static_cast<int32_t>(std::lower_bound(nodes.begin(), nodes.end(), n) - nodes.begin()));
    domain.cell_nodes.add(mesh.cells.kind(c), local);
  }
  return domain;
}

AssemblyDomain whole_mesh_domain(const mesh::Mesh& mesh)
{
  std::vector<int32_t> cells(mesh.n_cells());
  for (int32_t c = 0; c < mesh.n_cells(); ++c)
    cells[c] = c;
  return make_domain(mesh, std::move(cells));
}

Assembler::Assembler(const mesh::Mesh& mesh, AssemblyDomain domain, std::vector<Material> body_materials,
                     Kinematics kinematics)
    : _mesh(mesh), _domain(std::move(domain)), _materials(std::move(body_materials)), _kinematics(kinematics),
      _adjacency(node_adjacency(_domain))
{
  FETICON_CHECK(static_cast<int32_t>(_materials.size()) >= mesh.n_bodies(),
                "the mesh has " << mesh.n_bodies() << " bodies but " << _materials.size() << " materials were given");
  const auto body_name = [&](size_t b) { return b < mesh.body_names.size() ? mesh.body_names[b] : std::to_string(b); };
  for (size_t b = 0; b < _materials.size(); ++b)
    _materials[b].check("material of body '" + body_name(b) + "'");
  _plastic_offset.assign(1, 0);
  for (size_t k = 0; k < _domain.cells.size(); ++k)
  {
    const int32_t c = _domain.cells[k];
    const size_t points = plastic_points(mesh, _materials, c);
    // Simo's finite-strain J2 (fem/finite_j2_plasticity.hpp) has no thermal strain.
    FETICON_CHECK(points == 0 || kinematics == Kinematics::linear || _materials[mesh.cell_body[c]].expansion == 0,
                  "body '" << body_name(static_cast<size_t>(mesh.cell_body[c]))
                           << "' is plastic and expands with temperature: thermal strain in J2 plasticity is "
                              "implemented at small strain only (displacements = small, no NLGEOM)");
    _plastic_offset.push_back(_plastic_offset.back() + static_cast<int64_t>(points));
  }
  for (size_t b = 0; b < _materials.size(); ++b)
    FETICON_CHECK(!_materials[b].is_hyperelastic() || kinematics == Kinematics::total_lagrangian,
                  "body '" << body_name(b)
                           << "' is hyperelastic, which needs large displacements (displacements = large, NLGEOM)");
  _plastic_committed.resize(static_cast<size_t>(_plastic_offset.back()));
}

bool Assembler::has_hyperelastic_cells() const
{
  return std::ranges::any_of(_domain.cells,
                             [&](int32_t c) { return _materials[_mesh.cell_body[c]].is_hyperelastic(); });
}

void Assembler::assemble(const la::Vector& u, StiffnessKind kind, la::SparseMatrix* K, la::Vector* f_int) const
{
  assemble_cells(u, kind, K, f_int, nullptr);
}

void Assembler::commit_plastic_state(const la::Vector& u)
{
  if (_plastic_committed.empty())
    return;
  std::vector<PlasticPointState> updated(_plastic_committed.size());
  assemble_cells(u, StiffnessKind::none, nullptr, nullptr, &updated);
  _plastic_committed = std::move(updated);
}

std::span<const PlasticPointState> Assembler::plastic_state(size_t k) const
{
  return std::span<const PlasticPointState>(_plastic_committed)
      .subspan(static_cast<size_t>(_plastic_offset[k]),
               static_cast<size_t>(_plastic_offset[k + 1] - _plastic_offset[k]));
}

void Assembler::set_plastic_state(std::vector<PlasticPointState> states)
{
  FETICON_CHECK(states.size() == _plastic_committed.size(),
                "plastic state of " << states.size() << " points, the domain has " << _plastic_committed.size());
  _plastic_committed = std::move(states);
}

void Assembler::assemble_cells(const la::Vector& u, StiffnessKind kind, la::SparseMatrix* K, la::Vector* f_int,
                               std::vector<PlasticPointState>* updated) const
{
  FETICON_CHECK(u.size() == _domain.n_dofs(),
                "displacement has " << u.size() << " entries, expected " << _domain.n_dofs());
  if (K)
  {
    la::SparseMatrix pattern = block_pattern(_adjacency);
    K->swap(pattern);
  }
  if (f_int)
    f_int->setZero(_domain.n_dofs());
  const StiffnessKind element_kind = K ? kind : StiffnessKind::none;
  NodeCoords X, ue;
  ElementVector fe;
  ElementMatrix Ke;
  Eigen::MatrixX3d X_any, u_any;
  Eigen::VectorXd fe_any;
  Eigen::MatrixXd Ke_any;
  const bool thermal = _temperature_change.size() > 0;
  NodeTemperatures dT;
  Eigen::VectorXd dT_any;
  for (size_t k = 0; k < _domain.cells.size(); ++k)
  {
    const int32_t c = _domain.cells[k];
    const std::span<const int32_t> cell = _mesh.cells[c];
    const std::span<const int32_t> local = _domain.cell_nodes[k];
    const mesh::CellKind type = _mesh.cells.kind(c);
    const Material& material = _materials[_mesh.cell_body[c]];
    if (type == mesh::CellKind::hex8 && material.is_st_venant_kirchhoff())
    {
      for (int a = 0; a < 8; ++a)
      {
        X.row(a) = _mesh.nodes.row(cell[a]);
        ue.row(a) = u.segment<3>(3 * local[a]).transpose();
        if (thermal)
          dT(a) = _temperature_change(local[a]);
      }
      hex8_element(X, ue, material, _kinematics, element_kind, fe, &Ke, c, thermal ? &dT : nullptr);
      add_cell(local, fe, Ke, f_int, K);
      continue;
    }
    const auto n = static_cast<Eigen::Index>(cell.size());
    X_any.resize(n, 3);
    u_any.resize(n, 3);
    dT_any.resize(n);
    for (Eigen::Index a = 0; a < n; ++a)
    {
      X_any.row(a) = _mesh.nodes.row(cell[a]);
      u_any.row(a) = u.segment<3>(3 * local[a]).transpose();
      dT_any(a) = thermal ? _temperature_change(local[a]) : 0.0;
    }
    const Integration integration = _mesh.reduced(c) ? Integration::reduced : Integration::full;
    CellPlasticState plastic{plastic_state(k), {}};
    if (updated)
      plastic.updated = std::span<PlasticPointState>(*updated).subspan(static_cast<size_t>(_plastic_offset[k]),
                                                                       plastic.committed.size());
    cell_element(type, X_any, u_any, material, _kinematics, element_kind, integration, fe_any, &Ke_any, c,
                 thermal ? &dT_any : nullptr, &plastic, _mesh.planar_of_cell(c));
    add_cell(local, fe_any, Ke_any, f_int, K);
  }
}

void Assembler::set_temperature_change(la::Vector temperature_change)
{
  FETICON_CHECK(temperature_change.size() == 0 || temperature_change.size() == _domain.n_nodes(),
                "temperature change of " << temperature_change.size() << " nodes, the domain has "
                                         << _domain.n_nodes());
  _temperature_change = std::move(temperature_change);
}

la::SparseMatrix Assembler::stiffness(const la::Vector& u, StiffnessKind kind) const
{
  la::SparseMatrix K;
  assemble(u, kind, &K, nullptr);
  return K;
}

la::Vector Assembler::internal_force(const la::Vector& u) const
{
  la::Vector f;
  assemble(u, StiffnessKind::none, nullptr, &f);
  return f;
}

Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> Assembler::local_coordinates() const
{
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> X(_domain.n_nodes(), 3);
  for (int32_t n = 0; n < _domain.n_nodes(); ++n)
    X.row(n) = _mesh.nodes.row(_domain.local_to_global[n]);
  return X;
}
} // namespace feticon::fem

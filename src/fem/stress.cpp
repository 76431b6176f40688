#include "fem/stress.hpp"

#include "fem/cell_element.hpp"
#include "fem/hex8_element.hpp"

#include "common/parallel.hpp"

namespace feticon::fem
{
void gather_cell(const mesh::Mesh& mesh, int32_t c, const la::Vector& u, const la::Vector& temperature_change,
                 Eigen::MatrixX3d& X, Eigen::MatrixX3d& u_cell, Eigen::VectorXd& dT)
{
  const std::span<const int32_t> cell = mesh.cells[c];
  X.resize(static_cast<Eigen::Index>(cell.size()), 3);
  u_cell.resize(X.rows(), 3);
  dT.setZero(X.rows());
  for (size_t a = 0; a < cell.size(); ++a)
  {
    X.row(a) = mesh.nodes.row(cell[a]);
    u_cell.row(a) = u.segment<3>(3 * cell[a]).transpose();
    if (temperature_change.size() > 0)
      dT(a) = temperature_change(cell[a]);
  }
}

std::vector<Eigen::Matrix<double, 6, 1>> cell_cauchy_stresses(const mesh::Mesh& mesh, const la::Vector& u,
                                                              const std::vector<Material>& body_materials,
                                                              Kinematics kinematics,
                                                              const la::Vector& temperature_change,
                                                              const MeshPlasticStates* plastic)
{
  std::vector<Eigen::Matrix<double, 6, 1>> stresses(mesh.n_cells());
  const bool thermal = temperature_change.size() > 0;
  // Cells in chunks on the threads (each writes its own cells' stresses): the stresses are
  // taken twice in a run (contact pressures and the VTU), a twentieth of the 2D Hertz run.
  parallel_for_chunks(static_cast<size_t>(mesh.n_cells()), 256, [&](size_t begin, size_t end) {
    NodeCoords X, ue;
    NodeTemperatures dT = NodeTemperatures::Zero();
    Eigen::MatrixX3d X_any, u_any;
    Eigen::VectorXd dT_any;
    for (auto c = static_cast<int32_t>(begin); c < static_cast<int32_t>(end); ++c)
    {
      const mesh::CellKind type = mesh.cells.kind(c);
      const std::span<const PlasticPointState> states = plastic ? plastic->of(c) : std::span<const PlasticPointState>{};
      if (type != mesh::CellKind::hex8 || !states.empty() || body_materials[mesh.cell_body[c]].is_hyperelastic())
      {
        gather_cell(mesh, c, u, temperature_change, X_any, u_any, dT_any);
        stresses[c] = cell_cauchy_stress(type, X_any, u_any, body_materials[mesh.cell_body[c]], kinematics, c,
                                         mesh.reduced(c) ? Integration::reduced : Integration::full,
                                         thermal ? &dT_any : nullptr, states, mesh.planar_of_cell(c));
        continue;
      }
      for (int a = 0; a < 8; ++a)
      {
        X.row(a) = mesh.nodes.row(mesh.cells[c][a]);
        ue.row(a) = u.segment<3>(3 * mesh.cells[c][a]).transpose();
        if (thermal)
          dT(a) = temperature_change(mesh.cells[c][a]);
      }
      stresses[c] =
          hex8_cauchy_stress(X, ue, body_materials[mesh.cell_body[c]], kinematics, c, thermal ? &dT : nullptr);
    }
  });
  return stresses;
}

std::vector<Eigen::Matrix<double, 6, 1>> nodal_average(const mesh::Mesh& mesh,
                                                       const std::vector<Eigen::Matrix<double, 6, 1>>& cell_values)
{
  std::vector<Eigen::Matrix<double, 6, 1>> sum(mesh.n_nodes(), Eigen::Matrix<double, 6, 1>::Zero());
  std::vector<int> count(mesh.n_nodes(), 0);
  for (int32_t c = 0; c < mesh.n_cells(); ++c)
    for (int32_t node : mesh.cells[c])
    {
      sum[node] += cell_values[c];
      ++count[node];
    }
  for (int32_t n = 0; n < mesh.n_nodes(); ++n)
    if (count[n] > 0)
      sum[n] /= count[n];
  return sum;
}
} // namespace feticon::fem

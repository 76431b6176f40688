#include "problems/cantilever_obstacle.hpp"

#include "common/error.hpp"
#include "mesh/box.hpp"

namespace feticon::problems
{
double cantilever_tip_load(const CantileverObstacleParameters& p)
{
  const double E_plane = p.material.young / (1 - p.material.poisson * p.material.poisson);
  const double I = p.depth * p.depth * p.depth * p.depth / 12; // thickness = depth
  return p.linear_deflection_ratio * p.length * 3 * E_plane * I / (p.length * p.length * p.length);
}

namespace
{
/// The beam and the obstacle.
std::pair<mesh::BoxParameters, mesh::BoxParameters> boxes(const CantileverObstacleParameters& p)
{
  FETICON_CHECK(p.length > 0 && p.depth > 0 && p.gap > 0 && p.cells_along >= 10,
                "cantilever_obstacle: length, depth, gap must be positive and cells_along >= 10");
  mesh::BoxParameters beam;
  beam.lengths = Eigen::Vector3d(p.length, p.depth, p.depth);
  beam.nx = p.cells_along;
  beam.ny = std::max(2, p.cells_along / 10);
  beam.nz = 1;
  beam.body_name = "beam";
  mesh::BoxParameters obstacle;
  const double obstacle_length = 1.2 * p.length - p.obstacle_start;
  obstacle.origin = Eigen::Vector3d(p.obstacle_start, -p.gap - 0.2 * p.length, 0);
  obstacle.lengths = Eigen::Vector3d(obstacle_length, 0.2 * p.length, p.depth);
  // Master faces about 1.5 times the beam's cells: non-matching contact meshes.
  obstacle.nx = std::max(2, static_cast<int>(obstacle_length / (1.5 * p.length / p.cells_along)));
  obstacle.ny = 4;
  obstacle.nz = 1;
  obstacle.body_name = "obstacle";
  return {beam, obstacle};
}
} // namespace

int64_t cantilever_obstacle_node_count(const CantileverObstacleParameters& p)
{
  int64_t nodes = 0;
  for (const mesh::BoxParameters& b : {boxes(p).first, boxes(p).second})
    nodes += int64_t(b.nx + 1) * (b.ny + 1) * (b.nz + 1);
  return nodes;
}

fem::Problem cantilever_obstacle_problem(const CantileverObstacleParameters& p)
{
  const auto [beam, obstacle] = boxes(p);
  fem::Problem problem;
  problem.name = "cantilever_obstacle";
  problem.mesh = mesh::generate_box(obstacle);
  mesh::append_mesh(problem.mesh, mesh::generate_box(beam), "beam_");
  problem.materials.assign(2, p.material);
  problem.eliminated = {false, false, true};
  problem.steps.front().dirichlet = {{"beam_xmin", {0.0, 0.0, std::nullopt}}, {"ymin", {0.0, 0.0, std::nullopt}}};
  const double area = p.depth * p.depth;
  problem.steps.front().tractions = {{"beam_xmax", Eigen::Vector3d(0, -cantilever_tip_load(p) / area, 0)}};
  problem.contacts = {{"beam_ymin", "ymax"}};
  problem.validate();
  return problem;
}
} // namespace feticon::problems

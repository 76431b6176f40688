#pragma once
/// @file A finite-rotation contact problem: a cantilever bent far down onto an obstacle.
///
/// Beam [0, L] x [0, h] clamped at x = 0 and loaded by a downward dead traction on its free
/// end; obstacle block below the beam's outer part, top face at y = -gap, fixed at its
/// bottom. Plane strain (one element layer, u_z eliminated). The beam's bottom face
/// ("beam_ymin", slave) lands on the obstacle top ("ymax", master) after rotating by tens of
/// degrees, so small-displacement kinematics (no shortening, contact in the reference
/// configuration) is visibly wrong.

#include "fem/problem.hpp"
#include "problems/built_in_problem.hpp"

namespace feticon::problems
{
struct CantileverObstacleParameters
{
  double length = 1.0;         ///< L (m)
  double depth = 0.05;         ///< h (m), also the thickness in z
  double gap = 0.25;           ///< distance from the beam's bottom to the obstacle top (m)
  double obstacle_start = 0.4; ///< x of the obstacle's left face (m)
  /// Tip load as the linear-theory tip deflection P L^3 / (3 E' I) it would cause, over L.
  double linear_deflection_ratio = 0.8;
  int cells_along = 40; ///< beam cells along x (cells through the depth: cells_along / 10)
  fem::Material material{2.0e11, 0.3};
};

fem::Problem cantilever_obstacle_problem(const CantileverObstacleParameters& parameters);

/// Nodes of the mesh cantilever_obstacle_problem builds, counted without building it.
int64_t cantilever_obstacle_node_count(const CantileverObstacleParameters& parameters);

/// Total tip load P (N) of the parameters.
double cantilever_tip_load(const CantileverObstacleParameters& parameters);

/// The `cantilever.*` keys (problems/built_in_problem.hpp).
std::vector<io::SettingSpec> cantilever_obstacle_setting_specs();
/// The parameters of the `cantilever.*` and `material.*` settings.
CantileverObstacleParameters cantilever_obstacle_parameters(const io::Settings& settings);
std::unique_ptr<BuiltInProblem> make_cantilever_obstacle_problem(const io::Settings& settings);
} // namespace feticon::problems

#pragma once
/// @file Body loads: forces per unit volume rho b(x) on the reference configuration (dead
/// loads, in small and large displacements alike), as CalculiX's *DLOAD GRAV and CENTRIF:
///   gravity      b = g                                   (g: the acceleration vector, m/s^2)
///   centrifugal  b = omega^2 (r - (r . a) a), r = x - p  (axis through p along the unit a)
/// with rho the density of the cell's body (fem::Material::density). Their consistent nodal
/// forces f_a = sum over cells of the integral of N_a rho b dV use each cell type's full
/// quadrature rule (fem/reference_element.hpp), exact for gravity (the integrand is the shape
/// function times a constant) on cells whose Jacobian the rule integrates exactly.

#include "fem/material.hpp"
#include "la/types.hpp"
#include "mesh/mesh.hpp"

#include <Eigen/Dense>

#include <string>
#include <vector>

namespace feticon::fem
{
struct BodyLoad
{
  enum class Kind
  {
    gravity,
    centrifugal
  };
  Kind kind = Kind::gravity;
  std::vector<int32_t> cells;                        ///< the loaded cells; empty: every cell
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero(); ///< g (m/s^2)
  double omega2 = 0;                                 ///< omega^2 (1/s^2)
  Eigen::Vector3d point = Eigen::Vector3d::Zero();   ///< a point of the axis (m)
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();   ///< the axis's direction (normalized on use)
  std::string where = "body load";                   ///< for messages (the deck line, the file key)
  std::string amplitude = {};                        ///< fem::Problem::amplitudes name; empty: the step's ramp
};

/// Adds the consistent nodal forces of `load` to f (3 per node). Throws feticon::Error naming
/// load.where if a loaded cell's body has no positive density, a value is not finite or the
/// centrifugal axis is zero.
void add_body_load(const mesh::Mesh& mesh, const std::vector<Material>& materials, const BodyLoad& load, la::Vector& f);
} // namespace feticon::fem

#pragma once
/// @file External forces: face tractions and nodal forces (dead loads, reference configuration).

#include "la/types.hpp"
#include "mesh/mesh.hpp"

#include <vector>

namespace feticon::fem
{
/// Adds the consistent nodal forces of a uniform traction `traction` (Pa, force per
/// reference area) on `faces` to the global vector `f` (3 DOFs per mesh node), integrating
/// each face with its quadrature (fem/reference_face.hpp).
void add_face_traction(const mesh::Mesh& mesh, const std::vector<mesh::Face>& faces, const Eigen::Vector3d& traction,
                       la::Vector& f);

/// Adds a uniform normal pressure (Pa, positive pushes into the body) on `faces`.
void add_face_pressure(const mesh::Mesh& mesh, const std::vector<mesh::Face>& faces, double pressure, la::Vector& f);

/// Adds `total_force` (N) split equally over `nodes`.
void add_nodal_force(const std::vector<int32_t>& nodes, const Eigen::Vector3d& total_force, la::Vector& f);

/// Reference area of a set of faces (m^2).
double face_set_area(const mesh::Mesh& mesh, const std::vector<mesh::Face>& faces);
} // namespace feticon::fem

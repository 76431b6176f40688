#pragma once
/// @file Stress recovery per cell for output and post-processing.

#include "fem/material.hpp"
#include "fem/plastic_states.hpp"
#include "la/types.hpp"
#include "mesh/mesh.hpp"

#include <vector>

namespace feticon::fem
{
/// Cell c's node coordinates X and displacements u_cell (one row per node) and, where
/// `temperature_change` (per mesh node) is not empty, its nodes' temperature changes dT (else
/// zeros), from mesh-wide vectors (u: 3 DOFs per mesh node).
void gather_cell(const mesh::Mesh& mesh, int32_t c, const la::Vector& u, const la::Vector& temperature_change,
                 Eigen::MatrixX3d& X, Eigen::MatrixX3d& u_cell, Eigen::VectorXd& dT);

/// Volume-averaged Cauchy stress of every cell (Pa), Voigt [11,22,33,12,23,31].
/// @param u global displacement (3 DOFs per mesh node)
/// @param temperature_change T - T_0 per mesh node (K); empty: none
/// @param plastic the J2 states of the plastic cells (ContactSolution::plastic); null or empty:
///                no plastic body
std::vector<Eigen::Matrix<double, 6, 1>> cell_cauchy_stresses(const mesh::Mesh& mesh, const la::Vector& u,
                                                              const std::vector<Material>& body_materials,
                                                              Kinematics kinematics,
                                                              const la::Vector& temperature_change = {},
                                                              const MeshPlasticStates* plastic = nullptr);

/// Nodal average of cell stresses (each node: mean over its cells, within one body).
std::vector<Eigen::Matrix<double, 6, 1>> nodal_average(const mesh::Mesh& mesh,
                                                       const std::vector<Eigen::Matrix<double, 6, 1>>& cell_values);
} // namespace feticon::fem

#pragma once
/// @file Kernel R of a floating subdomain stiffness from node coordinates.
///
/// For node (x,y,z) relative to the centroid the 3x6 block is
///   [1 0 0   0   z  -y]
///   [0 1 0  -z   0   x]
///   [0 0 1   y  -x   0]
/// (translations, then rotations about x, y, z; ALGORITHMS.md section 2). Components
/// eliminated for the whole problem (plane strain) remove the modes that move them:
/// the kernel is the subspace of rigid modes vanishing on eliminated DOFs (3 modes in
/// plane strain). In axisymmetry (x = r) a radial displacement strains the hoops, so the modes
/// vanish on the x components too: one mode, the axial translation. Columns are
/// orthonormalized (R' R = I).

#include "la/types.hpp"

#include <array>
#include <optional>
#include <vector>

namespace feticon::decomposition
{
/// @param coords           one row per local node: reference X for K_0, current x for K_M(u)
/// @param full_of_active   active DOF -> local full DOF 3n+i
/// @param axisymmetric     the cells are axisymmetric (mesh::PlanarKind::axisymmetric)
/// @return n_active x k orthonormal basis of the kernel (k = 6 without eliminations)
la::Matrix rigid_body_modes(const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>& coords,
                            const std::vector<int32_t>& full_of_active, bool axisymmetric = false);

/// Largest subdomain (active DOFs) whose kernel zero_energy_modes computes densely.
inline constexpr la::Index max_dense_kernel_dofs = 1500;

/// The kernel of K itself where it is larger than the rigid-body modes': a cell with reduced
/// integration alone in its subdomain (CalculiX's plate: one CPS8R a body) has zero-energy
/// (hourglass) modes, which do not survive in a mesh of several cells. The space of the
/// eigenvectors of the dense K whose eigenvalues are below 1e-10 of the largest, as `rigid`
/// followed by an orthonormal basis of the rest that does not depend on the round-off of K;
/// none (nullopt) where that space is no larger than rigid's, K has a clearly negative
/// eigenvalue, or K has more than max_dense_kernel_dofs rows.
/// @param K_lower the lower triangle of the symmetric K (active DOFs)
/// @param rigid   the rigid-body modes (rigid_body_modes: orthonormal)
std::optional<la::Matrix> zero_energy_modes(const la::SparseMatrix& K_lower, const la::Matrix& rigid);
} // namespace feticon::decomposition

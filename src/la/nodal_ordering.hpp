#pragma once
/// @file A fill-reducing ordering of a 3D elasticity matrix from its node graph.
///
/// CHOLMOD's default analysis orders the DOF graph by AMD and, where AMD fills in much (every
/// 3D subdomain of hertz3d), again by METIS, and keeps the better. The matrix of a 3D solid
/// is a graph of nodes with 3 x 3 blocks: METIS's nested dissection of the node graph (a
/// third of the vertices, a ninth of the edges) gives the same fill (hertz3d 121k: 45.65 M
/// entries in the K+ factors against 45.53 M) and leaves CHOLMOD only the symbolic
/// factorization (docs/benchmarks.md).

#include "la/types.hpp"

#include <optional>
#include <vector>

namespace feticon::la
{
/// The DOF ordering (perm[k] = the DOF eliminated k-th, CHOLMOD's Perm) from METIS_NodeND on
/// the node graph of A's lower triangle mirrored (the part CHOLMOD reads). A node is a run of
/// consecutive columns with the same rows: the DOFs of a mesh node (fewer than three where a
/// generalized inverse fixed some). nullopt below `min_dofs` and where the nodes average
/// fewer than 2.5 DOFs (2D, scalar problems): there CHOLMOD's AMD is cheap and often better.
/// Draws METIS's random numbers: call it where CHOLMOD's own analysis would run
/// (metis_random.hpp).
std::optional<std::vector<int>> nodal_nested_dissection(const SparseMatrix& A, Index min_dofs);
} // namespace feticon::la

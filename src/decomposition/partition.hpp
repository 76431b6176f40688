#pragma once
/// @file Partitioning the cells of a mesh into subdomains.
///
/// Every subdomain lies in one body and is connected through faces, so that its kernel
/// is exactly the rigid-body modes (6 in 3D). All partitioners enforce this: bodies
/// are partitioned separately and disconnected pieces are split into separate subdomains.

#include "mesh/mesh.hpp"

#include <array>
#include <vector>

namespace feticon::decomposition
{
/// Subdomain id of every cell, ids 0..n_subdomains-1, every id used.
struct Partition
{
  std::vector<int32_t> cell_subdomain;
  int32_t n_subdomains = 0;
};

/// Structured partition: the bounding box of each body's cell centroids is cut into
/// parts[0] x parts[1] x parts[2] equal boxes (for a box mesh with n_i divisible by
/// parts[i], subdomains of exactly H/h elements per direction).
Partition partition_structured(const mesh::Mesh& mesh, std::array<int, 3> parts);

/// METIS k-way partition of the cell dual graph (cells adjacent through faces, weighed by the
/// faces' areas: parts compact in space on graded meshes) into about `n_subdomains` parts,
/// shared among bodies in proportion to their cell counts.
Partition partition_metis(const mesh::Mesh& mesh, int n_subdomains);

/// Recursive coordinate bisection: each body's cells are halved along the axis of largest
/// extent (in cells) until about `n_subdomains` parts, shared among bodies like METIS.
Partition partition_rcb(const mesh::Mesh& mesh, int n_subdomains);

/// Splits every subdomain that is not face-connected into its connected pieces.
Partition split_disconnected(const mesh::Mesh& mesh, const Partition& partition);
} // namespace feticon::decomposition

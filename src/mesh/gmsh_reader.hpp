#pragma once
/// @file Reading Gmsh .msh files (format 2.2 or 4.x, ASCII or binary) into a Mesh through the
/// Gmsh C++ API, called in the Gmsh module (gmsh_module.hpp; the reading is in
/// gmsh/model_reader.cpp). A file read before comes from the mesh cache (mesh_cache.hpp).
///
/// What the file must contain, and what becomes of it:
///   - 3D physical groups are the bodies, one body per group, named by the physical name, in
///     the order of the group tags. Their elements are 4- and 10-node tetrahedra, 8- and
///     20-node hexahedra (Mesh.SecondOrderIncomplete = 1) and 6-node prisms, of one or several
///     types (cell_type.hpp; Gmsh's node order turned into CalculiX's by gmsh_to_local);
///     pyramids, 27-node hexahedra and higher orders are rejected. A volume entity may belong
///     to one 3D group only, and every volume entity with elements must belong to one (Gmsh
///     only writes elements without a physical group when Mesh.SaveAll = 1).
///   - Bodies may share nodes (volumes fragmented or `Coherence`d together: a connected mesh of
///     several materials); mesh::bodies_sharing_nodes finds them, and the problem file accepts
///     them only as the sections of one body. Two bodies meant to touch (contact) must be
///     separate volumes with their own surface meshes.
///   - 2D physical groups are face sets and node sets of the same name. Each element must be a
///     3- or 6-node triangle or a 4- or 8-node quadrangle that is the face of exactly one cell
///     (a boundary face) and of its type; it is stored with that cell's nodes in the outward
///     order of the cell's face (mesh::cell_face), so its own orientation in the file does not
///     matter.
///   - 0D and 1D physical groups are node sets.
///   - A file without a 3D physical group is a 2D model: its 2D physical groups are the bodies
///     (3- and 6-node triangles, 4- and 8-node quadrangles at z = 0), its 1D groups edge sets
///     (2- and 3-node lines, each an edge of exactly one cell, stored with the cell's nodes
///     so that (x_1 - x_0) x e_z points out of the body) and node sets, its 0D groups node
///     sets. Cells clockwise in the x-y plane (a surface whose normal is -z) are turned
///     counter-clockwise. The formulation (plane strain, plane stress, axisymmetric) is not
///     in the file: the problem file's mesh.formulation sets Mesh::planar.
///   - Every physical group needs a name (Physical Surface("load") = {...}), names are unique
///     over all dimensions (sets and bodies are looked up by name alone), and every group has
///     elements. 2D elements outside physical groups are ignored.
///   - Nodes are renumbered 0..n-1 body by body, by increasing Gmsh node tag within a body; only
///     nodes of cells are kept. Coordinates are taken as written: feticon works in SI units,
///     so the file must be in metres (Gmsh has no units; scale with Mesh.ScalingFactor when
///     meshing a model drawn in mm).
///
/// Usage:
///   const feticon::mesh::Mesh mesh = feticon::mesh::read_gmsh("examples/x/x.msh");
///   const auto& contact_faces = mesh.face_set("punch_contact");
///
/// Gmsh keeps process-wide state: the module initializes and finalizes the Gmsh API itself, so it
/// must not be called from several threads at once nor while the caller has the Gmsh API
/// initialized. Gmsh's own messages are silenced (General.Terminal = 0, no user option files
/// read); its errors become feticon::Error.

#include "mesh/mesh.hpp"

#include <filesystem>

namespace feticon::mesh
{
/// @brief Reads a Gmsh mesh of the cell types of cell_type.hpp with named physical groups (see
/// file comment).
/// @param[in] path a `.msh` file (metres)
/// @return the mesh: bodies from 3D groups, face sets and node sets from 2D groups, node sets
///         from 0D/1D groups (a 2D model: one dimension less); cells have positive Jacobian
///         determinant at their centres
/// @throws feticon::Error naming the file and the problem: missing, unreadable or corrupt file,
///         no 3D or 2D physical group, unnamed, duplicate or empty groups, element types feticon does
///         not know, a surface element that is not a boundary face of a cell of its type,
///         inverted or degenerate cells.
/// @param[out] from_cache whether the mesh came from the mesh cache (may be null)
Mesh read_gmsh(const std::filesystem::path& path, bool* from_cache = nullptr);
} // namespace feticon::mesh

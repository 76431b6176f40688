#pragma once
/// @file The Gmsh module: every call into libgmsh, in a shared object opened on first use.
///
/// Linking libgmsh costs every process more start-up time than a whole small solve (the
/// dynamic linker resolving the symbols of libgmsh and the ~110 libraries it pulls in;
/// figures in docs/measurements.md).
/// So the code that calls Gmsh lives in libfeticon_gmsh.so (src/mesh/gmsh/), which
/// gmsh_module() opens with dlopen the first time a mesh is made or read by Gmsh; runs that
/// do neither (mapped meshes, hertz3d, a mesh from the cache) never load Gmsh.
///
/// Exceptions do not cross the boundary: each function returns the error message, empty on
/// success, and the caller throws it as feticon::Error.

#include "mesh/cross_section.hpp"
#include "mesh/mesh.hpp"

#include <array>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace feticon::mesh
{
/// A quadrilateral mesh of a cross section as Gmsh made it.
struct QuadSection
{
  std::vector<Eigen::Vector2d> points;
  std::vector<std::array<int32_t, 4>> quads; ///< counter-clockwise (positive area)
  /// Boundary edges (node pairs) of every curve of the section, in the section's order.
  std::vector<std::vector<std::pair<int32_t, int32_t>>> curve_edges;
};

/// The hertz3d quarter model as solids (problems/hertz3d.hpp): the sphere of radius `radius`
/// centred at (0, 0, radius) cut to the ball of radius `cap_radius` about the origin, on the
/// half-space z <= 0 cut to the ball of radius `block_radius`, both in x, y >= 0, meshed with
/// tetrahedra of order `order` (1: tet4, 2: tet10, edge nodes on the geometry) of size
/// min(size + growth max(0, r - core), max_size) at the distance r from the origin.
struct SphereOnHalfSpace
{
  double radius = 0;
  double cap_radius = 0;
  double block_radius = 0;
  double size = 0;
  double core = 0;
  double growth = 0;
  double max_size = 0;
  int order = 2;
};

struct GmshModule
{
  int abi_version = 0;
  std::string (*mesh_cross_section)(const CrossSection& section, const SizeField& size, QuadSection& out) = nullptr;
  /// Reads the hexahedra, bodies and sets of a .msh file that precheck_gmsh_file accepted.
  std::string (*read_model)(const std::filesystem::path& path, const std::string& where, Mesh& out) = nullptr;
  /// The tetrahedra, bodies "sphere" and "block" and the hertz3d sets of the model.
  std::string (*mesh_sphere_on_half_space)(const SphereOnHalfSpace& geometry, Mesh& out) = nullptr;
};

/// Changes whenever GmshModule or the types it passes change: a stale module is refused.
inline constexpr int gmsh_module_abi = 2;

/// The loaded module (next to the executable, else in the build tree); throws
/// feticon::Error naming the files tried and why when it cannot be loaded.
const GmshModule& gmsh_module();

/// Size and modification time of the module gmsh_module() would load, without loading it;
/// empty if there is none. The mesh cache's keys hold it: a rebuilt module (a changed mesher
/// or reader) leaves the executable's build id as it was.
std::string gmsh_module_stamp();
} // namespace feticon::mesh

/// The module's one exported symbol.
extern "C" const feticon::mesh::GmshModule* feticon_gmsh_module();

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

struct GmshModule
{
  int abi_version = 0;
  std::string (*mesh_cross_section)(const CrossSection& section, const SizeField& size, QuadSection& out) = nullptr;
  /// Reads the hexahedra, bodies and sets of a .msh file that precheck_gmsh_file accepted.
  std::string (*read_model)(const std::filesystem::path& path, const std::string& where, Mesh& out) = nullptr;
};

/// Changes whenever GmshModule or the types it passes change: a stale module is refused.
inline constexpr int gmsh_module_abi = 1;

/// The loaded module (next to the executable, else in the build tree); throws
/// feticon::Error naming the files tried and why when it cannot be loaded.
const GmshModule& gmsh_module();
} // namespace feticon::mesh

/// The module's one exported symbol.
extern "C" const feticon::mesh::GmshModule* feticon_gmsh_module();

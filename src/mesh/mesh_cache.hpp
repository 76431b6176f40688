#pragma once
/// @file A disk cache of the meshes Gmsh makes or reads, so that a run whose mesh was made
/// before neither loads Gmsh nor meshes again.
///
/// Making the graded Hertz mesh and loading libgmsh (mesh/gmsh_module.hpp) are most of a small
/// run (docs/measurements.md), and the same work again in every run of a load or material
/// study on one mesh. A cached mesh is a binary
/// copy of the Mesh, so a hit gives the identical mesh, bit for bit.
///
/// An entry is found by its key, the text of every input of the mesh, together with the build
/// id of the running executable and the size and time of the Gmsh module it would load, so
/// that a rebuilt feticon or module (whose mesher or reader may have changed) never reads an
/// older entry (a module rebuilt alone once served the meshes of the reader it replaced). The file stores the key and a checksum of its content and is
/// written atomically (temporary file, rename): a truncated, corrupt or foreign file is a
/// miss and is replaced, never an error. The folder is $FETICON_MESH_CACHE, else
/// $XDG_CACHE_HOME/feticon/meshes, else ~/.cache/feticon/meshes; FETICON_MESH_CACHE=off turns
/// the cache off. Its oldest entries are removed when it holds more than 256 MiB.

#include "mesh/mesh.hpp"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>

namespace feticon::mesh
{
/// Where the cache is; `enabled` is false for FETICON_MESH_CACHE=off or when neither
/// XDG_CACHE_HOME nor HOME is set, and for an executable without a build id.
struct MeshCacheLocation
{
  bool enabled = false;
  std::filesystem::path folder;
  /// The running executable's build id and the Gmsh module's stamp (gmsh_module_stamp), part of
  /// every key.
  std::string build_id;
  std::uintmax_t limit_bytes = std::uintmax_t{256} << 20; ///< entries beyond it are pruned
};
MeshCacheLocation mesh_cache_location();

/// The mesh of `key` from the cache in `location`, else `build()`, which is then stored.
/// Errors of build() propagate and store nothing; a cache that cannot be read or written
/// only costs the rebuild (a failed write is one warning).
/// @param[out] hit whether the mesh came from the cache (may be null)
Mesh cached_mesh(const MeshCacheLocation& location, const std::string& key, const std::function<Mesh()>& build,
                 bool* hit = nullptr);

/// The same with mesh_cache_location().
Mesh cached_mesh(const std::string& key, const std::function<Mesh()>& build, bool* hit = nullptr);

/// Hexadecimal 64-bit FNV-1a digest of a file's bytes (a cache key for a mesh read from it);
/// throws feticon::Error if it cannot be read.
std::string file_digest(const std::filesystem::path& path);
} // namespace feticon::mesh

#include "mesh/gmsh_reader.hpp"
#include "mesh/gmsh_module.hpp"
#include "mesh/gmsh_precheck.hpp"
#include "mesh/mesh_cache.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <string>
#include <system_error>

namespace feticon::mesh
{
Mesh read_gmsh(const std::filesystem::path& path, bool* from_cache)
{
  const std::string where = "Gmsh file '" + path.string() + "'";
  std::error_code error;
  FETICON_CHECK(std::filesystem::exists(path, error),
                where << ": no such file"
                      << (path.is_relative() ? " (relative to the working directory " +
                                  std::filesystem::current_path(error).string() + ")"
                                             : std::string()));
  FETICON_CHECK(std::filesystem::is_regular_file(path, error),
                where << ": is " << (std::filesystem::is_directory(path, error) ? "a folder" : "not a regular file")
                      << "; mesh.file names a .msh file");
  FETICON_CHECK(std::ifstream(path).good(), where << ": cannot be opened for reading");
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  FETICON_CHECK(extension == ".msh",
                where << ": expected a mesh file ending in .msh; mesh a "
                         "geometry first, e.g. gmsh -3 -format msh41 x.geo");

  // The same bytes give the same mesh: the file's digest is the key.
  return cached_mesh(
      "gmsh file " + file_digest(path),
      [&] {
    // What would crash libgmsh's reader is an input error here.
    precheck_gmsh_file(path, where);
    Mesh mesh;
    const std::string failure = gmsh_module().read_model(path, where, mesh);
    FETICON_CHECK(failure.empty(), failure);
    return mesh;
      },
      from_cache);
}
} // namespace feticon::mesh

#pragma once
/// @file A scan of a Gmsh MSH file's section headers before libgmsh reads it (issue 21):
/// what would crash libgmsh's reader becomes a one-line input error, and the declared node
/// and element counts let the memory guard refuse a mesh before it is read.
///
/// Checked: the $MeshFormat version (2.x or 4.x), the $PhysicalNames block (count, then one
/// `dim tag "name"` line each with dim in 0..3 and a positive tag: libgmsh 4.8 crashes on a
/// dimension of 7), and the count lines of $Nodes and $Elements. The rest of the file is
/// left to libgmsh, which reports its own errors.

#include <cstdint>
#include <filesystem>
#include <string>

namespace feticon::mesh
{
struct GmshDeclaredSizes
{
  int64_t nodes = -1;    ///< -1 when the file declares none (no $Nodes section)
  int64_t elements = -1; ///< of every dimension, as declared
};

/// @param where the file's name for messages ("Gmsh file 'x.msh'")
/// @throws feticon::Error naming the line at fault
GmshDeclaredSizes precheck_gmsh_file(const std::filesystem::path& path, const std::string& where);
} // namespace feticon::mesh

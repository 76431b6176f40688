#pragma once
/// @file VTK XML output for ParaView: one UnstructuredGrid (.vtu) per step and a .pvd collection.
///
/// The .vtu files use format="binary": every DataArray is one base64 stream of a UInt64 byte
/// count followed by the raw little- (or native-) endian values, as VTK itself writes
/// uncompressed inline data (header_type="UInt64"). Floating-point fields are Float64, so values
/// round-trip exactly. Every file also carries
///   - cell data "body" (Int32): the body index of each cell (mesh.cell_body);
///   - point data "set_<name>" (UInt8, 0 or 1) for every node set of the mesh, to show boundary
///     conditions and contact surfaces in ParaView.
/// Files are written atomically (common/atomic_file.hpp).
///
/// Usage:
///   PvdWriter series(out / "hertz.pvd");
///   write_vtu(out / "step_0001.vtu", mesh, &deformed, {{"displacement", 3, u}}, {{"stress", 6,
///   s}}); series.add(1.0, "step_0001.vtu");

#include "mesh/mesh.hpp"

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>

namespace feticon::io
{
/// Node coordinates, one row per node (m).
using PointMatrix = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

/// @brief A point or cell field written to a .vtu file.
///
/// `values` is entity-major: values[entity * components + c]. Component conventions:
///   1 scalar; 3 vector (x, y, z);
///   6 symmetric tensor in VTK's order xx, yy, zz, xy, yz, xz (ParaView shows it as a tensor);
///   9 full tensor, row-major xx, xy, xz, yx, yy, yz, zx, zy, zz.
/// Other counts are written as plain multi-component arrays.
struct VtuField
{
  std::string name;
  int components = 1;
  std::vector<double> values;
};

/// @brief Writes `mesh` with fields to a VTK XML UnstructuredGrid file.
/// @param[in] path            output file; parent directories are created
/// @param[in] mesh            cells are written as VTK_HEXAHEDRON (12)
/// @param[in] deformed_points current coordinates (m), n_nodes rows; nullptr writes the reference
///                            coordinates mesh.nodes
/// @param[in] point_fields    one tuple per node
/// @param[in] cell_fields     one tuple per cell
/// @throws feticon::Error naming the field if a size does not match the mesh, a name is empty or
///         repeated, or the file cannot be written.
void write_vtu(const std::filesystem::path& path, const mesh::Mesh& mesh,
               const Eigen::Ref<const PointMatrix>* deformed_points, const std::vector<VtuField>& point_fields = {},
               const std::vector<VtuField>& cell_fields = {});

/// @brief The .pvtu file that joins per-rank pieces written by write_vtu (same fields, each
/// piece a submesh) into one dataset for ParaView.
/// @param pieces  the piece files, relative to the directory of `path`
/// @param mesh    any of the pieces' meshes (for the names of the generated set_* fields)
void write_pvtu(const std::filesystem::path& path, const std::vector<std::string>& pieces, const mesh::Mesh& mesh,
                const std::vector<VtuField>& point_fields, const std::vector<VtuField>& cell_fields);

/// @brief A ParaView .pvd collection of time steps, rewritten atomically after every add(), so
/// the file on disk always lists exactly the steps written so far.
class PvdWriter
{
public:
  /// Writes an empty collection at `pvd_path` (replacing an older one of a previous run).
  explicit PvdWriter(std::filesystem::path pvd_path);

  /// @brief Appends a step and rewrites the collection.
  /// @param[in] time              pseudo-time or load factor of the step
  /// @param[in] vtu_relative_path the .vtu file, relative to the directory of the .pvd file
  void add(double time, const std::string& vtu_relative_path);

  const std::filesystem::path& path() const { return _path; }
  int32_t n_steps() const { return static_cast<int32_t>(_steps.size()); }

private:
  void write() const;

  std::filesystem::path _path;
  std::vector<std::pair<double, std::string>> _steps;
};
} // namespace feticon::io

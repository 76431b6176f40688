#include "io/vtu.hpp"

#include "common/atomic_file.hpp"
#include "io/base64.hpp"

#include "common/error.hpp"

#include <bit>
#include <cmath>
#include <iomanip>
#include <set>
#include <sstream>
#include <type_traits>

namespace feticon::io
{
namespace
{
/// VTK cell type id of the linear hexahedron.

const char* byte_order() { return std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian"; }

std::string xml_escape(const std::string& text)
{
  std::string escaped;
  for (const char c : text)
  {
    if (c == '&')
      escaped += "&amp;";
    else if (c == '<')
      escaped += "&lt;";
    else if (c == '>')
      escaped += "&gt;";
    else if (c == '"')
      escaped += "&quot;";
    else
      escaped += c;
  }
  return escaped;
}

/// VTK XML name of the value type T.
template <class T>
constexpr const char* vtk_type_name()
{
  static_assert(std::is_same_v<T, double> || std::is_same_v<T, int64_t> || std::is_same_v<T, int32_t> ||
                std::is_same_v<T, uint8_t>);
  if constexpr (std::is_same_v<T, double>)
    return "Float64";
  else if constexpr (std::is_same_v<T, int64_t>)
    return "Int64";
  else if constexpr (std::is_same_v<T, int32_t>)
    return "Int32";
  else
    return "UInt8";
}

/// Writes one binary DataArray; `write_values` feeds n_values values of type T to the encoder.
template <class T, class WriteValues>
void write_data_array(std::ostream& out, const std::string& name, int components, std::size_t n_values,
                      WriteValues&& write_values)
{
  out << "        <DataArray type=\"" << vtk_type_name<T>() << "\" Name=\"" << xml_escape(name)
      << "\" NumberOfComponents=\"" << components << "\" format=\"binary\">\n          ";
  Base64Writer encoder(out);
  const uint64_t n_bytes = n_values * sizeof(T);
  encoder.write(&n_bytes, sizeof n_bytes);
  write_values(encoder);
  encoder.finish();
  out << "\n        </DataArray>\n";
}

template <class T>
void write_vector(std::ostream& out, const std::string& name, int components, const std::vector<T>& values)
{
  write_data_array<T>(out, name, components, values.size(),
                      [&](Base64Writer& encoder) { encoder.write(values.data(), values.size() * sizeof(T)); });
}

void check_fields(const std::vector<VtuField>& fields, int64_t n_entities, const char* kind,
                  std::set<std::string>& names)
{
  for (const VtuField& field : fields)
  {
    FETICON_CHECK(!field.name.empty(), "VTU " << kind << " field with an empty name");
    FETICON_CHECK(names.insert(field.name).second,
                  "VTU " << kind << " field '" << field.name
                         << "' is given twice or clashes with a generated field (body, set_*)");
    FETICON_CHECK(field.components >= 1,
                  "VTU " << kind << " field '" << field.name << "' has " << field.components
                         << " components; need >= 1");
    const int64_t expected = n_entities * field.components;
    FETICON_CHECK(static_cast<int64_t>(field.values.size()) == expected,
                  "VTU " << kind << " field '" << field.name << "' has " << field.values.size() << " values, expected "
                         << n_entities << " " << kind << "s x " << field.components << " components = " << expected);
  }
}

void check_mesh(const mesh::Mesh& mesh)
{
  FETICON_CHECK(mesh.cell_body.size() == mesh.cells.size(),
                "VTU: mesh has " << mesh.cells.size() << " cells but " << mesh.cell_body.size() << " body indices");
  for (const std::span<const int32_t> cell : mesh.cells)
    for (const int32_t id : cell)
      FETICON_CHECK(id >= 0 && id < mesh.n_nodes(),
                    "VTU: cell node id " << id << " outside [0, " << mesh.n_nodes() << ")");
  for (const auto& [name, ids] : mesh.node_sets)
    for (const int32_t id : ids)
      FETICON_CHECK(id >= 0 && id < mesh.n_nodes(),
                    "VTU: node set '" << name << "' has node id " << id << " outside [0, " << mesh.n_nodes() << ")");
}

void write_piece(std::ostream& out, const mesh::Mesh& mesh, const Eigen::Ref<const PointMatrix>& points,
                 const std::vector<VtuField>& point_fields, const std::vector<VtuField>& cell_fields)
{
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"" << byte_order()
      << "\" header_type=\"UInt64\">\n"
      << "  <UnstructuredGrid>\n"
      << "    <Piece NumberOfPoints=\"" << mesh.n_nodes() << "\" NumberOfCells=\"" << mesh.n_cells() << "\">\n";

  out << "      <PointData>\n";
  for (const VtuField& field : point_fields)
    write_vector(out, field.name, field.components, field.values);
  for (const auto& [name, ids] : mesh.node_sets)
  {
    std::vector<uint8_t> member(mesh.n_nodes(), 0);
    for (const int32_t id : ids)
      member[id] = 1;
    write_vector(out, "set_" + name, 1, member);
  }
  out << "      </PointData>\n      <CellData>\n";
  for (const VtuField& field : cell_fields)
    write_vector(out, field.name, field.components, field.values);
  write_vector(out, "body", 1, mesh.cell_body);
  out << "      </CellData>\n      <Points>\n";
  // Row by row, because a Ref may have an outer stride larger than 3.
  write_data_array<double>(out, "Points", 3, std::size_t{3} * mesh.n_nodes(), [&](Base64Writer& encoder) {
    for (Eigen::Index i = 0; i < points.rows(); ++i)
      encoder.write(points.row(i).data(), 3 * sizeof(double));
  });
  out << "      </Points>\n      <Cells>\n";
  // VTK's node k of a cell is its local node vtk_to_local[k] (cell_type.hpp).
  std::vector<int64_t> connectivity;
  connectivity.reserve(mesh.cells.n_node_entries());
  std::vector<int64_t> offsets(mesh.n_cells());
  std::vector<uint8_t> types(mesh.n_cells());
  for (std::size_t c = 0; c < offsets.size(); ++c)
  {
    const mesh::CellType& type = mesh::cell_type(mesh.cells.kind(c));
    const std::span<const int32_t> cell = mesh.cells[c];
    for (const int local : type.vtk_to_local)
      connectivity.push_back(cell[local]);
    offsets[c] = static_cast<int64_t>(connectivity.size());
    types[c] = static_cast<uint8_t>(type.vtk_type);
  }
  write_vector(out, "connectivity", 1, connectivity);
  write_vector(out, "offsets", 1, offsets);
  write_vector(out, "types", 1, types);
  out << "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
}
} // namespace

void write_vtu(const std::filesystem::path& path, const mesh::Mesh& mesh,
               const Eigen::Ref<const PointMatrix>* deformed_points, const std::vector<VtuField>& point_fields,
               const std::vector<VtuField>& cell_fields)
{
  check_mesh(mesh);
  if (deformed_points)
    FETICON_CHECK(deformed_points->rows() == mesh.n_nodes(),
                  "VTU '" << path.string() << "': deformed points have " << deformed_points->rows()
                          << " rows, the mesh has " << mesh.n_nodes() << " nodes");
  std::set<std::string> point_names;
  for (const auto& [name, ids] : mesh.node_sets)
    point_names.insert("set_" + name);
  check_fields(point_fields, mesh.n_nodes(), "point", point_names);
  std::set<std::string> cell_names = {"body"};
  check_fields(cell_fields, mesh.n_cells(), "cell", cell_names);

  const Eigen::Ref<const PointMatrix> points =
      deformed_points ? *deformed_points : Eigen::Ref<const PointMatrix>(mesh.nodes);
  write_file_atomically(path, [&](std::ostream& out) { write_piece(out, mesh, points, point_fields, cell_fields); });
}

void write_pvtu(const std::filesystem::path& path, const std::vector<std::string>& pieces, const mesh::Mesh& mesh,
                const std::vector<VtuField>& point_fields, const std::vector<VtuField>& cell_fields)
{
  std::ostringstream out;
  auto array = [&](const char* type, const std::string& name, int components) {
    out << "      <PDataArray type=\"" << type << "\" Name=\"" << xml_escape(name) << "\" NumberOfComponents=\""
        << components << "\"/>\n";
  };
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\" byte_order=\"" << byte_order()
      << "\" header_type=\"UInt64\">\n"
      << "  <PUnstructuredGrid GhostLevel=\"0\">\n    <PPointData>\n";
  for (const VtuField& field : point_fields)
    array(vtk_type_name<double>(), field.name, field.components);
  for (const auto& [name, ids] : mesh.node_sets)
    array(vtk_type_name<uint8_t>(), "set_" + name, 1);
  out << "    </PPointData>\n    <PCellData>\n";
  for (const VtuField& field : cell_fields)
    array(vtk_type_name<double>(), field.name, field.components);
  array(vtk_type_name<int32_t>(), "body", 1);
  out << "    </PCellData>\n    <PPoints>\n";
  array(vtk_type_name<double>(), "Points", 3);
  out << "    </PPoints>\n";
  for (const std::string& piece : pieces)
    out << "    <Piece Source=\"" << xml_escape(piece) << "\"/>\n";
  out << "  </PUnstructuredGrid>\n</VTKFile>\n";
  write_file_atomically(path, out.str());
}

PvdWriter::PvdWriter(std::filesystem::path pvd_path) : _path(std::move(pvd_path)) { write(); }

void PvdWriter::add(double time, const std::string& vtu_relative_path)
{
  FETICON_CHECK(std::isfinite(time),
                "PVD '" << _path.string() << "': time " << time << " of '" << vtu_relative_path << "' must be finite");
  FETICON_CHECK(!vtu_relative_path.empty(), "PVD '" << _path.string() << "': empty VTU path");
  _steps.emplace_back(time, vtu_relative_path);
  write();
}

void PvdWriter::write() const
{
  std::ostringstream out;
  out << std::setprecision(17);
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"" << byte_order() << "\">\n"
      << "  <Collection>\n";
  for (const auto& [time, file] : _steps)
    out << "    <DataSet timestep=\"" << time << "\" group=\"\" part=\"0\" file=\"" << xml_escape(file) << "\"/>\n";
  out << "  </Collection>\n</VTKFile>\n";
  write_file_atomically(_path, out.str());
}
} // namespace feticon::io

#include "app/model_picture.hpp"

#include "app/run_output.hpp"
#include "common/error.hpp"
#include "contact/contact_constraints.hpp"
#include "fem/hex8_element.hpp"
#include "fem/stress.hpp"
#include "mesh/cell_type.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstdio>
#include <fstream>
#include <string>

namespace feticon::app
{
namespace
{
/// A C-ordered array of `rows` x `columns` values in NumPy's .npy format (version 1.0):
/// magic, header length, a dict header padded with spaces to 64 bytes, the raw data.
template <typename T>
void write_npy(const std::filesystem::path& path, const std::vector<T>& values, size_t columns)
{
  const char* descr = std::is_same_v<T, double> ? "<f8" : "<i4";
  const size_t rows = columns == 0 ? 0 : values.size() / columns;
  std::string shape = columns == 1 ? "(" + std::to_string(rows) + ",)"
                                   : "(" + std::to_string(rows) + ", " + std::to_string(columns) + ")";
  std::string header = std::string("{'descr': '") + descr + "', 'fortran_order': False, 'shape': " + shape + ", }";
  const size_t unpadded = 10 + header.size() + 1;
  header.append((64 - unpadded % 64) % 64, ' ');
  header += '\n';
  std::ofstream out(path, std::ios::binary);
  FETICON_CHECK(out, "cannot write " << path.string());
  const unsigned short length = static_cast<unsigned short>(header.size());
  out.write("\x93NUMPY\x01\x00", 8);
  out.put(static_cast<char>(length & 0xff));
  out.put(static_cast<char>(length >> 8));
  out << header;
  out.write(reinterpret_cast<const char*>(values.data()), static_cast<std::streamsize>(values.size() * sizeof(T)));
  FETICON_CHECK(out, "cannot write " << path.string());
}

/// A face of a cell: its sorted corners (the key two cells share), the cell and its number.
struct CellFaceRef
{
  std::array<int32_t, 4> key;
  int32_t cell;
  int32_t face;
};

/// The faces of the mesh that belong to one cell only, as (cell, face number).
std::vector<CellFaceRef> boundary_faces(const mesh::Mesh& mesh)
{
  std::vector<CellFaceRef> faces;
  for (size_t c = 0; c < mesh.cells.size(); ++c)
  {
    const mesh::CellKind kind = mesh.cells.kind(c);
    for (int k = 0; k < static_cast<int>(mesh::cell_type(kind).faces.size()); ++k)
      faces.push_back({mesh::sorted_corners(mesh::cell_face(kind, mesh.cells[c], k)), static_cast<int32_t>(c), k});
  }
  std::sort(faces.begin(), faces.end(), [](const CellFaceRef& a, const CellFaceRef& b) { return a.key < b.key; });
  std::vector<CellFaceRef> boundary;
  for (size_t i = 0; i < faces.size();)
  {
    size_t j = i + 1;
    while (j < faces.size() && faces[j].key == faces[i].key)
      ++j;
    if (j == i + 1)
      boundary.push_back(faces[i]);
    i = j;
  }
  return boundary;
}

/// The surface index of `node`, given to it as it first appears.
int32_t surface_index(int32_t node, std::vector<int32_t>& surface_of, std::vector<int32_t>& surface_nodes)
{
  if (surface_of[node] < 0)
  {
    surface_of[node] = static_cast<int32_t>(surface_nodes.size());
    surface_nodes.push_back(node);
  }
  return surface_of[node];
}

/// The corners of `face` split into triangles (a quad into two along its first diagonal),
/// appended as indices into the surface nodes (`surface_of`, filled as nodes first appear).
void add_triangles(const mesh::Face& face, std::vector<int32_t>& surface_of, std::vector<int32_t>& surface_nodes,
                   std::vector<int32_t>& triangles)
{
  const int corners = face.n_corners();
  for (int t = 0; t + 2 < corners; ++t)
    for (int a : {0, t + 1, t + 2})
      triangles.push_back(surface_index(face[a], surface_of, surface_nodes));
}
} // namespace

void write_picture_data(const std::filesystem::path& dir, const fem::Problem& problem,
                        const nonlinear::ContactSolution& solution, fem::Kinematics kinematics,
                        const std::vector<nonlinear::PressureSample>& samples, bool si_units)
{
  const mesh::Mesh& mesh = problem.mesh;
  std::filesystem::create_directories(dir);
  const auto stresses = fem::cell_cauchy_stresses(mesh, solution.u, problem.materials, kinematics,
                                                  solution.temperature_change, &solution.plastic);
  // The boundary faces by their corners (a triangle's fourth is -1), drawn as polygons.
  std::vector<int32_t> surface_of(mesh.n_nodes(), -1), surface_nodes, faces, contact_triangles, contact_pair;
  std::vector<double> mises;
  for (const CellFaceRef& f : boundary_faces(mesh))
  {
    const mesh::Face face = mesh::cell_face(mesh.cells.kind(f.cell), mesh.cells[f.cell], f.face);
    for (int a = 0; a < 4; ++a)
      faces.push_back(a < face.n_corners() ? surface_index(face[a], surface_of, surface_nodes) : -1);
    mises.push_back(fem::von_mises(stresses[f.cell]));
  }
  for (size_t p = 0; p < problem.contacts.size(); ++p)
    for (const mesh::Face& face : mesh.face_set(problem.contacts[p].slave))
    {
      const size_t before = contact_triangles.size();
      add_triangles(face, surface_of, surface_nodes, contact_triangles);
      contact_pair.insert(contact_pair.end(), (contact_triangles.size() - before) / 3, static_cast<int32_t>(p));
    }
  const std::vector<double> node_pressure = nonlinear::row_pressure_per_node(solution, mesh.n_nodes());
  std::vector<double> reference, displacement, pressure, slip;
  for (const int32_t node : surface_nodes)
  {
    for (int c = 0; c < 3; ++c)
    {
      reference.push_back(mesh.nodes(node, c));
      displacement.push_back(solution.u[3 * static_cast<la::Index>(node) + c]);
    }
    pressure.push_back(node_pressure[node]);
  }
  for (const nonlinear::PressureSample& s : samples)
    if (s.slipping)
      slip.insert(slip.end(), {s.x, s.y, s.z});
  write_npy(dir / "reference.npy", reference, 3);
  write_npy(dir / "displacement.npy", displacement, 3);
  write_npy(dir / "faces.npy", faces, 4);
  write_npy(dir / "von_mises.npy", mises, 1);
  write_npy(dir / "contact_triangles.npy", contact_triangles, 3);
  write_npy(dir / "contact_pair.npy", contact_pair, 1);
  write_npy(dir / "pressure.npy", pressure, 1);
  write_npy(dir / "slip.npy", slip, 3);
  nlohmann::ordered_json meta = {{"problem", problem.name},
                                 {"plane_strain", problem.eliminated[2]},
                                 {"si_units", si_units},
                                 {"large_displacements", kinematics == fem::Kinematics::total_lagrangian},
                                 {"pairs", nlohmann::ordered_json::array()}};
  for (const fem::ContactPairNames& pair : problem.contacts)
    meta["pairs"].push_back(pair.slave + " on " + pair.master);
  write_json(dir / "meta.json", meta);
}

void draw_model_pictures(const std::filesystem::path& dir, const std::filesystem::path& out_dir)
{
  run_plot_script("plot_model.py", {dir.string(), out_dir.string()});
}
} // namespace feticon::app

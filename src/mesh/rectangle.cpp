#include "mesh/rectangle.hpp"

#include "common/error.hpp"

#include <array>
#include <map>
#include <vector>

namespace feticon::mesh
{
Mesh generate_mapped_rectangle(const std::array<int32_t, 2>& n_cells, const PlanarGridMap& point, CellKind kind,
                               const Planar& planar, const std::string& body_name)
{
  const auto [nx, ny] = n_cells;
  FETICON_CHECK(is_planar(kind), "rectangle '" << body_name << "': " << cell_type(kind).name << " is no 2D cell");
  FETICON_CHECK(planar.kind != PlanarKind::none, "rectangle '" << body_name << "' needs a planar formulation");
  FETICON_CHECK(nx >= 1 && ny >= 1,
                "rectangle '" << body_name << "' needs at least one cell per direction, got " << nx << " x " << ny);
  Mesh mesh;
  mesh.planar = planar;
  mesh.body_names = {body_name};
  // Grid points in half-cell steps, numbered as cells first use them.
  const int32_t columns = 2 * nx + 1;
  std::vector<int32_t> id(static_cast<size_t>(columns) * (2 * ny + 1), -1);
  std::vector<Eigen::Vector2d> coordinates;
  const auto node = [&](int32_t i, int32_t j) {
    int32_t& n = id[static_cast<size_t>(j) * columns + i];
    if (n < 0)
    {
      n = static_cast<int32_t>(coordinates.size());
      coordinates.push_back(point(0.5 * i, 0.5 * j));
    }
    return n;
  };
  const bool quadratic = cell_type(kind).order == 2;
  std::map<std::string, std::vector<Face>>& sets = mesh.face_sets;
  const auto add_edge = [&](const char* name, std::array<int32_t, 2> a, std::array<int32_t, 2> b) {
    std::vector<int32_t> nodes = {node(a[0], a[1]), node(b[0], b[1])};
    if (quadratic)
      nodes.push_back(node((a[0] + b[0]) / 2, (a[1] + b[1]) / 2));
    sets[name].emplace_back(quadratic ? FaceKind::line3 : FaceKind::line2, nodes);
  };
  for (int32_t j = 0; j < ny; ++j)
    for (int32_t i = 0; i < nx; ++i)
    {
      // Corners counter-clockwise from (2i, 2j), in half-cell grid units.
      const std::array<std::array<int32_t, 2>, 4> c = {
          {{2 * i, 2 * j}, {2 * i + 2, 2 * j}, {2 * i + 2, 2 * j + 2}, {2 * i, 2 * j + 2}}};
      const auto cell_of = [&](const std::vector<int>& corners) {
        std::vector<int32_t> nodes;
        for (const int k : corners)
          nodes.push_back(node(c[k][0], c[k][1]));
        if (quadratic)
          for (size_t k = 0; k < corners.size(); ++k)
          {
            const auto& a = c[corners[k]];
            const auto& b = c[corners[(k + 1) % corners.size()]];
            nodes.push_back(node((a[0] + b[0]) / 2, (a[1] + b[1]) / 2));
          }
        return nodes;
      };
      if (kind == CellKind::quad4 || kind == CellKind::quad8)
        mesh.cells.add(kind, cell_of({0, 1, 2, 3}));
      else
      {
        mesh.cells.add(kind, cell_of({0, 1, 2}));
        mesh.cells.add(kind, cell_of({0, 2, 3}));
      }
      if (i == 0)
        add_edge("xmin", c[3], c[0]);
      if (i == nx - 1)
        add_edge("xmax", c[1], c[2]);
      if (j == 0)
        add_edge("ymin", c[0], c[1]);
      if (j == ny - 1)
        add_edge("ymax", c[2], c[3]);
    }
  mesh.nodes.resize(static_cast<Eigen::Index>(coordinates.size()), 3);
  for (size_t n = 0; n < coordinates.size(); ++n)
    mesh.nodes.row(static_cast<Eigen::Index>(n)) << coordinates[n].x(), coordinates[n].y(), 0;
  mesh.cell_body.assign(mesh.cells.size(), 0);
  for (int32_t cell = 0; cell < mesh.n_cells(); ++cell)
  {
    const double det = centre_jacobian_determinant(mesh, cell);
    FETICON_CHECK(det > 0,
                  "cell " << cell << " of rectangle '" << body_name << "' is inverted or flat (Jacobian " << det
                          << " at its centre); the map must keep the orientation");
  }
  for (const auto& [name, faces] : sets)
    mesh.add_node_set_from_faces(name, name);
  return mesh;
}

Mesh generate_rectangle(const RectangleParameters& parameters)
{
  const RectangleParameters& p = parameters;
  FETICON_CHECK(p.lengths.minCoeff() > 0 && p.lengths.allFinite() && p.origin.allFinite(),
                "rectangle '" << p.body_name << "': lengths must be finite and > 0 m, got " << p.lengths.transpose());
  const Eigen::Vector2d step = p.lengths.cwiseQuotient(Eigen::Vector2d(p.nx, p.ny));
  return generate_mapped_rectangle(
      {p.nx, p.ny},
      [&](double i, double j) { return Eigen::Vector2d(p.origin + step.cwiseProduct(Eigen::Vector2d(i, j))); }, p.kind,
      p.planar, p.body_name);
}
} // namespace feticon::mesh

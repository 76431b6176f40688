#include "mesh/box.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace feticon::mesh
{
namespace
{

std::vector<double> uniform_positions(double length, double spacing)
{
  const int n = std::max(1, static_cast<int>(std::ceil(length / spacing * (1 - 1e-12))));
  std::vector<double> positions(n + 1);
  for (int i = 0; i <= n; ++i)
    positions[i] = length * i / n;
  return positions;
}

/// spacing * (r + r^2 + ... + r^m), increasing in r > 0.
double geometric_sum(double spacing, double r, int m)
{
  double sum = 0, term = spacing;
  for (int k = 1; k <= m; ++k)
  {
    term *= r;
    sum += term;
  }
  return sum;
}
} // namespace

Mesh generate_mapped_block(const std::array<int32_t, 3>& n_cells, const GridMap& point, const std::string& body_name)
{
  const auto [nx, ny, nz] = n_cells;
  FETICON_CHECK(nx >= 1 && ny >= 1 && nz >= 1,
                "structured block '" << body_name << "' needs at least one cell per direction, got " << nx << " x "
                                     << ny << " x " << nz);
  const int64_t n_nodes = int64_t{nx + 1} * (ny + 1) * (nz + 1);
  FETICON_CHECK(n_nodes <= std::numeric_limits<int32_t>::max(),
                "structured block '" << body_name << "' would have " << n_nodes
                                     << " nodes, more than int32 local ids allow");
  auto node_id = [&](int32_t i, int32_t j, int32_t k) { return i + (nx + 1) * (j + (ny + 1) * k); };

  Mesh mesh;
  mesh.body_names = {body_name};
  mesh.nodes.resize(n_nodes, 3);
  for (int32_t k = 0; k <= nz; ++k)
    for (int32_t j = 0; j <= ny; ++j)
      for (int32_t i = 0; i <= nx; ++i)
        mesh.nodes.row(node_id(i, j, k)) = point(i, j, k).transpose();

  std::map<std::string, std::vector<Face>>& sets = mesh.face_sets;
  for (int32_t k = 0; k < nz; ++k)
    for (int32_t j = 0; j < ny; ++j)
      for (int32_t i = 0; i < nx; ++i)
      {
        const Hex8Nodes cell = {
            node_id(i, j, k),     node_id(i + 1, j, k),     node_id(i + 1, j + 1, k),     node_id(i, j + 1, k),
            node_id(i, j, k + 1), node_id(i + 1, j, k + 1), node_id(i + 1, j + 1, k + 1), node_id(i, j + 1, k + 1)};
        mesh.cells.add(CellKind::hex8, cell);
        const double det = centre_jacobian_determinant(mesh, mesh.n_cells() - 1);
        FETICON_CHECK(det > 0,
                      "cell (" << i << ", " << j << ", " << k << ") of block '" << body_name
                               << "' is inverted or flat (Jacobian determinant " << det
                               << " at its centre); the node map must preserve orientation");
        auto add_face = [&](const char* name, int local_face) {
          const auto& local = hex_faces[local_face];
          sets[name].push_back(Face{cell[local[0]], cell[local[1]], cell[local[2]], cell[local[3]]});
        };
        // Local face numbers follow the hex_faces table: 0/1 zeta, 2/3 eta, 4/5 xi.
        if (i == 0)
          add_face("xmin", 4);
        if (i == nx - 1)
          add_face("xmax", 5);
        if (j == 0)
          add_face("ymin", 2);
        if (j == ny - 1)
          add_face("ymax", 3);
        if (k == 0)
          add_face("zmin", 0);
        if (k == nz - 1)
          add_face("zmax", 1);
      }
  mesh.cell_body.assign(mesh.cells.size(), 0);
  for (const auto& [name, faces] : sets)
    mesh.add_node_set_from_faces(name, name);
  return mesh;
}

Mesh generate_box(const BoxParameters& parameters)
{
  const BoxParameters& p = parameters;
  FETICON_CHECK(p.nx >= 1 && p.ny >= 1 && p.nz >= 1,
                "box '" << p.body_name << "': cell counts nx, ny, nz must be >= 1, got " << p.nx << ", " << p.ny << ", "
                        << p.nz);
  FETICON_CHECK(p.lengths.minCoeff() > 0 && p.lengths.allFinite(),
                "box '" << p.body_name << "': lengths must be finite and > 0 m, got " << p.lengths.transpose());
  FETICON_CHECK(p.origin.allFinite(),
                "box '" << p.body_name << "': origin must be finite, got " << p.origin.transpose());
  const Eigen::Vector3d step = p.lengths.cwiseQuotient(Eigen::Vector3d(p.nx, p.ny, p.nz));
  return generate_mapped_block(
      {p.nx, p.ny, p.nz},
      [&](int32_t i, int32_t j, int32_t k) {
    return Eigen::Vector3d(p.origin + step.cwiseProduct(Eigen::Vector3d(i, j, k)));
      },
      p.body_name);
}

void append_mesh(Mesh& target, const Mesh& other, const std::string& prefix)
{
  // Check everything before changing target, so a failed append leaves it untouched.
  for (const std::string& name : other.body_names)
    FETICON_CHECK(std::find(target.body_names.begin(), target.body_names.end(), name) == target.body_names.end(),
                  "append_mesh: body '" << name << "' already exists; give the bodies distinct names");
  for (const auto& [name, ids] : other.node_sets)
    FETICON_CHECK(!target.node_sets.contains(prefix + name),
                  "append_mesh: node set '" << prefix + name << "' already exists; use another prefix than '" << prefix
                                            << "'");
  for (const auto& [name, faces] : other.face_sets)
    FETICON_CHECK(!target.face_sets.contains(prefix + name),
                  "append_mesh: face set '" << prefix + name << "' already exists; use another prefix than '" << prefix
                                            << "'");
  FETICON_CHECK(other.cell_body.size() == other.cells.size(),
                "append_mesh: the appended mesh has " << other.cells.size() << " cells but " << other.cell_body.size()
                                                      << " body indices");
  FETICON_CHECK(int64_t{target.n_nodes()} + other.n_nodes() <= std::numeric_limits<int32_t>::max(),
                "append_mesh: the result would exceed int32 local node ids");
  FETICON_CHECK(target.cells.empty() || target.planar == other.planar,
                "append_mesh: a " << planar_name(other.planar.kind) << " mesh cannot join a "
                                  << planar_name(target.planar.kind) << " one (or their thicknesses differ)");
  if (target.cells.empty())
    target.planar = other.planar;

  const int32_t node_offset = target.n_nodes();
  const int32_t body_offset = target.n_bodies();
  target.nodes.conservativeResize(node_offset + other.n_nodes(), 3);
  target.nodes.bottomRows(other.n_nodes()) = other.nodes;
  std::vector<int32_t> cell;
  for (size_t c = 0; c < other.cells.size(); ++c)
  {
    cell.clear();
    for (const int32_t id : other.cells[c])
      cell.push_back(id + node_offset);
    target.cells.add(other.cells.kind(c), cell);
  }
  for (const int32_t body : other.cell_body)
    target.cell_body.push_back(body + body_offset);
  target.body_names.insert(target.body_names.end(), other.body_names.begin(), other.body_names.end());
  for (const auto& [name, ids] : other.node_sets)
  {
    std::vector<int32_t>& shifted = target.node_sets[prefix + name];
    for (const int32_t id : ids)
      shifted.push_back(id + node_offset);
  }
  for (const auto& [name, faces] : other.face_sets)
  {
    std::vector<Face>& shifted = target.face_sets[prefix + name];
    for (Face face : faces)
    {
      for (int32_t& id : face)
        id += node_offset;
      shifted.push_back(face);
    }
  }
}

std::vector<double> graded_positions(double length, double spacing, double fine_length, double ratio)
{
  FETICON_CHECK(std::isfinite(length) && length > 0, "graded spacing: length " << length << " m must be > 0");
  FETICON_CHECK(std::isfinite(spacing) && spacing > 0, "graded spacing: cell size " << spacing << " m must be > 0");
  FETICON_CHECK(std::isfinite(fine_length) && fine_length >= 0,
                "graded spacing: fine-region length " << fine_length << " m must be >= 0");
  FETICON_CHECK(std::isfinite(ratio) && ratio >= 1, "graded spacing: growth ratio " << ratio << " must be >= 1");

  // The fine region is whole cells of exactly `spacing`, so its cell size is what was asked.
  const int n_fine = static_cast<int>(std::ceil(fine_length / spacing * (1 - 1e-12)));
  const double rest = length - n_fine * spacing;
  if (rest <= 0)
    return uniform_positions(length, spacing);

  // Number of cells spacing*ratio^k, k = 1..m, that best fills `rest`.
  const double m_real =
      ratio == 1 ? rest / spacing : std::log1p(rest * (ratio - 1) / (spacing * ratio)) / std::log(ratio);
  const int m = static_cast<int>(std::lround(m_real));
  if (m < 1)
    return uniform_positions(length, spacing);

  // Bisection for the ratio that ends exactly at `length`; it is close to `ratio` because m was
  // rounded from the real solution.
  double low = 0, high = std::max(ratio, 1.0) * 2;
  while (geometric_sum(spacing, high, m) < rest)
    high *= 2;
  for (int iteration = 0; iteration < 200 && high - low > 1e-15 * high; ++iteration)
  {
    const double middle = 0.5 * (low + high);
    if (geometric_sum(spacing, middle, m) < rest)
      low = middle;
    else
      high = middle;
  }
  const double adjusted_ratio = 0.5 * (low + high);
  if (adjusted_ratio < 1)
    return uniform_positions(length, spacing);

  std::vector<double> positions;
  for (int i = 0; i <= n_fine; ++i)
    positions.push_back(i * spacing);
  double size = spacing;
  for (int k = 1; k <= m; ++k)
  {
    size *= adjusted_ratio;
    positions.push_back(positions.back() + size);
  }
  positions.back() = length;
  return positions;
}
} // namespace feticon::mesh

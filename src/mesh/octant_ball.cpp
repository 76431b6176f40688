#include "mesh/octant_ball.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <cmath>

namespace feticon::mesh
{
namespace
{
// Node flags: which of the octant's boundary surfaces a node lies on.
constexpr uint8_t on_x0 = 1, on_y0 = 2, on_d0 = 4, on_outer = 8;

/// Node numbers: the core's nodes first, then layer after layer one node on the ray of every
/// node of the core's outer faces.
struct OctantNumbering
{
  explicit OctantNumbering(int n) : m(n + 1), n_core(m * m * m), surface_of(n_core, -1)
  {
    // Core nodes (i, j, k) in [0, n]^3; the nodes of its outer faces x = c, y = c, d = c (the
    // "surface", max(i, j, k) = n) are the roots of the rays of the shell layers.
    for (int k = 0; k <= n; ++k)
      for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i)
          if (std::max({i, j, k}) == n)
          {
            surface_of[core_id(i, j, k)] = static_cast<int32_t>(surface_ijk.size());
            surface_ijk.push_back({i, j, k});
          }
    n_surface = static_cast<int32_t>(surface_ijk.size());
  }

  /// Core node (i, j, k).
  int32_t core_id(int i, int j, int k) const { return static_cast<int32_t>(i + m * (j + m * k)); }

  /// The node of surface node `surface` on layer `layer` (0: the core node itself).
  int32_t layer_node(int layer, int32_t surface) const
  {
    if (layer == 0)
    {
      const auto& [i, j, k] = surface_ijk[surface];
      return core_id(i, j, k);
    }
    return static_cast<int32_t>(n_core + static_cast<int64_t>(layer - 1) * n_surface + surface);
  }

  int m;                                       ///< nodes per core edge
  int32_t n_core;                              ///< core nodes
  std::vector<int32_t> surface_of;             ///< per core node: its surface index, or -1
  std::vector<std::array<int, 3>> surface_ijk; ///< per surface node: its (i, j, k)
  int32_t n_surface = 0;
};

/// The coordinates of the core's and the layers' nodes; returns per node the boundary
/// surfaces it lies on.
std::vector<uint8_t> place_nodes(const OctantBallParameters& parameters, const OctantBallSize& size,
                                 const OctantNumbering& numbering, OctantBall& out)
{
  const int n = parameters.core_cells;
  const double h = parameters.cell_size;
  const int layers = size.layers, blend = size.blend_layers;
  const double c = n * h;
  const double R = parameters.radius;

  // Layer radii: see octant_ball_size.
  const double s = 0.5 * (1 + std::sqrt(3.0));
  const double g = std::pow(R / (c * s), 1.0 / layers) - 1;

  const int64_t n_nodes = numbering.n_core + static_cast<int64_t>(layers) * numbering.n_surface;
  out.nodes.resize(n_nodes, 3);
  std::vector<uint8_t> flags(n_nodes, 0);
  auto flags_of = [](int i, int j, int k) {
    return static_cast<uint8_t>((i == 0 ? on_x0 : 0) | (j == 0 ? on_y0 : 0) | (k == 0 ? on_d0 : 0));
  };
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i)
      {
        out.nodes.row(numbering.core_id(i, j, k)) << i * h, j * h, k * h;
        flags[numbering.core_id(i, j, k)] = flags_of(i, j, k);
      }
  for (int layer = 1; layer <= layers; ++layer)
  {
    const double t = c * std::pow(1 + g, layer);
    const double w = std::min(1.0, static_cast<double>(layer) / blend);
    for (int32_t q = 0; q < numbering.n_surface; ++q)
    {
      const auto& [i, j, k] = numbering.surface_ijk[q];
      const Eigen::Vector3d p(i * h, j * h, k * h);
      const double box = p.norm() / c;
      const int32_t id = numbering.layer_node(layer, q);
      // Exact zeros on the symmetry and flat planes: the ray keeps a zero component.
      out.nodes.row(id) = (t * ((1 - w) * box + w * s) / p.norm()) * p.transpose();
      flags[id] = static_cast<uint8_t>(flags_of(i, j, k) | (layer == layers ? on_outer : 0));
    }
  }
  return flags;
}

/// The core's cells, then the layers' cells.
void add_cells(int n, int layers, const OctantNumbering& numbering, OctantBall& out)
{
  // Cells: the core's, then per layer one cell over every quad of the core's outer faces. The
  // quads are ordered so that (x1 - x0) x (x3 - x0) points away from the core, which makes
  // the cell {quad at layer - 1, quad at layer} positively oriented in VTK order.
  auto core_id = [&](int i, int j, int k) { return numbering.core_id(i, j, k); };
  out.cells.reserve(static_cast<size_t>(n) * n * n + static_cast<size_t>(layers) * 3 * n * n);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        out.cells.push_back({core_id(i, j, k), core_id(i + 1, j, k), core_id(i + 1, j + 1, k), core_id(i, j + 1, k),
                             core_id(i, j, k + 1), core_id(i + 1, j, k + 1), core_id(i + 1, j + 1, k + 1),
                             core_id(i, j + 1, k + 1)});
  std::vector<std::array<int32_t, 4>> quads;
  auto sid = [&](int i, int j, int k) { return numbering.surface_of[core_id(i, j, k)]; };
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b)
    {
      quads.push_back({sid(n, a, b), sid(n, a + 1, b), sid(n, a + 1, b + 1), sid(n, a, b + 1)}); // x = c: y x d = +x
      quads.push_back({sid(a, n, b), sid(a, n, b + 1), sid(a + 1, n, b + 1), sid(a + 1, n, b)}); // y = c: d x x = +y
      quads.push_back({sid(a, b, n), sid(a + 1, b, n), sid(a + 1, b + 1, n), sid(a, b + 1, n)}); // d = c: x x y = +d
    }
  auto layer_node = [&](int layer, int32_t surface) { return numbering.layer_node(layer, surface); };
  for (int layer = 1; layer <= layers; ++layer)
    for (const auto& q : quads)
      out.cells.push_back({layer_node(layer - 1, q[0]), layer_node(layer - 1, q[1]), layer_node(layer - 1, q[2]),
                           layer_node(layer - 1, q[3]), layer_node(layer, q[0]), layer_node(layer, q[1]),
                           layer_node(layer, q[2]), layer_node(layer, q[3])});
}

/// The faces of the octant's boundary surfaces, from the nodes' flags.
void add_boundary_faces(const std::vector<uint8_t>& flags, OctantBall& out)
{
  // Boundary faces: a cell face whose four nodes lie on one of the octant's boundary surfaces
  // is a face of that surface (hex_faces are outward for positively oriented cells).
  for (const Hex8Nodes& cell : out.cells)
    for (const auto& local : hex_faces)
    {
      const Face f{cell[local[0]], cell[local[1]], cell[local[2]], cell[local[3]]};
      const uint8_t common = flags[f[0]] & flags[f[1]] & flags[f[2]] & flags[f[3]];
      if (common & on_x0)
        out.symmetry_x.push_back(f);
      if (common & on_y0)
        out.symmetry_y.push_back(f);
      if (common & on_d0)
        out.flat.push_back(f);
      if (common & on_outer)
        out.outer.push_back(f);
    }
}
} // namespace

OctantBallSize octant_ball_size(const OctantBallParameters& parameters)
{
  const int n = parameters.core_cells;
  const double h = parameters.cell_size;
  FETICON_CHECK(n >= 1 && n <= 2000, "octant ball: core_cells = " << n << " must be in [1, 2000]");
  FETICON_CHECK(std::isfinite(h) && h > 0, "octant ball: cell_size = " << h << " must be positive");
  FETICON_CHECK(std::isfinite(parameters.radial_aspect) && parameters.radial_aspect >= 0.5 &&
                    parameters.radial_aspect <= 3,
                "octant ball: radial_aspect = " << parameters.radial_aspect << " must be in [0.5, 3]");
  const double c = n * h;
  const double R = parameters.radius;
  FETICON_CHECK(std::isfinite(R) && R >= 2.5 * c,
                "octant ball: radius " << R << " must be at least 2.5 times the core width " << c);

  // Layer radii. The mean tangential cell size on a sphere of radius r is r sqrt(pi/6) / n (the
  // octant's area pi r^2 / 2 over 3 n^2 cells), so growth g = aspect sqrt(pi/6) / n per layer
  // keeps radial / tangential = aspect. Over the first B layers the ray length blends from the
  // box's, t |p| / c, to the sphere's, t s with s = (1 + sqrt 3) / 2 (between the face centre's
  // 1 and the corner's sqrt 3); B is chosen so that even the corner ray, which shrinks from
  // sqrt 3 to s, still grows by at least g / 2 per layer. The last layer lies on |p| = R.
  const double s = 0.5 * (1 + std::sqrt(3.0));
  const double g0 = parameters.radial_aspect * std::sqrt(M_PI / 6) / n;
  const int blend = std::max(1, static_cast<int>(std::ceil((std::sqrt(3.0) - s) / (0.5 * g0 * s))));
  OctantBallSize size;
  size.blend_layers = blend;
  size.layers = std::max(blend + 1, static_cast<int>(std::ceil(std::log(R / (c * s)) / std::log1p(g0))));
  const int64_t m = n + 1, surface = m * m * m - int64_t(n) * n * n;
  size.nodes = m * m * m + size.layers * surface;
  size.cells = int64_t(n) * n * n + size.layers * 3 * int64_t(n) * n;
  // A flat face: the core's square, and per layer the two core edges' rays (2 n + 1 nodes).
  size.plane_nodes = m * m + size.layers * (2 * int64_t(n) + 1);
  return size;
}

OctantBall octant_ball(const OctantBallParameters& parameters)
{
  const OctantBallSize size = octant_ball_size(parameters);
  const OctantNumbering numbering(parameters.core_cells);
  OctantBall out;
  out.layers = size.layers;
  const std::vector<uint8_t> flags = place_nodes(parameters, size, numbering, out);
  add_cells(parameters.core_cells, size.layers, numbering, out);
  add_boundary_faces(flags, out);
  return out;
}

OctantBall mirrored_across_x(const OctantBall& ball)
{
  const auto n = static_cast<int32_t>(ball.nodes.rows());
  std::vector<char> on_plane(n, 0);
  for (const Face& f : ball.symmetry_x)
    for (int32_t node : f)
      on_plane[node] = 1;
  // image[i]: the mirror image of node i (itself on the plane).
  std::vector<int32_t> image(n);
  int32_t next = n;
  for (int32_t i = 0; i < n; ++i)
    image[i] = on_plane[i] ? i : next++;
  OctantBall out;
  out.layers = ball.layers;
  out.nodes.resize(next, 3);
  out.nodes.topRows(n) = ball.nodes;
  for (int32_t i = 0; i < n; ++i)
    if (!on_plane[i])
      out.nodes.row(image[i]) = Eigen::RowVector3d(-ball.nodes(i, 0), ball.nodes(i, 1), ball.nodes(i, 2));
  // A reflection reverses orientation: a cell's image swaps its bottom and top quads, a face's
  // image runs its corners the other way round.
  out.cells = ball.cells;
  for (const Hex8Nodes& c : ball.cells)
  {
    Hex8Nodes m;
    for (int k = 0; k < 8; ++k)
      m[k] = image[c[(k + 4) % 8]];
    out.cells.push_back(m);
  }
  auto with_images = [&](const std::vector<Face>& faces) {
    std::vector<Face> all = faces;
    for (const Face& f : faces)
      all.push_back(Face{image[f[0]], image[f[3]], image[f[2]], image[f[1]]});
    return all;
  };
  out.flat = with_images(ball.flat);
  out.outer = with_images(ball.outer);
  out.symmetry_y = with_images(ball.symmetry_y);
  return out;
}
} // namespace feticon::mesh

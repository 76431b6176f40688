#include "decomposition/partition.hpp"

#include "common/error.hpp"

#include <metis.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <tuple>
#include <utility>

namespace feticon::decomposition
{
namespace
{
/// True if the graph (CSR) is connected: a breadth-first search from vertex 0 reaches all.
bool face_graph_connected(const std::vector<idx_t>& xadj, const std::vector<idx_t>& adjncy)
{
  const size_t n = xadj.size() - 1;
  std::vector<char> seen(n, 0);
  std::vector<idx_t> queue{0};
  seen[0] = 1;
  for (size_t head = 0; head < queue.size(); ++head)
    for (idx_t k = xadj[queue[head]]; k < xadj[queue[head] + 1]; ++k)
      if (!seen[adjncy[k]])
      {
        seen[adjncy[k]] = 1;
        queue.push_back(adjncy[k]);
      }
  return queue.size() == n;
}

/// The cell face graph (CSR): each cell's neighbours through a face, in the order of the
/// faces' sorted corners. Sorting (face corners, cell) pairs and pairing equal neighbours
/// replaced a map of 1.8 M faces at hertz3d 924k (about 5 % of the set-up's samples).
struct CellFaceGraph
{
  std::vector<idx_t> xadj, adjncy;
  std::vector<double> area; ///< of the face each adjacency crosses (where asked for)
};

/// Area of a face from its corners (a quad's from its diagonals; an edge's length in 2D).
double face_area(const mesh::Mesh& mesh, const mesh::Face& face)
{
  auto x = [&](int a) -> Eigen::Vector3d { return mesh.nodes.row(face[a]).transpose(); };
  switch (face.n_corners())
  {
  case 2:
    return (x(1) - x(0)).norm();
  case 3:
    return 0.5 * (x(1) - x(0)).cross(x(2) - x(0)).norm();
  default:
    return 0.5 * (x(2) - x(0)).cross(x(3) - x(1)).norm();
  }
}

/// With `areas`, also each shared face's area (METIS's weights), computed once per pair of
/// cells: the sort keeps (corners, 8 cell + local face) and the split of disconnected parts,
/// which needs no areas, pays nothing for them.
CellFaceGraph cell_face_graph(const mesh::Mesh& mesh, bool areas = false)
{
  std::vector<std::pair<std::array<int32_t, 4>, int64_t>> faces;
  for (int32_t c = 0; c < mesh.n_cells(); ++c)
    for (size_t k = 0; k < mesh::cell_type(mesh.cells.kind(c)).faces.size(); ++k)
      faces.emplace_back(mesh::sorted_corners(mesh::cell_face(mesh.cells.kind(c), mesh.cells[c], static_cast<int>(k))),
                         8 * int64_t{c} + static_cast<int64_t>(k));
  std::sort(faces.begin(), faces.end());
  std::vector<std::vector<std::pair<int32_t, double>>> neighbours(mesh.n_cells());
  for (size_t first = 0, last = 0; first < faces.size(); first = last)
  {
    for (last = first + 1; last < faces.size() && faces[last].first == faces[first].first;)
      ++last;
    if (last - first == 2) // a face of two cells (three or more: a non-manifold face, no neighbours)
    {
      const auto a = static_cast<int32_t>(faces[first].second / 8),
                 b = static_cast<int32_t>(faces[first + 1].second / 8);
      const double area =
          areas ? face_area(mesh, mesh::cell_face(mesh.cells.kind(a), mesh.cells[a], faces[first].second % 8)) : 0.0;
      neighbours[a].emplace_back(b, area);
      neighbours[b].emplace_back(a, area);
    }
  }
  CellFaceGraph graph;
  graph.xadj.assign(1, 0);
  for (const auto& list : neighbours)
  {
    for (const auto& [cell, area] : list)
    {
      graph.adjncy.push_back(cell);
      if (areas)
        graph.area.push_back(area);
    }
    graph.xadj.push_back(static_cast<idx_t>(graph.adjncy.size()));
  }
  return graph;
}

/// METIS's edge weights for faces of these areas: each face's area over the smallest, rounded,
/// from 1 to 100.
///
/// METIS minimizes the weighted edge cut. Unweighted it counts cut faces, and on a graded mesh
/// (cells ten times larger away from a contact than at it) the fewest faces are cut through the
/// coarse cells, which leaves subdomains long and thin in space: many small cells one way, few
/// large ones the other. FETI's condition number grows with that aspect ratio (the constants
/// of its bound are Korn's and the trace theorem's of each subdomain). Weighted by area, the cut
/// is the interfaces' area and the subdomains come out compact in space. Measured on graded hex
/// meshes (docs/benchmarks.md, "METIS weighs faces by area"): a stack of eight bodies, 486k DOFs
/// in 64 subdomains, 502 -> 163 MPRGP steps; a sphere on a block at 136k DOFs, 412 -> 179;
/// hertz3d refinement 2, 253 -> 172. The cap of 100 is measured too: without it 194, 161 and
/// 248 steps; with 30, 239, 156 and 163; weights of area^0.75 did worse on three of the four
/// meshes (with the leaf pack), of area^0.5 on all four. Faces within a factor 1.5 of
/// the smallest all weigh 1, so near-uniform meshes keep the partitions they had. On a large
/// body the cap is lower, so that the weights' sum stays below 2^30: METIS adds them up (over
/// merged edges while coarsening) in its 32-bit idx_t.
std::vector<idx_t> area_weights(const std::vector<double>& area)
{
  double smallest = std::numeric_limits<double>::max();
  for (double a : area)
    if (a > 0)
      smallest = std::min(smallest, a);
  const double largest = std::clamp(std::floor(double(1 << 30) / std::max<double>(1, area.size())), 1.0, 100.0);
  std::vector<idx_t> weight(area.size());
  for (size_t k = 0; k < area.size(); ++k)
    weight[k] = static_cast<idx_t>(std::clamp(std::round(area[k] / smallest), 1.0, largest));
  return weight;
}

/// Parts per body in proportion to its cells (largest remainder), at least one each.
std::vector<int> parts_per_body(const mesh::Mesh& mesh, int n_subdomains)
{
  FETICON_CHECK(n_subdomains >= mesh.n_bodies(),
                "partition: " << n_subdomains << " subdomains requested but the mesh has " << mesh.n_bodies()
                              << " bodies (at least one each)");
  FETICON_CHECK(n_subdomains <= mesh.n_cells(),
                "partition: " << n_subdomains << " subdomains requested for " << mesh.n_cells() << " cells");
  std::vector<int32_t> body_cells(mesh.n_bodies(), 0);
  for (int32_t b : mesh.cell_body)
    ++body_cells[b];
  std::vector<int> body_parts(mesh.n_bodies(), 1);
  int remaining = n_subdomains - mesh.n_bodies();
  while (remaining-- > 0)
  {
    int best = 0;
    for (int b = 1; b < mesh.n_bodies(); ++b)
      if (static_cast<double>(body_cells[b]) / body_parts[b] > static_cast<double>(body_cells[best]) / body_parts[best])
        best = b;
    ++body_parts[best];
  }
  return body_parts;
}

std::vector<Eigen::Vector3d> cell_centroids(const mesh::Mesh& mesh)
{
  std::vector<Eigen::Vector3d> centroid(mesh.n_cells(), Eigen::Vector3d::Zero());
  for (int32_t c = 0; c < mesh.n_cells(); ++c)
    for (int32_t node : mesh.cells[c])
      centroid[c] += mesh.nodes.row(node).transpose() / static_cast<double>(mesh.cells[c].size());
  return centroid;
}

/// Renumbers ids to 0..k-1 in order of first appearance.
Partition compact(std::vector<int32_t> ids)
{
  std::map<int32_t, int32_t> renumber;
  for (int32_t& id : ids)
  {
    auto [it, inserted] = renumber.emplace(id, static_cast<int32_t>(renumber.size()));
    id = it->second;
  }
  return {std::move(ids), static_cast<int32_t>(renumber.size())};
}

/// split_disconnected on the graph of the partition's mesh.
Partition split_disconnected(const CellFaceGraph& graph, const Partition& partition)
{
  const std::vector<idx_t>& xadj = graph.xadj;
  const std::vector<idx_t>& adjncy = graph.adjncy;
  const auto n_cells = static_cast<int32_t>(xadj.size() - 1);
  std::vector<int32_t> component(n_cells, -1);
  int32_t next = 0;
  std::vector<int32_t> stack;
  for (int32_t seed = 0; seed < n_cells; ++seed)
  {
    if (component[seed] >= 0)
      continue;
    component[seed] = next;
    stack.assign(1, seed);
    while (!stack.empty())
    {
      const int32_t c = stack.back();
      stack.pop_back();
      for (idx_t k = xadj[c]; k < xadj[c + 1]; ++k)
      {
        const int32_t nb = adjncy[k];
        if (component[nb] < 0 && partition.cell_subdomain[nb] == partition.cell_subdomain[c])
        {
          component[nb] = next;
          stack.push_back(nb);
        }
      }
    }
    ++next;
  }
  return compact(std::move(component));
}

/// Recursive coordinate bisection of `cells` (indices into centroid/size) into n parts.
void bisect(std::vector<int32_t>& cells, size_t first, size_t last, int n, int32_t first_id,
            const std::vector<Eigen::Vector3d>& centroid, const std::vector<Eigen::Vector3d>& size,
            std::vector<int32_t>& ids)
{
  if (n == 1)
  {
    for (size_t k = first; k < last; ++k)
      ids[cells[k]] = first_id;
    return;
  }
  // Axis of the largest extent measured in cells (graded meshes: cells, not metres).
  int axis = 0;
  double best = -1;
  for (int d = 0; d < 3; ++d)
  {
    double lo = 1e300, hi = -1e300;
    std::vector<double> sizes;
    for (size_t k = first; k < last; ++k)
    {
      lo = std::min(lo, centroid[cells[k]](d));
      hi = std::max(hi, centroid[cells[k]](d));
      sizes.push_back(size[cells[k]](d));
    }
    std::nth_element(sizes.begin(), sizes.begin() + sizes.size() / 2, sizes.end());
    const double extent = (hi - lo) / sizes[sizes.size() / 2];
    if (extent > best)
    {
      best = extent;
      axis = d;
    }
  }
  const int n_first = n / 2;
  // Ties along the axis (a column of cells at one abscissa) are broken by the other
  // coordinates, so that a cut through the column leaves both halves connected.
  const int second = (axis + 1) % 3, third = (axis + 2) % 3;
  std::sort(cells.begin() + first, cells.begin() + last, [&](int32_t a, int32_t b) {
    const Eigen::Vector3d& x = centroid[a];
    const Eigen::Vector3d& y = centroid[b];
    return std::tie(x(axis), x(second), x(third)) < std::tie(y(axis), y(second), y(third));
  });
  // Cut between two layers of cells when one lies within half a part of the balanced cut:
  // on structured meshes the parts are then boxes, not boxes with a step where the cut
  // crossed a column (the weak-scaling punch at 15 cells per subdomain, 63 to 4 032
  // subdomains: 27, 29, 30, 31 MPRGP steps with the steps, 18, 23, 27, 29 without).
  // Unstructured meshes have no layers; the balanced cut stays.
  const size_t balanced = first + (last - first) * n_first / n;
  const size_t window = (last - first) / (2 * static_cast<size_t>(n));
  auto layer_boundary = [&](size_t k) {
    const double gap = centroid[cells[k]](axis) - centroid[cells[k - 1]](axis);
    return gap > 1e-6 * std::min(size[cells[k]](axis), size[cells[k - 1]](axis));
  };
  size_t middle = balanced;
  for (size_t offset = 0; offset <= window; ++offset)
  {
    if (balanced - offset > first && layer_boundary(balanced - offset))
    {
      middle = balanced - offset;
      break;
    }
    if (balanced + offset < last && layer_boundary(balanced + offset))
    {
      middle = balanced + offset;
      break;
    }
  }
  bisect(cells, first, middle, n_first, first_id, centroid, size, ids);
  bisect(cells, middle, last, n - n_first, first_id + n_first, centroid, size, ids);
}
} // namespace

Partition partition_structured(const mesh::Mesh& mesh, std::array<int, 3> parts)
{
  for (int p : parts)
    FETICON_CHECK(p >= 1, "structured partition: parts per direction must be >= 1, got " << p);
  const std::vector<Eigen::Vector3d> centroid = cell_centroids(mesh);
  const int per_body = parts[0] * parts[1] * parts[2];
  std::vector<int32_t> ids(mesh.n_cells());
  for (int32_t body = 0; body < mesh.n_bodies(); ++body)
  {
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
    for (int32_t c = 0; c < mesh.n_cells(); ++c)
      if (mesh.cell_body[c] == body)
      {
        lo = lo.cwiseMin(centroid[c]);
        hi = hi.cwiseMax(centroid[c]);
      }
    for (int32_t c = 0; c < mesh.n_cells(); ++c)
    {
      if (mesh.cell_body[c] != body)
        continue;
      int box = 0;
      for (int d = 2; d >= 0; --d)
      {
        const double extent = hi(d) - lo(d);
        int k = extent > 0 ? static_cast<int>(std::floor((centroid[c](d) - lo(d)) / extent * parts[d])) : 0;
        k = std::clamp(k, 0, parts[d] - 1);
        box = box * parts[d] + k;
      }
      ids[c] = body * per_body + box;
    }
  }
  return split_disconnected(mesh, compact(std::move(ids)));
}

Partition partition_metis(const mesh::Mesh& mesh, int n_subdomains)
{
  const CellFaceGraph graph = cell_face_graph(mesh, true);
  const std::vector<idx_t>& xadj = graph.xadj;
  const std::vector<idx_t>& adjncy = graph.adjncy;

  const std::vector<int> body_parts = parts_per_body(mesh, n_subdomains);

  std::vector<int32_t> ids(mesh.n_cells(), 0);
  int offset = 0;
  for (int32_t body = 0; body < mesh.n_bodies(); ++body)
  {
    // Subgraph of this body's cells.
    std::vector<int32_t> cells, local(mesh.n_cells(), -1);
    for (int32_t c = 0; c < mesh.n_cells(); ++c)
      if (mesh.cell_body[c] == body)
      {
        local[c] = static_cast<int32_t>(cells.size());
        cells.push_back(c);
      }
    idx_t nparts = body_parts[body];
    if (nparts == 1)
    {
      for (int32_t c : cells)
        ids[c] = offset;
      offset += 1;
      continue;
    }
    std::vector<idx_t> sub_xadj(1, 0), sub_adjncy;
    std::vector<double> sub_area;
    for (int32_t c : cells)
    {
      for (idx_t k = xadj[c]; k < xadj[c + 1]; ++k)
        if (local[adjncy[k]] >= 0)
        {
          sub_adjncy.push_back(local[adjncy[k]]);
          sub_area.push_back(graph.area[static_cast<size_t>(k)]);
        }
      sub_xadj.push_back(static_cast<idx_t>(sub_adjncy.size()));
    }
    std::vector<idx_t> sub_weight = area_weights(sub_area);
    idx_t nvtxs = static_cast<idx_t>(cells.size()), ncon = 1, objval = 0;
    std::vector<idx_t> part(cells.size());
    idx_t options[METIS_NOPTIONS];
    METIS_SetDefaultOptions(options);
    // Connected parts (6 rigid modes each) where the body's face graph is connected; a body
    // whose cells touch only at edges or nodes somewhere is one body to feticon but not to the
    // face graph, and METIS refuses CONTIG there (printing its own message): split_disconnected
    // below makes such parts connected.
    options[METIS_OPTION_CONTIG] = face_graph_connected(sub_xadj, sub_adjncy) ? 1 : 0;
    options[METIS_OPTION_SEED] = 1; // reproducible partitions
    const int status = METIS_PartGraphKway(&nvtxs, &ncon, sub_xadj.data(), sub_adjncy.data(), nullptr, nullptr,
                                           sub_weight.data(), &nparts, nullptr, nullptr, options, &objval, part.data());
    FETICON_CHECK(status == METIS_OK,
                  "METIS failed to partition body '" << mesh.body_names[body] << "' into " << nparts
                                                     << " parts (status " << status << ")");
    for (size_t k = 0; k < cells.size(); ++k)
      ids[cells[k]] = offset + static_cast<int32_t>(part[k]);
    offset += static_cast<int>(nparts);
  }
  return split_disconnected(graph, compact(std::move(ids)));
}

Partition partition_rcb(const mesh::Mesh& mesh, int n_subdomains)
{
  const std::vector<Eigen::Vector3d> centroid = cell_centroids(mesh);
  std::vector<Eigen::Vector3d> size(mesh.n_cells()); // bounding-box edges of each cell
  for (int32_t c = 0; c < mesh.n_cells(); ++c)
  {
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
    for (int32_t node : mesh.cells[c])
    {
      lo = lo.cwiseMin(mesh.nodes.row(node).transpose());
      hi = hi.cwiseMax(mesh.nodes.row(node).transpose());
    }
    size[c] = hi - lo;
  }
  const std::vector<int> body_parts = parts_per_body(mesh, n_subdomains);
  std::vector<int32_t> ids(mesh.n_cells(), 0);
  int offset = 0;
  for (int32_t body = 0; body < mesh.n_bodies(); ++body)
  {
    std::vector<int32_t> cells;
    for (int32_t c = 0; c < mesh.n_cells(); ++c)
      if (mesh.cell_body[c] == body)
        cells.push_back(c);
    bisect(cells, 0, cells.size(), body_parts[body], offset, centroid, size, ids);
    offset += body_parts[body];
  }
  return split_disconnected(mesh, compact(std::move(ids)));
}

Partition split_disconnected(const mesh::Mesh& mesh, const Partition& partition)
{
  return split_disconnected(cell_face_graph(mesh), partition);
}
} // namespace feticon::decomposition

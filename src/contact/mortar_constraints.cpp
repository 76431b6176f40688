#include "contact/mortar_constraints.hpp"
#include "contact/contact_row_builder.hpp"

#include "contact/mortar_face_integration.hpp"
#include "contact/surface_search.hpp"

#include "common/error.hpp"
#include "common/parallel.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <utility>

namespace feticon::contact
{
namespace
{
/// Sparse row of M under assembly: (master node, M_ja) pairs, a few per slave node.
using CouplingRow = std::vector<std::pair<int32_t, double>>;

/// |M_ja| <= this * D_j is integration round-off (biorthogonality zeros such as the far
/// through-thickness master node of a matching layer) or a sliver without effect: such entries
/// are left out of the row, and the renormalization uses the entries kept.
constexpr double negligible_coupling = 1e-13;

void add_to_row(CouplingRow& row, int32_t master_node, double value)
{
  for (auto& [node, sum] : row)
    if (node == master_node)
    {
      sum += value;
      return;
    }
  row.emplace_back(master_node, value);
}

bool share_a_node(const mesh::Face& first, const mesh::Face& second)
{
  return std::ranges::any_of(first, [&](int32_t node) { return std::ranges::find(second, node) != second.end(); });
}

Eigen::Vector3d current_position(const mesh::Mesh& mesh, const la::Vector& u, int32_t node)
{
  Eigen::Vector3d x = mesh.nodes.row(node).transpose();
  if (u.size() > 0)
    x += u.segment<3>(3 * static_cast<la::Index>(node));
  return x;
}

void check_displacement(const mesh::Mesh& mesh, const la::Vector& u)
{
  const la::Index n_dofs = 3 * static_cast<la::Index>(mesh.n_nodes());
  FETICON_CHECK(u.size() == 0 || u.size() == n_dofs,
                "mortar: displacement has " << u.size() << " entries, expected 3 * n_nodes = " << n_dofs
                                            << " (or 0 for u = 0)");
}

/// What mortar integration needs of its input: u of the mesh, a positive search distance and
/// non-empty slave and master face sets (mortar integrates whole faces, not nodes).
void check_mortar_input(const mesh::Mesh& mesh, const la::Vector& u, const ContactPair& pair, double search_distance)
{
  check_displacement(mesh, u);
  FETICON_CHECK(std::isfinite(search_distance) && search_distance > 0,
                "mortar: search distance = " << search_distance << " m must be > 0");
  FETICON_CHECK(pair.slave_nodes.empty(),
                "mortar: the slave surface '" << pair.slave << "' is given by nodes; mortar integrates whole "
                                              << "slave faces: use contact.formulation=node_to_segment");
  FETICON_CHECK(!mesh.face_set(pair.slave).empty(), "mortar: slave face set '" << pair.slave << "' is empty");
  FETICON_CHECK(!mesh.face_set(pair.master).empty(), "mortar: master face set '" << pair.master << "' is empty");
}

/// Per slave index: the corners at the ends of its edge if it is an edge node of a quadratic
/// slave face, else {-1, -1}.
std::vector<std::array<int32_t, 2>> quadratic_edge_ends(const mesh::Mesh& mesh, const std::string& slave,
                                                        const SlaveNodalAreas& nodes)
{
  std::vector<std::array<int32_t, 2>> ends(nodes.nodes.size(), {-1, -1});
  for (const mesh::Face& face : mesh.face_set(slave))
  {
    if (!is_quadratic(face.kind))
      continue;
    // Edge node corners + e joins corners e and e + 1 (fem/reference_face.hpp); a line3's one
    // edge node joins its two ends.
    const int corners = mesh::face_corners(face.kind);
    for (int e = 0; e < face.size() - corners; ++e)
      ends[nodes.index_of(face[corners + e])] = {face[e], face[(e + 1) % corners]};
  }
  return ends;
}

/// Unit normals at the nodes of the master faces other than quad4: the mean of the normals there
/// of the faces around each node.
std::unordered_map<int32_t, Eigen::Vector3d> master_nodal_normals(const mesh::Mesh& mesh, const la::Vector& u,
                                                                  const std::vector<mesh::Face>& faces)
{
  std::unordered_map<int32_t, Eigen::Vector3d> normals;
  for (const mesh::Face& face : faces)
  {
    if (face.kind == mesh::FaceKind::quad4)
      continue;
    const FaceGeometry geometry = current_face_geometry(mesh, u, face);
    for (int a = 0; a < face.size(); ++a)
    {
      auto [it, inserted] = normals.try_emplace(face[a], Eigen::Vector3d::Zero());
      it->second += face_normal(geometry, face_node_xi(face.kind, a));
    }
  }
  for (auto& [node, n] : normals)
    n.normalize();
  return normals;
}

/// The normal of row i: the node-to-segment one (the master face's normal at the closest point)
/// on quad4 faces, the hex8 runs' rows; on the other face types the nodal normals interpolated
/// at the closest point, continuous across the master faces' edges. Face normals jump there,
/// by a few 1e-3 rad between the triangles of a deformed flat surface, and a weighted gap
/// n . (x_j - sum_a w_a x_a) whose master point lies off the normal through x_j jumps with
/// them: tet10 hertz3d with large displacements cycled between two row sets at |du|/|u| =
/// 1.1e-6 with the face normals.
Eigen::Vector3d row_normal(const ContactConstraints& closest, la::Index i, const std::vector<mesh::Face>& master_faces,
                           const std::unordered_map<int32_t, Eigen::Vector3d>& master_normals)
{
  const mesh::Face& face = master_faces[closest.master_face[i]];
  if (face.kind == mesh::FaceKind::quad4 || closest.kind[i] != ProjectionKind::face)
    return closest.normal[i];
  const Eigen::VectorXd shape = face_weights(face.kind, closest.xi[i]);
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  for (int a = 0; a < face.size(); ++a)
    n += shape(a) * master_normals.at(face[a]);
  return n.normalized();
}

/// Nodal areas and segments of one slave face.
struct FaceSegments
{
  Eigen::VectorXd nodal_area;                                ///< D_j (D~_j of quadratic faces)
  std::vector<std::pair<int32_t, Eigen::MatrixXd>> segments; ///< (master face, coupling)
};

/// The dual basis of a slave face and its segments with the candidate master faces (those
/// sharing no node with it). quad4 against quad4 goes through integrate_segment, the arithmetic
/// of hex8 runs; any other pair (edges of 2D cells included) through integrate_face_segment.
FaceSegments integrate_slave_face(const mesh::Face& face, const FaceGeometry& slave,
                                  const std::vector<mesh::Face>& master_faces,
                                  const std::vector<FaceGeometry>& master_geometry, const SurfaceSearch& search,
                                  const SegmentOptions& options, std::vector<int32_t>& candidates)
{
  FaceSegments out;
  BoundingBox box;
  for (Eigen::Index k = 0; k < slave.x.rows(); ++k)
    box.extend(slave.x.row(k).transpose());
  search.candidates(box, candidates);
  std::optional<DualBasis> quad_dual;
  std::optional<FaceDualBasis> dual;
  if (face.kind == mesh::FaceKind::quad4)
  {
    quad_dual = dual_basis(slave.quad());
    out.nodal_area = quad_dual->nodal_area;
  }
  else
  {
    dual = face_dual_basis(slave);
    out.nodal_area = dual->nodal_area;
  }
  const SlaveFootprint footprint(slave);
  for (const int32_t f : candidates)
  {
    if (share_a_node(face, master_faces[f]) || !footprint.may_overlap(master_geometry[f]))
      continue;
    if (quad_dual && master_faces[f].kind == mesh::FaceKind::quad4)
    {
      if (const std::optional<SegmentCoupling> segment =
              integrate_segment(slave.quad(), *quad_dual, master_geometry[f].quad(), options))
        out.segments.emplace_back(f, segment->coupling);
      continue;
    }
    if (!dual)
      dual = face_dual_basis(slave);
    if (std::optional<Eigen::MatrixXd> segment = integrate_face_segment(slave, *dual, master_geometry[f], options))
      out.segments.emplace_back(f, std::move(*segment));
  }
  return out;
}
} // namespace

int32_t SlaveNodalAreas::index_of(int32_t node) const
{
  const auto it = std::ranges::lower_bound(nodes, node);
  return it != nodes.end() && *it == node ? static_cast<int32_t>(it - nodes.begin()) : -1;
}

double SlaveNodalAreas::of(int32_t node) const
{
  const int32_t j = index_of(node);
  FETICON_CHECK(j >= 0, "mortar: node " << node << " is not a slave node");
  return area(j);
}

SlaveNodalAreas slave_nodal_areas(const mesh::Mesh& mesh, const la::Vector& u, const std::string& slave)
{
  check_displacement(mesh, u);
  SlaveNodalAreas areas;
  areas.nodes = mesh.face_set_nodes(slave);
  areas.area = la::Vector::Zero(static_cast<la::Index>(areas.nodes.size()));
  for (const mesh::Face& face : mesh.face_set(slave))
  {
    const Eigen::VectorXd nodal_areas = face_lumped_areas(current_face_geometry(mesh, u, face));
    for (int k = 0; k < face.size(); ++k)
      areas.area(areas.index_of(face[k])) += nodal_areas(k);
  }
  return areas;
}

MortarCoupling compute_mortar_coupling(const mesh::Mesh& mesh, const la::Vector& u, const ContactPair& pair,
                                       double search_distance, const SegmentOptions& options,
                                       const std::vector<int32_t>* row_nodes)
{
  check_mortar_input(mesh, u, pair, search_distance);
  const std::vector<mesh::Face>& slave_faces = mesh.face_set(pair.slave);
  const std::vector<mesh::Face>& master_faces = mesh.face_set(pair.master);

  std::vector<FaceGeometry> master_geometry;
  master_geometry.reserve(master_faces.size());
  std::vector<BoundingBox> boxes(master_faces.size());
  for (size_t f = 0; f < master_faces.size(); ++f)
  {
    master_geometry.push_back(current_face_geometry(mesh, u, master_faces[f]));
    for (Eigen::Index a = 0; a < master_geometry[f].x.rows(); ++a)
      boxes[f].extend(master_geometry[f].x.row(a).transpose());
    boxes[f].inflate(search_distance);
  }
  const SurfaceSearch search(std::move(boxes));

  MortarCoupling coupling;
  coupling.search_distance = search_distance;
  coupling.slave.nodes = mesh.face_set_nodes(pair.slave);
  const auto n_slave = static_cast<la::Index>(coupling.slave.nodes.size());
  coupling.slave.area = la::Vector::Zero(n_slave);
  // The segments of every slave face on the threads, then summed in face order: M and the
  // nodal areas are the same bit for bit whatever the thread count.
  std::vector<FaceSegments> per_face(slave_faces.size());
  // A face none of whose nodes has a row adds nothing to the rows' D_j and M_ja: skipped (it
  // keeps a zero nodal area and no segments). The outer loop of large displacements has rows
  // only near contact, a few of the faces.
  std::vector<char> is_row_node;
  if (row_nodes)
  {
    is_row_node.assign(mesh.n_nodes(), 0);
    for (const int32_t node : *row_nodes)
      is_row_node[node] = 1;
  }
  const auto integrated = [&](const mesh::Face& face) {
    return !row_nodes || std::ranges::any_of(face, [&](int32_t node) { return is_row_node[node] != 0; });
  };
  parallel_for_chunks(slave_faces.size(), 64, [&](size_t begin, size_t end) {
    std::vector<int32_t> candidates;
    for (size_t i = begin; i < end; ++i)
      if (integrated(slave_faces[i]))
        per_face[i] = integrate_slave_face(slave_faces[i], current_face_geometry(mesh, u, slave_faces[i]), master_faces,
                                           master_geometry, search, options, candidates);
  });

  std::vector<CouplingRow> rows(n_slave);
  for (size_t i = 0; i < slave_faces.size(); ++i)
  {
    const mesh::Face& face = slave_faces[i];
    if (per_face[i].nodal_area.size() == 0)
      continue;
    std::array<int32_t, 8> slave_index{};
    for (int k = 0; k < face.size(); ++k)
    {
      slave_index[k] = coupling.slave.index_of(face[k]);
      coupling.slave.area(slave_index[k]) += per_face[i].nodal_area(k);
    }
    for (const auto& [f, segment] : per_face[i].segments)
    {
      ++coupling.n_segments;
      for (int k = 0; k < face.size(); ++k)
        for (int a = 0; a < master_faces[f].size(); ++a)
          add_to_row(rows[slave_index[k]], master_faces[f][a], segment(k, a));
    }
  }

  std::vector<Eigen::Triplet<double>> triplets;
  for (la::Index j = 0; j < n_slave; ++j)
    for (const auto& [node, value] : rows[j])
      triplets.emplace_back(j, node, value);
  coupling.M.resize(n_slave, mesh.n_nodes());
  coupling.M.setFromTriplets(triplets.begin(), triplets.end());
  coupling.edge_ends = quadratic_edge_ends(mesh, pair.slave, coupling.slave);
  return coupling;
}

std::optional<MortarRowWeights> mortar_row_weights(const MortarCoupling& coupling, la::Index j, double min_overlap)
{
  const double nodal_area = coupling.slave.area(j);
  MortarRowWeights out;
  double overlap = 0;
  for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(coupling.M, j); it; ++it)
    if (std::abs(it.value()) > negligible_coupling * nodal_area)
    {
      out.weights.emplace_back(static_cast<int32_t>(it.col()), it.value());
      overlap += it.value();
    }
  if (!(overlap >= min_overlap * nodal_area))
    return std::nullopt;
  // An edge node's row is that of its transformed value x~_m = (x_m - alpha (x_c1 + x_c2)) /
  // (1 - 2 alpha) (mortar_face_integration.hpp), scaled to a unit coefficient on x_m: the
  // master weights times 1 - 2 alpha, its edge's corners alpha each (all summing to 1).
  const std::array<int32_t, 2>& ends = coupling.edge_ends[j];
  out.share = ends[0] >= 0 ? 1 - 2 * quadratic_dual_alpha : 1.0;
  for (auto& [node, weight] : out.weights)
    weight = weight / overlap * out.share;
  if (ends[0] >= 0)
    for (const int32_t corner : ends)
      out.weights.emplace_back(corner, quadratic_dual_alpha);
  return out;
}

ContactConstraints build_mortar_constraints(const mesh::Mesh& mesh, const la::Vector& u, const ContactPair& pair,
                                            const ContactOptions& options)
{
  // Validates the input and gives, per slave node, whether a row exists and its normal.
  ContactConstraints closest = build_node_to_segment_constraints(mesh, u, pair, options);
  const MortarCoupling coupling =
      compute_mortar_coupling(mesh, u, pair, closest.search_distance, {}, &closest.slave_node);

  ContactConstraints out;
  out.search_distance = closest.search_distance;
  out.n_slave_nodes = closest.n_slave_nodes;
  out.n_overhanging = closest.n_overhanging;
  out.formulation = ContactFormulation::mortar;
  out.transformed_basis =
      std::ranges::any_of(mesh.face_set(pair.slave), [](const mesh::Face& face) { return is_quadratic(face.kind); });
  const std::vector<mesh::Face>& master_faces = mesh.face_set(pair.master);
  const std::unordered_map<int32_t, Eigen::Vector3d> master_normals = master_nodal_normals(mesh, u, master_faces);
  ContactRowBuilder rows;
  for (la::Index i = 0; i < closest.n_rows(); ++i)
  {
    const int32_t s = closest.slave_node[i];
    const int32_t j = coupling.slave.index_of(s);
    const std::optional<MortarRowWeights> row = mortar_row_weights(coupling, j, options.mortar_min_overlap);
    if (!row)
    {
      ++out.n_overhanging;
      continue;
    }
    const auto& [weights, share] = *row;
    // The area D~_m / (1 - 2 alpha) of an edge node, so that force / area is still the nodal
    // pressure z_m.
    const double nodal_area = coupling.slave.area(j);
    const Eigen::Vector3d n = row_normal(closest, i, master_faces, master_normals);
    Eigen::Vector3d master_point = Eigen::Vector3d::Zero();
    for (const auto& [node, weight] : weights)
      master_point += weight * current_position(mesh, u, node);
    const double gap = n.dot(current_position(mesh, u, s) - master_point);
    if (!(gap < out.search_distance))
      continue;
    rows.add({s, n, gap, nodal_area / share, closest.master_face[i], closest.xi[i], closest.kind[i], share}, weights);
  }
  rows.finish(3 * static_cast<la::Index>(mesh.n_nodes()), out);
  return out;
}
} // namespace feticon::contact

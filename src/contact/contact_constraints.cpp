#include "contact/contact_constraints.hpp"
#include "contact/contact_row_builder.hpp"

#include "contact/mortar_constraints.hpp"

#include "common/error.hpp"
#include "common/parallel.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <utility>

namespace feticon::contact
{
namespace
{
/// The closest master point chosen for one slave node.
struct ClosestPoint
{
  int32_t face = -1;
  Eigen::Vector2d xi{0, 0};
  Eigen::Vector3d normal{0, 0, 0};
  double gap = 0;
  ProjectionKind kind = ProjectionKind::face;
};

/// Which master edges lie on the boundary of the master surface: those of only one master face;
/// of a master curve (the edges of 2D cells), the corners of only one master edge.
class SurfaceBoundary
{
public:
  explicit SurfaceBoundary(const std::vector<mesh::Face>& faces)
  {
    for (const mesh::Face& face : faces)
      if (mesh::is_line(face.kind))
        for (int a = 0; a < 2; ++a)
          ++_corner_faces[face[a]];
      else
        for (int a = 0, n = face.n_corners(); a < n; ++a)
          ++_edge_faces[key(face[a], face[(a + 1) % n])];
  }
  bool edge_on_boundary(int32_t a, int32_t b) const { return _edge_faces.at(key(a, b)) == 1; }
  bool corner_on_boundary(int32_t a) const { return _corner_faces.at(a) == 1; }

private:
  static std::pair<int32_t, int32_t> key(int32_t a, int32_t b) { return std::minmax(a, b); }
  std::map<std::pair<int32_t, int32_t>, int32_t> _edge_faces;
  std::map<int32_t, int32_t> _corner_faces;
};

/// Distance beyond a boundary side, relative to the face size, from which a node is beyond the rim
/// of the master surface: the same 1e-6 as the acceptance tolerance of a projection.
constexpr double rim_tolerance = 1e-6;

/// Whether x_s lies beyond a boundary side of the face (file comment): for a face, on the outer
/// side of the line of a boundary side in the face's tangent plane, whose outward in-plane
/// normal is (x_k+1 - x_k) x n_f (counter-clockwise sides seen from outside); for an edge of a
/// 2D cell, past a boundary corner along the edge.
bool beyond_boundary(const mesh::Face& face, const FaceGeometry& geometry, const SurfaceBoundary& boundary,
                     const Eigen::Vector3d& x_s)
{
  const double tolerance = rim_tolerance * face_size(geometry);
  if (mesh::is_line(face.kind))
  {
    for (int k = 0; k < 2; ++k)
    {
      const Eigen::Vector3d corner = geometry.x.row(k).transpose();
      const Eigen::Vector3d outward = (corner - geometry.x.row(1 - k).transpose()).normalized();
      if (boundary.corner_on_boundary(face[k]) && outward.dot(x_s - corner) > tolerance)
        return true;
    }
    return false;
  }
  const int n_corners = geometry.n_corners();
  for (int k = 0; k < n_corners; ++k)
  {
    const int next = (k + 1) % n_corners;
    if (!boundary.edge_on_boundary(face[k], face[next]))
      continue;
    const Eigen::Vector3d start = geometry.x.row(k).transpose();
    const Eigen::Vector3d side = geometry.x.row(next).transpose() - start;
    const Eigen::Vector2d mid = 0.5 * (face_corner_xi(geometry.kind, k) + face_corner_xi(geometry.kind, next));
    const Eigen::Vector3d outward = side.cross(face_normal(geometry, mid)).normalized();
    if (outward.dot(x_s - start) > tolerance)
      return true;
  }
  return false;
}

bool has_corner(const mesh::Face& face, int32_t node) { return std::ranges::find(face, node) != face.end(); }

/// Accepted face projection with the smallest |g| among the candidates, if any. An accepted
/// projection is a stationary point, so |g| = |x_s - x(xi_bar)| is at least the distance from x_s
/// to the face's box: candidates are visited by increasing box distance (then id) and the visit
/// stops once that distance exceeds the best |g| found, which leaves the result unchanged.
std::optional<ClosestPoint> closest_face_projection(const std::vector<FaceGeometry>& geometries,
                                                    const std::vector<BoundingBox>& face_boxes,
                                                    const std::vector<mesh::Face>& faces,
                                                    const std::vector<int32_t>& candidates, int32_t slave,
                                                    const Eigen::Vector3d& x_s)
{
  std::vector<std::pair<double, int32_t>> order;
  order.reserve(candidates.size());
  for (const int32_t f : candidates)
    if (!has_corner(faces[f], slave))
      order.emplace_back(face_boxes[f].distance(x_s), f);
  std::ranges::sort(order);
  std::optional<ClosestPoint> best;
  for (const auto& [box_distance, f] : order)
  {
    // A face whose box is farther than the best gap cannot be closer, but one a round-off
    // farther may tie with it (a node on the side two faces share lies on both boxes' rims).
    if (best && box_distance > std::abs(best->gap) + 1e-6 * face_size(geometries[best->face]))
      break;
    const FaceGeometry& face = geometries[f];
    const QuadProjection p = project_to_face(face, x_s);
    // A node on a common side, whose gaps to the two faces agree to round-off, goes to the
    // smaller face id: chosen by the round-off, it crossed from one face to the other at every
    // outer iteration. quad4 faces accept a projection up to 1e-6 outside (QuadProjection),
    // other faces (triangles, quadratic faces) up to side_tolerance: with 1e-6, a node on the
    // side of two triangles that meet at an angle crossed it each iteration (each face's
    // normal pushing it over to the other), and hertz3d with tet4, tet10 or wedge6 cells and
    // large displacements stalled at |du|/|u| ~ 1e-5. On quad4 faces the tie alone was missing:
    // CalculiX's friction1 (hard contact, matching meshes: every slave node on a master edge)
    // alternated between two iterates 6e-6 apart (relative) for any number of outer iterations.
    constexpr double side_tolerance = 1e-4;
    const bool accepted = face.kind == mesh::FaceKind::quad4
        ? p.accepted()
        : p.converged && outside_distance(face.kind, p.xi) <= side_tolerance;
    if (!accepted)
      continue;
    const double tie = 1e-9 * face_size(face);
    if (!best || std::abs(p.gap) < std::abs(best->gap) - tie ||
        (std::abs(p.gap) <= std::abs(best->gap) + tie && f < best->face))
      best = ClosestPoint{f, p.xi, p.normal, p.gap, ProjectionKind::face};
  }
  return best;
}

/// Fallback of the file comment when no projection is accepted: the closest point x_e on the
/// candidate faces' edges, on face f. Beyond a boundary side of f: the projection on f if it lies
/// within the rim extension, else nothing (overhanging). Otherwise the node-to-edge point x_e.
std::optional<ClosestPoint> outside_point(const std::vector<FaceGeometry>& geometries,
                                          const std::vector<mesh::Face>& faces, const std::vector<int32_t>& candidates,
                                          const SurfaceBoundary& boundary, int32_t slave, const Eigen::Vector3d& x_s,
                                          double rim_extension)
{
  double best_distance = std::numeric_limits<double>::infinity();
  int32_t best_face = -1;
  int best_edge = 0;
  double best_t = 0;
  for (const int32_t f : candidates)
  {
    if (has_corner(faces[f], slave))
      continue;
    for (int a = 0, n = geometries[f].n_corners(); a < n; ++a)
    {
      // Straight sides between the corners (a quadratic face's curved edges are near them).
      const Eigen::Vector3d start = geometries[f].x.row(a).transpose();
      const Eigen::Vector3d end = geometries[f].x.row((a + 1) % n).transpose();
      const double t = closest_on_segment(start, end, x_s);
      const double distance = (start + t * (end - start) - x_s).norm();
      if (distance < best_distance)
      {
        best_distance = distance;
        best_face = f;
        best_edge = a;
        best_t = t;
      }
    }
  }
  if (best_face < 0)
    return std::nullopt;

  const FaceGeometry& geometry = geometries[best_face];
  const int n_corners = geometry.n_corners();
  const double size = face_size(geometry);
  if (beyond_boundary(faces[best_face], geometry, boundary, x_s))
  {
    const QuadProjection p = project_to_face(geometry, x_s);
    if (p.converged && within_extension(geometry.kind, p.xi, rim_extension))
      return ClosestPoint{best_face, p.xi, p.normal, p.gap, ProjectionKind::rim};
    return std::nullopt;
  }

  const int b = (best_edge + 1) % n_corners;
  ClosestPoint point;
  point.face = best_face;
  point.kind = ProjectionKind::edge;
  point.xi = (1 - best_t) * face_corner_xi(geometry.kind, best_edge) + best_t * face_corner_xi(geometry.kind, b);
  const Eigen::Vector3d normal_there = face_normal(geometry, point.xi);
  const Eigen::Vector3d distance = x_s - face_point(geometry, point.xi);
  // Within the rim tolerance of the face in its own plane, the node lies on the face: its row
  // takes the face normal. The distance vector to the side is no normal there: for a node in
  // contact (gap ~ 0) off a side by round-off, such as a node of a symmetry plane that the
  // Dirichlet rows hold to ~1e-10 m, it points anywhere (measured: 60 degrees from the face
  // normal on hertz3d's axis node, which tilted its row and inflated its multiplier by 1/n_z).
  const Eigen::Vector3d in_plane = distance - distance.dot(normal_there) * normal_there;
  if (in_plane.norm() <= rim_tolerance * size)
  {
    point.normal = normal_there;
    point.gap = normal_there.dot(distance);
    return point;
  }
  const double side = distance.dot(normal_there) < 0 ? -1.0 : 1.0;
  point.normal = side * distance.normalized();
  point.gap = side * distance.norm();
  return point;
}

/// Each slave node's closest point on the master faces (closest_face_projection, else
/// outside_point), in chunks of nodes on the threads (the outer loop searches every slave node
/// at every iteration); `overhanging` grows by the nodes that have candidates but no point.
std::vector<std::optional<ClosestPoint>> closest_points_of(const mesh::Mesh& mesh, const la::Vector& u,
                                                           const std::vector<int32_t>& slave_nodes,
                                                           const std::vector<mesh::Face>& faces,
                                                           const std::vector<FaceGeometry>& geometries,
                                                           double search_distance, double rim_extension,
                                                           int32_t& overhanging)
{
  std::vector<BoundingBox> face_boxes(faces.size());
  for (size_t f = 0; f < faces.size(); ++f)
    for (Eigen::Index a = 0; a < geometries[f].x.rows(); ++a)
      face_boxes[f].extend(geometries[f].x.row(a).transpose());
  std::vector<BoundingBox> search_boxes = face_boxes;
  for (BoundingBox& box : search_boxes)
    box.inflate(search_distance);
  const SurfaceSearch search(std::move(search_boxes));
  const SurfaceBoundary boundary(faces);
  std::vector<std::optional<ClosestPoint>> closest_points(slave_nodes.size());
  std::vector<char> beyond(slave_nodes.size(), 0);
  parallel_for_chunks(slave_nodes.size(), 64, [&](size_t begin, size_t end) {
    std::vector<int32_t> candidates;
    for (size_t i = begin; i < end; ++i)
    {
      const int32_t s = slave_nodes[i];
      Eigen::Vector3d x_s = mesh.nodes.row(s).transpose();
      if (u.size() > 0)
        x_s += u.segment<3>(3 * static_cast<la::Index>(s));
      search.candidates(x_s, candidates);
      std::optional<ClosestPoint>& closest = closest_points[i];
      closest = closest_face_projection(geometries, face_boxes, faces, candidates, s, x_s);
      if (!closest && !candidates.empty())
      {
        closest = outside_point(geometries, faces, candidates, boundary, s, x_s, rim_extension);
        beyond[i] = !closest;
      }
    }
  });
  overhanging += static_cast<int32_t>(std::ranges::count(beyond, 1));
  return closest_points;
}
} // namespace

QuadCoordinates current_face_coordinates(const mesh::Mesh& mesh, const la::Vector& u, const mesh::Face& face)
{
  FETICON_ASSERT(face.kind == mesh::FaceKind::quad4, "current_face_coordinates of a face other than quad4");
  QuadCoordinates quad;
  for (int a = 0; a < 4; ++a)
  {
    quad.row(a) = mesh.nodes.row(face[a]);
    if (u.size() > 0)
      quad.row(a) += u.segment<3>(3 * static_cast<la::Index>(face[a])).transpose();
  }
  return quad;
}

double largest_face_diagonal(const mesh::Mesh& mesh, const la::Vector& u, const std::vector<mesh::Face>& faces)
{
  double diagonal = 0;
  for (const mesh::Face& face : faces)
    diagonal = std::max(diagonal, face_size(current_face_geometry(mesh, u, face)));
  return diagonal;
}

std::vector<int32_t> slave_nodes(const mesh::Mesh& mesh, const ContactPair& pair)
{
  std::vector<int32_t> nodes = mesh.face_set_nodes(pair.slave);
  if (pair.slave_nodes.empty())
    return nodes;
  const std::vector<int32_t>& restriction = mesh.node_set(pair.slave_nodes);
  std::vector<int32_t> out;
  std::ranges::set_intersection(nodes, restriction, std::back_inserter(out));
  return out;
}

std::vector<int64_t> ContactConstraints::keys() const
{
  std::vector<int64_t> out(slave_node.size());
  for (size_t i = 0; i < out.size(); ++i)
    out[i] = key(static_cast<int64_t>(i));
  return out;
}

ContactConstraints concatenate_pairs(std::vector<ContactConstraints> parts, la::Index n_global_dofs)
{
  if (parts.size() == 1) // one pair: its rows as built, pair 0 already
    return std::move(parts.front());
  ContactRowBuilder builder;
  ContactConstraints out;
  for (size_t p = 0; p < parts.size(); ++p)
  {
    const ContactConstraints& part = parts[p];
    FETICON_ASSERT(part.B.cols() == n_global_dofs, "contact rows of pair " << p << " over other DOFs");
    for (la::Index i = 0; i < part.n_rows(); ++i)
      builder.copy(part, i, part.gap[i], static_cast<int32_t>(p));
    out.search_distance = std::max(out.search_distance, part.search_distance);
    out.n_slave_nodes += part.n_slave_nodes;
    out.n_overhanging += part.n_overhanging;
    out.transformed_basis = out.transformed_basis || part.transformed_basis;
    out.pair_formulation.push_back(part.formulation);
  }
  if (!parts.empty())
    out.formulation = parts.front().formulation;
  builder.finish(n_global_dofs, out);
  return out;
}

ContactConstraints no_rows(ContactFormulation formulation, la::Index n_global_dofs)
{
  ContactConstraints out;
  out.formulation = formulation;
  ContactRowBuilder().finish(n_global_dofs, out);
  return out;
}

ContactConstraints without_rows(const ContactConstraints& rows)
{
  ContactConstraints out;
  out.formulation = rows.formulation;
  out.pair_formulation = rows.pair_formulation;
  out.transformed_basis = rows.transformed_basis;
  out.search_distance = rows.search_distance;
  out.n_slave_nodes = rows.n_slave_nodes;
  out.n_overhanging = rows.n_overhanging;
  return out;
}

ContactConstraints pair_rows(const ContactConstraints& rows, int32_t p)
{
  ContactRowBuilder builder;
  ContactConstraints out = without_rows(rows);
  if (!rows.pair_formulation.empty())
    out.formulation = rows.pair_formulation[p];
  out.pair_formulation.clear();
  for (la::Index i = 0; i < rows.n_rows(); ++i)
    if (rows.pair[i] == p)
      builder.copy(rows, i, rows.gap[i], p);
  builder.finish(rows.B.cols(), out);
  return out;
}

ContactConstraints build_contact_constraints(const mesh::Mesh& mesh, const la::Vector& u, const ContactPair& pair,
                                             const ContactOptions& options)
{
  if (options.formulation == ContactFormulation::mortar)
    return build_mortar_constraints(mesh, u, pair, options);
  return build_node_to_segment_constraints(mesh, u, pair, options);
}

ContactConstraints build_node_to_segment_constraints(const mesh::Mesh& mesh, const la::Vector& u,
                                                     const ContactPair& pair, const ContactOptions& options)
{
  const la::Index n_dofs = 3 * static_cast<la::Index>(mesh.n_nodes());
  FETICON_CHECK(u.size() == 0 || u.size() == n_dofs,
                "contact: displacement has " << u.size() << " entries, expected 3 * n_nodes = " << n_dofs
                                             << " (or 0 for u = 0)");
  FETICON_CHECK(std::isfinite(options.search_distance) && options.search_distance >= 0,
                "contact: search_distance = " << options.search_distance << " m must be >= 0 (0 = automatic)");
  FETICON_CHECK(std::isfinite(options.rim_extension) && options.rim_extension >= 0,
                "contact: rim_extension = " << options.rim_extension << " must be >= 0");
  FETICON_CHECK(options.near_contact_fraction > 0,
                "contact: near_contact_fraction = " << options.near_contact_fraction << " must be > 0");
  FETICON_CHECK(options.mortar_min_overlap > 0 && options.mortar_min_overlap <= 1,
                "contact: mortar_min_overlap = " << options.mortar_min_overlap << " must be in (0, 1]");
  const std::vector<mesh::Face>& faces = mesh.face_set(pair.master);
  FETICON_CHECK(!faces.empty(), "contact: master face set '" << pair.master << "' is empty");
  const std::vector<int32_t> slave_nodes = contact::slave_nodes(mesh, pair);

  std::vector<FaceGeometry> geometries;
  geometries.reserve(faces.size());
  for (const mesh::Face& face : faces)
    geometries.push_back(current_face_geometry(mesh, u, face));

  ContactConstraints out;
  out.n_slave_nodes = static_cast<int32_t>(slave_nodes.size());
  out.search_distance = options.search_distance > 0 ? options.search_distance : largest_face_diagonal(mesh, u, faces);
  FETICON_CHECK(out.search_distance > 0, "contact: master face set '" << pair.master << "' has only degenerate faces");

  const std::vector<std::optional<ClosestPoint>> closest_points = closest_points_of(
      mesh, u, slave_nodes, faces, geometries, out.search_distance, options.rim_extension, out.n_overhanging);
  double smallest_gap = std::numeric_limits<double>::infinity();
  for (const std::optional<ClosestPoint>& closest : closest_points)
    if (closest)
      smallest_gap = std::min(smallest_gap, closest->gap);
  // Near contact (options.near_contact_fraction): the bodies touch where the gap is at most
  // the smallest one, or 0 once they touch.
  const double contact_level = std::max(smallest_gap, 0.0);
  const auto near_contact = [&](const ClosestPoint& c) {
    return std::isinf(options.near_contact_fraction) ||
        c.gap < contact_level + options.near_contact_fraction * face_size(geometries[c.face]);
  };

  const SlaveNodalAreas areas = slave_nodal_areas(mesh, u, pair.slave);
  // CalculiX gives a node of a node surface the area of the faces it is a corner of, and a node
  // that is a corner of none (an edge node of quadratic faces; every node of a 2D model, which
  // it expands into 3D cells with the node in their mid-plane) the master face's
  // (fem::NormalLaw::on_master_face): the rows of such nodes carry it.
  std::vector<char> corner(areas.nodes.size(), 0); // by slave index
  if (mesh.planar.kind == mesh::PlanarKind::none)
    for (const mesh::Face& face : mesh.face_set(pair.slave))
      for (int a = 0; a < face.n_corners(); ++a)
        corner[static_cast<size_t>(areas.index_of(face[a]))] = 1;
  ContactRowBuilder rows;
  std::vector<std::pair<int32_t, double>> weights;
  for (size_t i = 0; i < slave_nodes.size(); ++i)
  {
    const int32_t s = slave_nodes[i];
    const std::optional<ClosestPoint>& closest = closest_points[i];
    if (!closest || !(closest->gap < out.search_distance) || !near_contact(*closest))
      continue;
    const mesh::Face& face = faces[closest->face];
    const Eigen::VectorXd shape = face_weights(face.kind, closest->xi);
    weights.resize(face.size());
    for (int a = 0; a < face.size(); ++a)
      weights[a] = {face[a], shape(a)};
    rows.add({s, closest->normal, closest->gap, areas.of(s), closest->face, closest->xi, closest->kind, 1, 0,
              corner[static_cast<size_t>(areas.index_of(s))]
                  ? 0.0
                  : face_area_estimate(geometries[closest->face], closest->xi)},
             weights);
  }
  rows.finish(n_dofs, out);
  return out;
}

la::Vector contact_forces(const ContactConstraints& constraints, const la::Vector& lambda_hat, int64_t n_global_dofs)
{
  FETICON_CHECK(lambda_hat.size() == constraints.n_rows(),
                "contact_forces: " << lambda_hat.size() << " multipliers for " << constraints.n_rows()
                                   << " contact rows");
  FETICON_CHECK(n_global_dofs == constraints.B.cols(),
                "contact_forces: n_global_dofs = " << n_global_dofs << " but the rows have " << constraints.B.cols()
                                                   << " columns");
  return -(constraints.B.transpose() * lambda_hat);
}

la::Vector slave_normal_forces(const ContactConstraints& constraints, const la::Vector& lambda_hat)
{
  FETICON_CHECK(lambda_hat.size() == constraints.n_rows(),
                "slave_normal_forces: " << lambda_hat.size() << " multipliers for " << constraints.n_rows()
                                        << " contact rows");
  la::Vector forces(lambda_hat.size());
  for (la::Index i = 0; i < lambda_hat.size(); ++i)
    forces(i) = lambda_hat(i) / constraints.row_norm[i];
  return forces;
}
} // namespace feticon::contact

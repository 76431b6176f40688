#include "contact/tie_rows.hpp"

#include "contact/contact_constraints.hpp"
#include "contact/face_geometry.hpp"
#include "contact/mortar_constraints.hpp"

#include "common/error.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <sstream>

namespace feticon::contact
{
namespace
{
/// Mean length of the corner-to-corner edges of `faces` (one per line face).
double mean_edge_length(const mesh::Mesh& mesh, const std::vector<mesh::Face>& faces)
{
  double sum = 0;
  int64_t count = 0;
  for (const mesh::Face& face : faces)
  {
    const int corners = mesh::face_corners(face.kind);
    const int edges = corners == 2 ? 1 : corners;
    for (int e = 0; e < edges; ++e)
    {
      sum += (mesh.nodes.row(face[(e + 1) % corners]) - mesh.nodes.row(face[e])).norm();
      ++count;
    }
  }
  return count > 0 ? sum / static_cast<double>(count) : 0.0;
}

using Weights = std::vector<std::pair<int32_t, double>>;

/// The master shape functions at row i's closest point.
Weights closest_point_weights(const ContactConstraints& closest, la::Index i,
                              const std::vector<mesh::Face>& master_faces)
{
  const mesh::Face& face = master_faces[closest.master_face[i]];
  const Eigen::VectorXd shape = face_weights(face.kind, closest.xi[i]);
  Weights out;
  for (int a = 0; a < face.size(); ++a)
    out.emplace_back(face[a], shape(a));
  return out;
}

/// One row per free component of `node`: u(node) - R sum w u(a) = 0 (R the identity but in a
/// cyclic symmetry tie).
void add_rows(fem::Problem& problem, int32_t node, const Weights& weights, const Eigen::Matrix3d& R,
              std::vector<char>& taken, TieReport& report)
{
  for (int c = 0; c < 3; ++c)
  {
    if (problem.eliminated[c])
      continue;
    const size_t dof = 3 * static_cast<size_t>(node) + c;
    if (taken[dof])
    {
      ++report.skipped_dofs;
      continue;
    }
    taken[dof] = 1;
    fem::LinearEquation row;
    row.terms.push_back({node, c, 1.0});
    for (const auto& [master, w] : weights)
      for (int d = 0; d < 3; ++d)
        if (R(c, d) != 0 && !problem.eliminated[d])
          row.terms.push_back({master, d, -w * R(c, d)});
    problem.tie_equations.push_back(std::move(row));
    ++report.rows;
  }
}

/// The turn by one sector of a cyclic symmetry tie that takes its master side onto its slave
/// side: 2 pi / sectors about the axis, in the sense the two sides' centroids give.
Eigen::Matrix3d sector_turn(const mesh::Mesh& mesh, const fem::Tie& tie, const ContactPair& pair)
{
  const fem::Tie::CyclicSymmetry& cyclic = *tie.cyclic;
  const Eigen::Vector3d axis = (cyclic.axis_b - cyclic.axis_a).normalized();
  const auto centroid = [&](const std::vector<int32_t>& nodes) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (const int32_t n : nodes)
      sum += mesh.nodes.row(n).transpose();
    Eigen::Vector3d radial = sum / static_cast<double>(nodes.size()) - cyclic.axis_a;
    return Eigen::Vector3d(radial - radial.dot(axis) * axis);
  };
  const Eigen::Vector3d slave = centroid(slave_nodes(mesh, pair)), master = centroid(mesh.face_set_nodes(tie.master));
  const double sense = axis.dot(master.cross(slave)) >= 0 ? 1.0 : -1.0;
  return Eigen::AngleAxisd(sense * 2 * std::numbers::pi / cyclic.sectors, axis).toRotationMatrix();
}

TieReport tie_surface(fem::Problem& problem, const fem::Tie& tie, std::vector<char>& taken)
{
  const ContactPair pair{tie.slave, tie.master, tie.slave_nodes};
  // A cyclic symmetry tie searches the master side from its slave nodes turned back by a sector
  // (on a copy of the mesh whose slave nodes are turned) and turns the master's displacement.
  const Eigen::Matrix3d R = tie.cyclic ? sector_turn(problem.mesh, tie, pair) : Eigen::Matrix3d::Identity();
  std::optional<mesh::Mesh> turned;
  if (tie.cyclic)
  {
    turned = problem.mesh;
    for (const int32_t n : slave_nodes(problem.mesh, pair))
      turned->nodes.row(n) =
          (tie.cyclic->axis_a + R.transpose() * (problem.mesh.nodes.row(n).transpose() - tie.cyclic->axis_a))
              .transpose();
  }
  mesh::Mesh& mesh = turned ? *turned : problem.mesh;
  const std::vector<mesh::Face>& master_faces = mesh.face_set(tie.master);
  TieReport report;
  report.name = tie.name;
  report.tolerance = tie.position_tolerance > 0 ? tie.position_tolerance
                                                : default_tie_tolerance * mean_edge_length(mesh, master_faces);
  FETICON_CHECK(report.tolerance > 0, "tie " << tie.name << ": master surface '" << tie.master << "' has no extent");
  report.slave_nodes = static_cast<int64_t>(slave_nodes(mesh, pair).size());

  ContactOptions options;
  options.formulation = ContactFormulation::node_to_segment;
  options.search_distance = std::nextafter(report.tolerance, std::numeric_limits<double>::infinity());
  const ContactConstraints closest = build_node_to_segment_constraints(mesh, {}, pair, options);
  std::vector<char> is_master(mesh.n_nodes(), 0);
  for (const int32_t node : mesh.face_set_nodes(tie.master))
    is_master[node] = 1;
  std::vector<la::Index> tied_rows;
  std::vector<int32_t> tied_nodes;
  for (la::Index i = 0; i < closest.n_rows(); ++i)
    if (!is_master[closest.slave_node[i]] && std::abs(closest.gap[i]) <= report.tolerance)
    {
      tied_rows.push_back(i);
      tied_nodes.push_back(closest.slave_node[i]);
    }
  report.tied_nodes = static_cast<int64_t>(tied_nodes.size());
  FETICON_CHECK(report.tied_nodes > 0,
                "tie " << tie.name << ": no node of slave surface '" << tie.slave
                       << "' lies within the position tolerance " << report.tolerance << " m of master surface '"
                       << tie.master << "'");
  if (tie.adjust)
    for (const la::Index i : tied_rows)
    {
      mesh.nodes.row(closest.slave_node[i]) -= closest.gap[i] * closest.normal[i].transpose();
      // Meshes meant to match are apart by round-off: those moves are not reported.
      report.moved_nodes += std::abs(closest.gap[i]) > 1e-9 * report.tolerance ? 1 : 0;
    }

  std::optional<MortarCoupling> coupling;
  if (tie.formulation == ContactFormulation::mortar && tie.slave_nodes.empty())
    coupling = compute_mortar_coupling(mesh, {}, pair, options.search_distance, {}, &tied_nodes);
  for (const la::Index i : tied_rows)
  {
    const int32_t node = closest.slave_node[i];
    std::optional<MortarRowWeights> mortar;
    if (coupling)
      mortar = mortar_row_weights(*coupling, coupling->slave.index_of(node), ContactOptions{}.mortar_min_overlap);
    if (coupling && !mortar)
      ++report.closest_point_nodes;
    add_rows(problem, node, mortar ? mortar->weights : closest_point_weights(closest, i, master_faces), R, taken,
             report);
  }
  return report;
}
} // namespace

std::vector<TieReport> tie_surfaces(fem::Problem& problem)
{
  problem.tie_equations.clear();
  problem.tie_of_equation.clear();
  if (problem.ties.empty())
    return {};
  // Slave DOFs that may not get a tie row (file comment): those every step's supports hold
  // (one that some step frees needs its tie row then), every DOF an equation names, then each
  // tie's own.
  std::vector<char> taken(3 * static_cast<size_t>(problem.mesh.n_nodes()), 0);
  std::vector<int> holding(taken.size(), 0);
  for (size_t k = 0; k < problem.steps.size(); ++k)
    for (const int64_t dof : problem.all_constrained_dofs(k).dofs)
      if (dof < 3 * int64_t{problem.mesh.n_nodes()} && // a held combination leaves the tie its row
          ++holding[dof] == static_cast<int>(problem.steps.size()))
        taken[dof] = 1;
  for (const fem::LinearEquation& equation : problem.equations)
    for (const auto& term : equation.terms)
      taken[3 * static_cast<size_t>(term.node) + term.component] = 1;
  std::vector<TieReport> out;
  for (const fem::Tie& tie : problem.ties)
  {
    out.push_back(tie_surface(problem, tie, taken));
    problem.tie_of_equation.resize(problem.tie_equations.size(), static_cast<int32_t>(out.size()) - 1);
  }
  return out;
}

std::string describe(const TieReport& r)
{
  std::ostringstream s;
  s.precision(3);
  s << "tie " << r.name << ": " << r.tied_nodes << " of " << r.slave_nodes << " slave nodes tied (position tolerance "
    << r.tolerance << " m";
  if (r.slave_nodes > r.tied_nodes)
    s << "; " << r.slave_nodes - r.tied_nodes << " beyond it or on the master surface";
  s << "), " << r.rows << " rows";
  if (r.moved_nodes > 0)
    s << ", " << r.moved_nodes << " nodes moved onto the master surface (ADJUST)";
  if (r.closest_point_nodes > 0)
    s << ", " << r.closest_point_nodes << " by their closest point (mortar overlap below "
      << ContactOptions{}.mortar_min_overlap << ")";
  if (r.skipped_dofs > 0)
    s << "; " << r.skipped_dofs << " slave DOFs left to supports, equations or earlier ties";
  return s.str();
}
} // namespace feticon::contact

#include "fem/coupling.hpp"

#include "common/error.hpp"
#include "fem/loads.hpp"

#include <algorithm>
#include <cmath>

namespace feticon::fem
{
namespace
{
/// Relative size below which a pivot of the rigid motion counts as zero: a direction the
/// coupled components do not see (collinear nodes, components left out). Far above round-off.
constexpr double rank_tolerance = 1e-8;

/// The coupled components of a kinematic coupling and their rigid motion, scaled: row i of
/// `motion` is [e_c', (r x e_c)' / length] for component c of node n (dofs[i] = 3 n + c,
/// r = X_n - X_ref), the generalized DOFs (t, length theta), so that the pivoting does not
/// depend on the unit of length.
struct RigidMotion
{
  std::vector<int64_t> dofs;
  Eigen::MatrixXd motion; ///< dofs x 6
  double length = 1;
  std::vector<int32_t> anchors;     ///< rows of `motion` that carry it, rank of them
  std::vector<int64_t> anchor_dofs; ///< their DOFs
  std::vector<char> is_anchor;      ///< per row
  Eigen::MatrixXd anchor_motion;    ///< rank x 6: those rows
};

std::vector<int32_t> unique_nodes(const mesh::Mesh& mesh, const Coupling& coupling)
{
  std::vector<int32_t> nodes = coupled_nodes(mesh, coupling);
  std::ranges::sort(nodes);
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  FETICON_CHECK(!nodes.empty(), coupling.name << ": it couples no node");
  return nodes;
}

/// The rows of `rigid` with the arms turned by `rotation`: [e_c', ((R r) x e_c)' / length].
Eigen::MatrixXd turned_motion(const mesh::Mesh& mesh, const Coupling& coupling, const RigidMotion& rigid,
                              const Eigen::Matrix3d& rotation)
{
  Eigen::MatrixXd out(std::ssize(rigid.dofs), 6);
  for (size_t i = 0; i < rigid.dofs.size(); ++i)
  {
    const int64_t dof = rigid.dofs[i];
    const int c = static_cast<int>(dof % 3);
    const Eigen::Vector3d arm = rotation * (mesh.nodes.row(dof / 3).transpose() - coupling.reference);
    out.row(static_cast<la::Index>(i)) << Eigen::RowVector3d::Unit(c),
        arm.cross(Eigen::Vector3d::Unit(c)).transpose() / rigid.length;
  }
  return out;
}

RigidMotion rigid_motion(const mesh::Mesh& mesh, const Coupling& coupling, const std::array<bool, 3>& eliminated)
{
  RigidMotion out;
  for (const int32_t n : unique_nodes(mesh, coupling))
  {
    out.length = std::max(out.length, (mesh.nodes.row(n).transpose() - coupling.reference).norm());
    for (int c = 0; c < 3; ++c)
      if (coupling.components[c] && !eliminated[c])
        out.dofs.push_back(3 * int64_t{n} + c);
  }
  FETICON_CHECK(!out.dofs.empty(), coupling.name << ": no component of its nodes is coupled");
  out.motion = turned_motion(mesh, coupling, out, Eigen::Matrix3d::Identity());
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(out.motion.transpose());
  qr.setThreshold(rank_tolerance);
  const la::Index rank = qr.rank();
  out.anchor_motion.resize(rank, 6);
  out.is_anchor.assign(out.dofs.size(), 0);
  for (la::Index k = 0; k < rank; ++k)
  {
    const int32_t a = static_cast<int32_t>(qr.colsPermutation().indices()(k));
    out.anchors.push_back(a);
    out.anchor_dofs.push_back(out.dofs[static_cast<size_t>(a)]);
    out.is_anchor[static_cast<size_t>(a)] = 1;
    out.anchor_motion.row(k) = out.motion.row(a);
  }
  return out;
}

/// exp of the spin w: Rodrigues' rotation by |w| about w.
Eigen::Matrix3d rotation_of(const Eigen::Vector3d& w)
{
  const double angle = w.norm();
  return angle == 0 ? Eigen::Matrix3d::Identity() : Eigen::AngleAxisd(angle, w / angle).toRotationMatrix();
}

/// Where the pose (t, R) puts component `dof`: (t + (R - I) r)_c, a displacement.
double posed(const mesh::Mesh& mesh, const Coupling& coupling, const Eigen::Vector3d& t, const Eigen::Matrix3d& R,
             int64_t dof)
{
  const Eigen::Vector3d arm = mesh.nodes.row(dof / 3).transpose() - coupling.reference;
  return (t + R * arm - arm)(dof % 3);
}

/// x with G_A' x = rhs, if rhs lies in the rows of G_A (else empty).
std::optional<Eigen::VectorXd> anchor_combination(const Eigen::ColPivHouseholderQR<Eigen::MatrixXd>& qr,
                                                  const Eigen::MatrixXd& anchor_motion, const Eigen::VectorXd& rhs)
{
  const Eigen::VectorXd x = qr.solve(rhs);
  if ((anchor_motion.transpose() * x - rhs).norm() > rank_tolerance * (1 + rhs.norm()))
    return std::nullopt;
  return x;
}

DofCombination combination(const std::vector<int64_t>& dofs, const Eigen::VectorXd& coefficients, double scale = 1)
{
  DofCombination out;
  const double largest = coefficients.cwiseAbs().maxCoeff();
  for (la::Index i = 0; i < coefficients.size(); ++i)
    if (std::abs(coefficients(i)) > 1e-14 * largest)
    {
      out.dofs.push_back(dofs[static_cast<size_t>(i)]);
      out.coefficients.push_back(coefficients(i) * scale);
    }
  return out;
}

/// One row u_s - alpha' u_A = 0 per coupled component but the anchors, alpha from `motion` (the
/// rows of `rigid`, turned or not) and its anchor rows `anchor_motion`.
std::vector<CouplingRow> slave_rows(const Coupling& coupling, const RigidMotion& rigid, const Eigen::MatrixXd& motion,
                                    const Eigen::MatrixXd& anchor_motion)
{
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(anchor_motion.transpose());
  std::vector<CouplingRow> out;
  for (size_t i = 0; i < rigid.dofs.size(); ++i)
  {
    if (rigid.is_anchor[i])
      continue;
    const std::optional<Eigen::VectorXd> alpha =
        anchor_combination(qr, anchor_motion, motion.row(static_cast<la::Index>(i)).transpose());
    FETICON_CHECK(alpha,
                  coupling.name << ": the rigid motion of node " << rigid.dofs[i] / 3
                                << " is not carried by the anchors (rank tolerance)");
    out.push_back({rigid.dofs[i], combination(rigid.anchor_dofs, *alpha)});
  }
  return out;
}

ReferenceDofs kinematic_reference_dofs(const mesh::Mesh& mesh, const Coupling& coupling,
                                       const std::array<bool, 3>& eliminated)
{
  const RigidMotion rigid = rigid_motion(mesh, coupling, eliminated);
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(rigid.anchor_motion.transpose());
  const Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> gram(rigid.motion.transpose() * rigid.motion);
  ReferenceDofs out;
  for (int d = 0; d < 6; ++d)
  {
    const std::optional<Eigen::VectorXd> beta =
        anchor_combination(qr, rigid.anchor_motion, Eigen::VectorXd(Eigen::VectorXd::Unit(6, d)));
    if (!beta)
      continue;
    // Generalized DOF d is length theta for a rotation: theta = q_d / length, and a moment M
    // does the work of a generalized force M / length.
    const double scale = d < 3 ? 1 : 1 / rigid.length;
    out.value[d] = combination(rigid.anchor_dofs, *beta, scale);
    out.unit_load[d] = combination(rigid.dofs, rigid.motion * gram.solve(Eigen::VectorXd::Unit(6, d)), scale);
    out.unit_motion[d] = combination(rigid.dofs, rigid.motion.col(d), 1 / scale);
  }
  return out;
}

/// Consistent nodal areas of the face set, normalized to sum 1, per node of `nodes`.
std::vector<double> area_weights(const mesh::Mesh& mesh, const Coupling& coupling, const std::vector<int32_t>& nodes)
{
  la::Vector f = la::Vector::Zero(3 * mesh.n_nodes());
  add_face_traction(mesh, mesh.face_set(coupling.faces), Eigen::Vector3d::UnitX(), f);
  std::vector<double> out;
  double total = 0;
  for (const int32_t n : nodes)
    total += out.emplace_back(f(3 * la::Index{n}));
  FETICON_CHECK(total > 0, coupling.name << ": the surface '" << coupling.faces << "' has no area");
  for (double& w : out)
    w /= total;
  return out;
}

ReferenceDofs distributing_reference_dofs(const mesh::Mesh& mesh, const Coupling& coupling,
                                          const std::array<bool, 3>& eliminated)
{
  const std::vector<int32_t> nodes = unique_nodes(mesh, coupling);
  const std::vector<double> w = area_weights(mesh, coupling, nodes);
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < nodes.size(); ++i)
    centroid += w[i] * mesh.nodes.row(nodes[i]).transpose();
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
  for (size_t i = 0; i < nodes.size(); ++i)
  {
    const Eigen::Vector3d r = mesh.nodes.row(nodes[i]).transpose() - centroid;
    inertia += w[i] * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
  }
  const Eigen::CompleteOrthogonalDecomposition<Eigen::Matrix3d> polar(inertia);
  // The nodal forces of a force `force` and a moment `moment` about the centroid.
  const auto spread = [&](const Eigen::Vector3d& force, const Eigen::Vector3d& moment) {
    const Eigen::Vector3d spin = polar.solve(moment);
    FETICON_CHECK((inertia * spin - moment).norm() <= rank_tolerance * (1 + moment.norm()),
                  coupling.name << ": its nodes lie on a line, so a moment about that line cannot be distributed");
    DofCombination out;
    for (size_t i = 0; i < nodes.size(); ++i)
    {
      const Eigen::Vector3d f = w[i] * (force + spin.cross(mesh.nodes.row(nodes[i]).transpose() - centroid));
      for (int c = 0; c < 3; ++c)
        if (!eliminated[c] && f(c) != 0)
        {
          out.dofs.push_back(3 * int64_t{nodes[i]} + c);
          out.coefficients.push_back(f(c));
        }
    }
    return out;
  };
  ReferenceDofs out;
  for (int d = 0; d < 3; ++d)
  {
    const Eigen::Vector3d e = Eigen::Vector3d::Unit(d);
    out.unit_load[d] = spread(e, (coupling.reference - centroid).cross(e));
    if (coupling.moments[d])
      out.unit_load[3 + d] = spread(Eigen::Vector3d::Zero(), e);
  }
  return out;
}

ReferenceDofs mean_reference_dofs(const mesh::Mesh& mesh, const Coupling& coupling,
                                  const std::array<bool, 3>& eliminated)
{
  const std::vector<int32_t> nodes = coupled_nodes(mesh, coupling);
  FETICON_CHECK(coupling.weights.size() == nodes.size(),
                coupling.name << ": " << coupling.weights.size() << " weights for " << nodes.size() << " nodes");
  double total = 0;
  for (const double w : coupling.weights)
  {
    FETICON_CHECK(std::isfinite(w), coupling.name << ": a weight is not finite");
    total += w;
  }
  FETICON_CHECK(total != 0, coupling.name << ": its weights sum to zero");
  ReferenceDofs out;
  for (int d = 0; d < 3; ++d)
  {
    if (eliminated[d])
      continue;
    DofCombination mean, motion;
    for (size_t i = 0; i < nodes.size(); ++i)
    {
      mean.dofs.push_back(3 * int64_t{nodes[i]} + d);
      mean.coefficients.push_back(coupling.weights[i] / total);
      motion.dofs.push_back(mean.dofs.back());
      motion.coefficients.push_back(1);
    }
    out.value[d] = mean;
    out.unit_load[d] = mean;
    out.unit_motion[d] = motion;
  }
  return out;
}

/// A pretension section's node pairs, unit normal n and the tangents t, d (n x t) in the plane
/// of the model's free components, as CalculiX builds them (pretensionsections.f).
struct PretensionSection
{
  std::vector<int32_t> old_nodes, new_nodes;
  std::vector<Eigen::Vector3d> directions; ///< n, then the tangents (one in 2D)
  std::vector<int> slave_components;       ///< per direction: j_n, j_t (, j_d), distinct
};

PretensionSection pretension_section(const mesh::Mesh& mesh, const Coupling& coupling,
                                     const std::array<bool, 3>& eliminated)
{
  PretensionSection out{mesh.node_set(coupling.nodes), mesh.node_set(coupling.partners), {}, {}};
  FETICON_CHECK(!out.old_nodes.empty() && out.old_nodes.size() == out.new_nodes.size(),
                coupling.name << ": " << out.old_nodes.size() << " nodes and " << out.new_nodes.size()
                              << " partners; a pretension section needs one partner per node");
  Eigen::Vector3d n = coupling.normal;
  if (n.isZero())
  {
    // The faces' outward normals, area-weighted: a unit pressure's nodal forces are -n dA.
    la::Vector f = la::Vector::Zero(3 * la::Index{mesh.n_nodes()});
    add_face_pressure(mesh, mesh.face_set(coupling.faces), 1.0, f);
    for (int32_t a = 0; a < mesh.n_nodes(); ++a)
      n -= f.segment<3>(3 * la::Index{a});
  }
  for (int c = 0; c < 3; ++c)
    if (eliminated[c])
      n(c) = 0;
  FETICON_CHECK(n.norm() > 0, coupling.name << ": its normal is zero (in the model's plane)");
  n.normalize();
  // A tangent from e_x, or from e_y where n is near x (CalculiX's choice).
  Eigen::Vector3d t = std::abs(n.x()) < 0.95 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  t = (t - n.dot(t) * n).normalized();
  out.directions = {n, t};
  if (std::ranges::none_of(eliminated, [](bool e) { return e; }))
    out.directions.push_back(n.cross(t));
  // The slave components: the assignment of distinct components to the directions with the
  // largest product of coefficients (every one nonzero).
  std::array<int, 3> order{0, 1, 2};
  double best = -1;
  do
  {
    double product = 1;
    for (size_t k = 0; k < out.directions.size(); ++k)
      product *= eliminated[order[k]] ? 0.0 : std::abs(out.directions[k](order[k]));
    if (product > best)
    {
      best = product;
      out.slave_components.assign(order.begin(), order.begin() + std::ssize(out.directions));
    }
  } while (std::next_permutation(order.begin(), order.end()));
  return out;
}

/// v . (u_new - u_old) of one pair, as a combination (free components only).
DofCombination pair_gap(int32_t old_node, int32_t new_node, const Eigen::Vector3d& v,
                        const std::array<bool, 3>& eliminated, double scale = 1)
{
  DofCombination out;
  for (const auto& [node, sign] : {std::pair{new_node, 1.0}, std::pair{old_node, -1.0}})
    for (int c = 0; c < 3; ++c)
      if (!eliminated[c] && v(c) != 0)
      {
        out.dofs.push_back(3 * int64_t{node} + c);
        out.coefficients.push_back(sign * scale * v(c));
      }
  return out;
}

/// The rows of a pretension section: per pair its tangential rows, and for every pair but the
/// first its normal gap equal to the first's; each solved for its slave component.
std::vector<CouplingRow> pretension_rows(const mesh::Mesh& mesh, const Coupling& coupling,
                                         const std::array<bool, 3>& eliminated)
{
  const PretensionSection section = pretension_section(mesh, coupling, eliminated);
  std::vector<CouplingRow> out;
  for (size_t i = 0; i < section.old_nodes.size(); ++i)
    for (size_t k = i == 0 ? 1 : 0; k < section.directions.size(); ++k)
    {
      const Eigen::Vector3d& v = section.directions[k];
      const int j = section.slave_components[k];
      // v . (u_new - u_old) [- n . (u_new_0 - u_old_0)] = 0, divided by v_j: u_s - alpha' u_A = 0.
      DofCombination row = pair_gap(section.old_nodes[i], section.new_nodes[i], v, eliminated, -1 / v(j));
      if (k == 0)
      {
        const DofCombination first = pair_gap(section.old_nodes[0], section.new_nodes[0], v, eliminated, 1 / v(j));
        row.dofs.insert(row.dofs.end(), first.dofs.begin(), first.dofs.end());
        row.coefficients.insert(row.coefficients.end(), first.coefficients.begin(), first.coefficients.end());
      }
      const int64_t slave = 3 * int64_t{section.new_nodes[i]} + j;
      CouplingRow& r = out.emplace_back();
      r.slave = slave;
      for (size_t a = 0; a < row.dofs.size(); ++a)
        if (row.dofs[a] != slave)
        {
          r.anchors.dofs.push_back(row.dofs[a]);
          r.anchors.coefficients.push_back(row.coefficients[a]);
        }
    }
  return out;
}

ReferenceDofs pretension_reference_dofs(const mesh::Mesh& mesh, const Coupling& coupling,
                                        const std::array<bool, 3>& eliminated)
{
  const PretensionSection section = pretension_section(mesh, coupling, eliminated);
  const Eigen::Vector3d& n = section.directions.front();
  const std::vector<double> w = area_weights(mesh, coupling, section.new_nodes);
  ReferenceDofs out;
  out.value[0] = pair_gap(section.old_nodes[0], section.new_nodes[0], n, eliminated);
  for (size_t i = 0; i < section.old_nodes.size(); ++i)
  {
    const DofCombination load = pair_gap(section.old_nodes[i], section.new_nodes[i], n, eliminated, w[i]);
    out.unit_load[0].dofs.insert(out.unit_load[0].dofs.end(), load.dofs.begin(), load.dofs.end());
    out.unit_load[0].coefficients.insert(out.unit_load[0].coefficients.end(), load.coefficients.begin(),
                                         load.coefficients.end());
    for (int c = 0; c < 3; ++c)
      if (!eliminated[c] && n(c) != 0)
      {
        out.unit_motion[0].dofs.push_back(3 * int64_t{section.new_nodes[i]} + c);
        out.unit_motion[0].coefficients.push_back(n(c));
      }
  }
  return out;
}
} // namespace

std::vector<int32_t> coupled_nodes(const mesh::Mesh& mesh, const Coupling& coupling)
{
  return coupling.nodes.empty() ? mesh.face_set_nodes(coupling.faces) : mesh.node_set(coupling.nodes);
}

double DofCombination::of(const la::Vector& u) const
{
  double out = 0;
  for (size_t k = 0; k < dofs.size(); ++k)
    out += coefficients[k] * u(dofs[k]);
  return out;
}

ReferenceDofs reference_dofs(const mesh::Mesh& mesh, const Coupling& coupling, const std::array<bool, 3>& eliminated)
{
  switch (coupling.kind)
  {
  case CouplingKind::kinematic:
    return kinematic_reference_dofs(mesh, coupling, eliminated);
  case CouplingKind::distributing:
    return distributing_reference_dofs(mesh, coupling, eliminated);
  case CouplingKind::mean:
    return mean_reference_dofs(mesh, coupling, eliminated);
  case CouplingKind::pretension:
    return pretension_reference_dofs(mesh, coupling, eliminated);
  }
  return {};
}

KinematicRows kinematic_rows(const mesh::Mesh& mesh, const Coupling& coupling, const std::array<bool, 3>& eliminated)
{
  if (coupling.kind == CouplingKind::pretension)
    return {pretension_rows(mesh, coupling, eliminated), 1};
  if (coupling.kind != CouplingKind::kinematic)
    return {};
  const RigidMotion rigid = rigid_motion(mesh, coupling, eliminated);
  return {slave_rows(coupling, rigid, rigid.motion, rigid.anchor_motion), static_cast<int>(rigid.anchors.size())};
}

bool has_finite_kinematics(const mesh::Mesh& mesh, const Coupling& coupling, const std::array<bool, 3>& eliminated)
{
  return coupling.kind == CouplingKind::kinematic && rigid_motion(mesh, coupling, eliminated).anchors.size() == 6;
}

FiniteKinematics finite_kinematics(const mesh::Mesh& mesh, const Coupling& coupling,
                                   const std::array<bool, 3>& eliminated, const la::Vector& u)
{
  const RigidMotion rigid = rigid_motion(mesh, coupling, eliminated);
  FETICON_CHECK(rigid.anchors.size() == 6,
                coupling.name << ": finite rotations need a rigid motion of rank 6, it has " << rigid.anchors.size());
  const std::vector<int64_t>& anchor_dofs = rigid.anchor_dofs;
  FiniteKinematics out;
  // The pose that puts the six anchor components where u has them (Newton; quadratic from the
  // identity for any rotation below a half turn).
  Eigen::Matrix<double, 6, 6> jacobian;
  Eigen::Matrix<double, 6, 1> misfit;
  double scale = rigid.length;
  for (const int64_t dof : anchor_dofs)
    scale = std::max(scale, std::abs(u(dof)));
  for (int iteration = 0;; ++iteration)
  {
    const Eigen::MatrixXd turned = turned_motion(mesh, coupling, rigid, out.rotation);
    for (int k = 0; k < 6; ++k)
    {
      misfit(k) = u(anchor_dofs[k]) - posed(mesh, coupling, out.translation, out.rotation, anchor_dofs[k]);
      jacobian.row(k) = turned.row(rigid.anchors[k]);
    }
    if (misfit.norm() <= 1e-14 * scale)
      break;
    FETICON_CHECK(iteration < 50 && misfit.allFinite(),
                  coupling.name << ": the rigid pose of its anchors does not converge (misfit " << misfit.norm()
                                << " m)");
    const Eigen::Matrix<double, 6, 1> step = jacobian.fullPivLu().solve(misfit);
    out.translation += step.head<3>();
    out.rotation = rotation_of(step.tail<3>() / rigid.length) * out.rotation;
  }
  const Eigen::MatrixXd turned = turned_motion(mesh, coupling, rigid, out.rotation);
  Eigen::MatrixXd anchor_motion(6, 6);
  for (int k = 0; k < 6; ++k)
    anchor_motion.row(k) = turned.row(rigid.anchors[k]);
  out.rows = {slave_rows(coupling, rigid, turned, anchor_motion), 6};
  for (CouplingRow& row : out.rows.rows)
  {
    const double departure = u(row.slave) - posed(mesh, coupling, out.translation, out.rotation, row.slave);
    row.rhs = u(row.slave) - row.anchors.of(u) - departure;
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(anchor_motion.transpose());
  const Eigen::AngleAxisd turn(out.rotation);
  const Eigen::Vector3d rotation_vector = turn.angle() * turn.axis();
  for (int d = 0; d < 6; ++d)
  {
    const Eigen::VectorXd beta = qr.solve(Eigen::VectorXd(Eigen::VectorXd::Unit(6, d)));
    out.value[d] = combination(anchor_dofs, beta, d < 3 ? 1 : 1 / rigid.length);
    out.value[d].offset = out.value[d].of(u) - (d < 3 ? out.translation(d) : rotation_vector(d - 3));
  }
  return out;
}

ReferenceResult reference_result(const ReferenceDofs& dofs, const la::Vector& u, const la::Vector& rho)
{
  ReferenceResult out;
  for (int d = 0; d < 6; ++d)
  {
    out.value[d] = dofs.value[d].of(u);
    out.reaction[d] = dofs.unit_motion[d].of(rho);
  }
  return out;
}

ReferenceResult finite_reference_result(const mesh::Mesh& mesh, const Coupling& coupling,
                                        const std::array<bool, 3>& eliminated, const la::Vector& u,
                                        const la::Vector& rho)
{
  const FiniteKinematics pose = finite_kinematics(mesh, coupling, eliminated, u);
  const Eigen::AngleAxisd turn(pose.rotation);
  ReferenceResult out;
  for (int d = 0; d < 3; ++d)
  {
    out.value[d] = pose.translation(d);
    out.value[3 + d] = turn.angle() * turn.axis()(d);
  }
  for (const int64_t dof : rigid_motion(mesh, coupling, eliminated).dofs)
  {
    const int c = static_cast<int>(dof % 3);
    const Eigen::Vector3d arm = pose.rotation * (mesh.nodes.row(dof / 3).transpose() - coupling.reference);
    out.reaction[c] += rho(dof);
    const Eigen::Vector3d moment = arm.cross(rho(dof) * Eigen::Vector3d::Unit(c));
    for (int d = 0; d < 3; ++d)
      out.reaction[3 + d] += moment(d);
  }
  return out;
}

std::string describe_reference_dof(int dof)
{
  static constexpr const char* names[6] = {"translation x",    "translation y",    "translation z",
                                           "rotation about x", "rotation about y", "rotation about z"};
  return "DOF " + std::to_string(dof + 1) + " (" + names[dof] + ")";
}
} // namespace feticon::fem

#pragma once
/// @file Reference nodes and the surfaces they drive (CalculiX / Abaqus *RIGID BODY, *COUPLING with
/// *KINEMATIC or *DISTRIBUTING, *DISTRIBUTING COUPLING): a point with six DOFs, translations t
/// and rotations theta about it, that carries loads and supports for a set of mesh nodes.
///
/// The reference node is no mesh node and no unknown of the solvers: its DOFs are functions of
/// the coupled nodes' displacements (docs/contact.md, "Couplings"), so that FETI needs no
/// subdomain for it and every solver takes a coupling as rows, held combinations and forces:
/// - kinematic (*RIGID BODY, *KINEMATIC): the coupled nodes' components c (all three, or those
///   *KINEMATIC lists) follow the rigid motion u_i = t + theta x (X_i - X_ref), linearized
///   (small rotations; large displacements turn a coupling of rank 6 by finite rotations,
///   finite_kinematics, as CalculiX's rigid-body MPCs do under NLGEOM).
///   The motion G q (q = (t, theta)) of the coupled components has rank k <= 6: k anchor
///   components A (a column-pivoted QR of G' picks them, well spread) carry it, and every other
///   coupled component s gets the row u_s - alpha_s' u_A = 0, alpha_s solving G_A' alpha_s = G_s',
///   its own DOF with coefficient 1 as a tie row has (decomposition/constraint_rows.hpp scales
///   such rows one by one). A reference DOF d that G drives (e_d in the rows of G) has the value
///   beta_d' u_A (G_A' beta_d = e_d); a support on it holds that combination, a load P on it is
///   the least-norm nodal forces f = G (G' G)^+ e_d P, which do the same work on every rigid
///   motion (any such f gives the same answer: the rows take the difference).
/// - distributing (*COUPLING with *DISTRIBUTING): loads only, spread over the coupled nodes with
///   the consistent nodal areas w_i of the surface (sum 1) as CalculiX's couplings.f does:
///   f_i = w_i F + w_i (J^-1 M_c) x r_i, r_i = X_i - X_c from the weighted centroid X_c,
///   J = sum w_i (|r_i|^2 I - r_i r_i'), M_c = M + (X_ref - X_c) x F; moments only on the
///   rotational DOFs listed. No rows: the reference node does not move (CalculiX: "the
///   displacements at the reference node remain zero"), and a support on it does nothing.
/// - mean (*DISTRIBUTING COUPLING, a DCOUP3D element's node): t = sum w_i u_i / sum w_i with the
///   deck's weights, per translational component: a support holds that combination, a force F
///   on it is f_i = w_i F / sum w.
/// - pretension (*PRE-TENSION SECTION): a cut through a bolt, its nodes doubled (the cells whose
///   faces make the section take the new nodes, `partners`; the rest keep `nodes`). As
///   CalculiX's pretensionsections.f: every pair moves apart by the same normal gap and not at all
///   tangentially, (u_new - u_old) . t = 0 and (u_new_i - u_old_i) . n = (u_new_0 - u_old_0) . n,
///   and reference DOF 1 is that gap q = (u_new_0 - u_old_0) . n, n pointing away from the cells
///   that took the new nodes: q > 0 (the two sides overlap by q) or a force F > 0 on it puts the
///   bolt in tension. A force F is the nodal forces +-w_i F n on the pairs (w_i the section's
///   consistent nodal areas, sum 1); its reaction is the sum of the new nodes' residual forces
///   along n. Each row has its own slave: component j_n, j_t, j_d of a new node, distinct with
///   nonzero coefficients (the pair 0's j_n carries q).
///
/// The reaction of a reference DOF (printed RF of the reference node) is the work of the coupled
/// nodes' residual forces rho = f_int - f_ext on its unit motion: sum rho_i for a translation,
/// sum r_i x rho_i for a rotation (the rows' own forces do no work on a rigid motion).

#include "la/types.hpp"
#include "mesh/mesh.hpp"

#include <Eigen/Dense>

#include <array>
#include <string>
#include <vector>

namespace feticon::fem
{
enum class CouplingKind
{
  kinematic,
  distributing,
  mean,
  pretension
};

struct Coupling
{
  std::string name; ///< for messages: "*RIGID BODY at line 31", "coupling C1"
  CouplingKind kind = CouplingKind::kinematic;
  Eigen::Vector3d reference = Eigen::Vector3d::Zero(); ///< position of the reference node (m)
  /// node set of the coupled nodes; empty: the nodes of `faces`
  std::string nodes;
  /// distributing: the face set whose consistent nodal areas weigh its nodes (a kinematic
  /// coupling may name its nodes by a face set too)
  std::string faces = {};
  /// kinematic: the components of the coupled nodes that follow the rigid motion
  std::array<bool, 3> components{true, true, true};
  /// distributing: whether moments about x, y, z are distributed (DOFs 4 to 6 listed)
  std::array<bool, 3> moments{false, false, false};
  /// mean: the weight of each node of `nodes`, in the set's order
  std::vector<double> weights = {};
  /// pretension: the node set of the new nodes, the partners of `nodes` in the same order, and
  /// the section's normal (zero: the mean outward normal of `faces`, whose cells took `partners`)
  std::string partners = {};
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
};

/// The coupled nodes: `nodes`, or the nodes of `faces`.
std::vector<int32_t> coupled_nodes(const mesh::Mesh& mesh, const Coupling& coupling);

/// A support or a load on DOF `dof` of coupling `coupling`'s reference node: 0-2 translations
/// (m, N), 3-5 rotations about x, y, z (rad, N m).
struct ReferenceValue
{
  int32_t coupling;
  int dof;
  double value;
  std::string amplitude = {};
};

/// A combination sum_k coefficients[k] u(dofs[k]) of global DOFs (3 node + component).
struct DofCombination
{
  std::vector<int64_t> dofs;
  std::vector<double> coefficients;
  /// Held as sum a_k u_k = value + offset: a combination linearized at a displacement (finite
  /// rotations, finite_kinematics) moves its target by what the linearization misses there.
  double offset = 0;
  bool empty() const { return dofs.empty(); }
  double of(const la::Vector& u) const;
};

/// What the solvers need of one coupling's six reference DOFs (file comment).
struct ReferenceDofs
{
  /// Per DOF: its value from the coupled nodes' displacements; empty if the coupling does not
  /// drive it (a support on it then does nothing).
  std::array<DofCombination, 6> value;
  /// Per DOF: the nodal forces of a unit load on it; empty if the coupling cannot carry one.
  std::array<DofCombination, 6> unit_load;
  /// Per DOF: the coupled nodes' motion per unit value (its reaction is rho . motion); empty
  /// where `value` is.
  std::array<DofCombination, 6> unit_motion;
};

/// One row u_s - sum_a alpha_a u_a = 0 per coupled component besides the anchors (kinematic).
struct CouplingRow
{
  int64_t slave;
  DofCombination anchors; ///< the alphas, on the anchor DOFs
  double rhs = 0;         ///< u_s - alpha' u_A = rhs (0 but linearized at a displacement)
};

/// Reference DOFs and rows of `coupling` on `mesh` (reference configuration).
/// @param eliminated components fixed to zero everywhere (2D): never coupled
/// @throws feticon::Error naming the coupling if its node set is empty or unknown, a weight is
///         not finite, or the weights sum to zero
ReferenceDofs reference_dofs(const mesh::Mesh& mesh, const Coupling& coupling, const std::array<bool, 3>& eliminated);
/// The rows of a kinematic or pretension coupling (none for the other kinds) and the rank of its
/// rigid motion (a pretension: 1, its gap).
struct KinematicRows
{
  std::vector<CouplingRow> rows;
  int rank = 0;
};
KinematicRows kinematic_rows(const mesh::Mesh& mesh, const Coupling& coupling, const std::array<bool, 3>& eliminated);

/// Finite rotations (large displacements): the pose of a kinematic coupling of rank 6 at
/// displacement u, x_i = X_ref + t + R (X_i - X_ref), fitted to its anchors exactly (Newton from
/// the identity, spin updates R <- exp(dw) R), and at that pose its rows and reference DOFs
/// linearized: the motion's rows turned, [e_c', ((R r_i) x e_c)'], alpha from them, and each
/// row's rhs u_s - alpha' u_A - g_s (g_s the slave's departure from the pose), so that the row
/// holds the finite rigidity once the iteration is done; a reference DOF's combination the
/// increment of t or of the spin, its offset what the increment misses of t or of the rotation
/// vector log R. The same slaves and anchors as kinematic_rows (their order too).
struct FiniteKinematics
{
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  KinematicRows rows;
  std::array<DofCombination, 6> value;
};
/// @throws feticon::Error naming the coupling if its rigid motion has rank below 6 (finite
///         rotations need all six) or the anchors' fit does not converge
FiniteKinematics finite_kinematics(const mesh::Mesh& mesh, const Coupling& coupling,
                                   const std::array<bool, 3>& eliminated, const la::Vector& u);
/// Whether finite_kinematics applies: kinematic, rank 6.
bool has_finite_kinematics(const mesh::Mesh& mesh, const Coupling& coupling, const std::array<bool, 3>& eliminated);

/// A reference node's six values and reactions at displacement u (3 per mesh node) with nodal
/// forces rho (the forces the coupled nodes receive beyond their elements': f_int - f_ext, or
/// CalculiX's RF, which adds the applied loads): value d from ReferenceDofs::value (0 where it is
/// empty, as CalculiX leaves a *DISTRIBUTING reference node), reaction d = unit_motion . rho.
struct ReferenceResult
{
  std::array<double, 6> value{};
  std::array<double, 6> reaction{};
};
ReferenceResult reference_result(const ReferenceDofs& dofs, const la::Vector& u, const la::Vector& rho);

/// reference_result at finite rotations (has_finite_kinematics, large displacements): the pose's
/// t and rotation vector (log R), the reactions on the turned arms (moments about the displaced
/// reference point).
ReferenceResult finite_reference_result(const mesh::Mesh& mesh, const Coupling& coupling,
                                        const std::array<bool, 3>& eliminated, const la::Vector& u,
                                        const la::Vector& rho);

/// "DOF 4 (rotation about x)" for messages, dof 0-based.
std::string describe_reference_dof(int dof);
} // namespace feticon::fem

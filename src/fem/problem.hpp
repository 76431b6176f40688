#pragma once
/// @file A contact problem as the solvers see it: mesh, materials, supports, loads, pairs.

#include "fem/amplitude.hpp"
#include "fem/contact_interaction.hpp"
#include "fem/material.hpp"
#include "fem/step.hpp"
#include "la/types.hpp"
#include "mesh/mesh.hpp"

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace feticon::fem
{
/// Linear multi-point constraint sum_k a_k u(node_k, component_k) = 0 (deck *EQUATION):
/// FETI takes it as an equality row beside the gluing rows.
struct LinearEquation
{
  struct Term
  {
    int32_t node;
    int component; ///< 0, 1, 2
    double coefficient;
  };
  std::vector<Term> terms;
  /// sum_k a_k u_k = rhs: 0 but for a coupling's row linearized at a displacement (finite
  /// rotations, contact/coupling_rows.hpp)
  double rhs = 0;
};

/// Slave and master face sets of one contact pair (node-to-segment: slave nodes against
/// master faces) and the interaction between them. A body may be slave in one pair and
/// master in another; the solver builds every pair's rows and keys them by (pair, slave node).
struct ContactPairNames
{
  std::string slave;
  std::string master;
  /// If not empty, a node set: only these nodes of the slave faces carry contact rows (a
  /// deck's node-based slave surface, whose faces give the nodes' tributary areas).
  /// Node-to-segment only: mortar integrates whole slave faces.
  std::string slave_nodes = {};
  ContactInteraction interaction = {};
  /// ADJUST (CalculiX, Abaqus): before the first increment the slave nodes whose gap is at most
  /// this (m; penetrating ones included) are moved onto the master surface
  /// (contact::adjust_slave_nodes). 0: the mesh as it is.
  double adjust = 0;
  /// ADJUST by node set: these slave nodes are moved onto the master surface. Empty: none.
  std::string adjust_nodes = {};
};

/// A tie (deck *TIE, or a contact pair whose law is PRESSURE-OVERCLOSURE=TIED; problem file
/// `ties:`): every slave node within the position tolerance of the master surface moves with
/// the master surface where it lies, u_s = sum_a w_a u_a in each component
/// (contact/tie_rows.hpp builds the rows).
struct Tie
{
  std::string name;
  std::string slave;  ///< face set
  std::string master; ///< face set
  /// If not empty, a node set: only these nodes of the slave faces are tied (a deck's
  /// node-based slave surface); their rows are node-to-segment.
  std::string slave_nodes = {};
  /// Slave nodes farther than this from the master surface stay untied (m); 0: 2.5 % of the
  /// master faces' mean edge length (CalculiX's rule is 2.5 % of a typical element size).
  double position_tolerance = 0;
  /// Tied slave nodes moved onto the master surface first (CalculiX's default, ADJUST=YES).
  bool adjust = true;
  /// mortar: w_a = M_ja / D_j (the dual mortar weights, exact for a constant stress across
  /// non-matching meshes); node_to_segment: w_a = N_a at the closest point (CalculiX's tie).
  ContactFormulation formulation = ContactFormulation::mortar;
  /// A cyclic symmetry tie (deck *TIE, CYCLIC SYMMETRY with its *CYCLIC SYMMETRY MODEL): the
  /// model is one of `sectors` equal sectors about the axis through a and b, the slave (dependent)
  /// side the master (independent) side turned by one sector, and the static answer the same in
  /// every sector: u_s = R sum_a w_a u_a, R that turn, the weights at the slave node turned back
  /// onto the master side (node to segment). Unset: an ordinary tie.
  struct CyclicSymmetry
  {
    Eigen::Vector3d axis_a = Eigen::Vector3d::Zero(), axis_b = Eigen::Vector3d::UnitZ();
    double sectors = 0;
  };
  std::optional<CyclicSymmetry> cyclic = {};
};

struct Problem
{
  std::string name;
  mesh::Mesh mesh;
  bool mesh_from_cache = false;    ///< the mesh came from the mesh cache (mesh/mesh_cache.hpp)
  std::vector<Material> materials; ///< one per body
  std::vector<LinearEquation> equations;
  /// The history, one record a step (fem/step.hpp); at least one.
  std::vector<Step> steps = std::vector<Step>(1);
  std::map<std::string, Amplitude> amplitudes; ///< by the name loads and supports give
  /// T_0 per mesh node (deck *INITIAL CONDITIONS, TYPE=TEMPERATURE): the temperature of the
  /// unstrained state, from which the thermal strain counts. Empty: 0 everywhere.
  std::vector<double> initial_temperatures;
  /// Any number of pairs, none included (a model held by supports, glued or tied only).
  std::vector<ContactPairNames> contacts;
  std::vector<Tie> ties;
  /// The ties' rows, made from `ties` and the mesh before a solve (contact::tie_surfaces): one
  /// per tied slave DOF, its first term the slave DOF with coefficient 1, the only row where
  /// that DOF comes first. A block of its own beside `equations`: independent by construction,
  /// so FETI scales them row by row instead of orthonormalizing them.
  std::vector<LinearEquation> tie_equations;
  std::vector<int32_t> tie_of_equation; ///< the tie (index into ties) of each tie equation
  /// Local coordinate systems of nodes (deck *TRANSFORM): their supports act along the local
  /// axes (fem/node_frames.hpp; their forces are given in global components already).
  NodeFrames frames;
  /// Reference nodes and the nodes they drive (fem/coupling.hpp); their kinematic rows are
  /// among `tie_equations` (contact::tie_surfaces makes them, after the ties').
  std::vector<Coupling> couplings;
  /// Components fixed to zero on every node and eliminated (plane strain: {0,0,1}; every 2D
  /// model, mesh::Planar).
  std::array<bool, 3> eliminated{false, false, false};

  /// Consistent nodal forces (3 per node) of the loads of step `step` (0-based) whose
  /// amplitude is `amplitude` (empty: those without one), at their full values; the loads on
  /// reference nodes as their nodal forces unless `reference_loads` is false (a deck writes
  /// them on the reference node).
  la::Vector external_force(size_t step = 0, const std::string& amplitude = {}, bool reference_loads = true) const;
  /// The DOFs step `step` prescribes, with the eliminated components, and the values of the
  /// supports whose amplitude is `amplitude` (0 for the others).
  ConstrainedDofs all_constrained_dofs(size_t step = 0, const std::string& amplitude = {}) const;
  /// The tie equations of the ties in force in step `step` (0-based; Step::removed_ties).
  std::vector<LinearEquation> tie_equations_in_force(size_t step) const;
  /// `equations` then `tie_equations`: what the direct solves eliminate.
  std::vector<LinearEquation> all_equations() const;
  /// The held DOF of reference DOF `dof` (0-5) of coupling `coupling`: past the global DOFs and
  /// the frames' local ones, 3 N + 3 K + 6 coupling + dof.
  int64_t reference_dof(int32_t coupling, int dof) const;
  /// What each coupling's reference DOFs are (fem/coupling.hpp), in the order of `couplings`.
  std::vector<ReferenceDofs> reference_dofs() const;
  /// The combination of mesh DOFs each held DOF past the global ones holds, index dof - 3 N: a
  /// frame's local axes (3 per frame node), then the couplings' reference DOFs (6 each; empty
  /// where a coupling does not drive one).
  std::vector<DofCombination> held_combinations() const;
  /// u (3 per mesh node) followed by the values of held_combinations() (fem::LoadHistory's
  /// start values).
  la::Vector extended(const la::Vector& u) const;
  /// Some step gives temperatures (the thermal strain then enters the elements).
  bool has_temperatures() const;
  /// True if some kinematic coupling has a rigid motion of rank 6, which large displacements turn
  /// by finite rotations (fem::finite_kinematics).
  bool has_finite_couplings() const;
  /// True if some body's material is plastic (Material::is_plastic).
  bool has_plastic_body() const;
  /// True if some body is plastic or hyperelastic: its tangent drifts away from K_0.
  bool has_inelastic_or_hyperelastic_body() const;
  /// Checks materials, set names and sizes; throws feticon::Error naming what is wrong.
  void validate() const;

private:
  void validate_step(size_t step) const;
  /// 2D cells in a planar model only, u_z eliminated, nodes at z = 0 (and x >= 0 in axisymmetry).
  void validate_planar() const;
  /// One orthonormal right-handed frame per listed node; in 2D, rotations about z only.
  void validate_frames() const;
  /// Coupled node sets exist; supports and loads name couplings and DOFs they have.
  void validate_couplings() const;
};
} // namespace feticon::fem

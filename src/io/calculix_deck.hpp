#pragma once
/// @file The model of a fem::Problem as a CalculiX (Abaqus-format) input deck, so that the peer
/// code solves exactly the mesh, materials, supports, loads and contact pairs feticon solves
/// (bench/calculix.sh measures both on it).
///
/// Translation (CalculiX 2.20 keywords, SI units as in feticon):
///  - nodes and cells as *NODE and *ELEMENT blocks of C3D8, C3D4, C3D10, C3D20 and C3D6 (the
///    cell types' local order is CalculiX's); one *ELSET, *MATERIAL (*ELASTIC) and *SOLID
///    SECTION per body;
///  - Dirichlet conditions as *BOUNDARY on node sets, eliminated components (plane strain)
///    as *BOUNDARY on every node; nonzero values are ramped over the step like feticon's
///    u_D(t);
///  - tractions as their consistent nodal forces (fem::Problem::external_force) in *CLOAD:
///    feticon's tractions are dead loads per reference area, and *CLOAD keeps its direction
///    under NLGEOM, whereas *DLOAD pressure would follow the deformed face;
///  - each contact pair as a surface-to-surface *CONTACT PAIR (node-to-surface where its rows
///    are node-to-segment; slave and master as in feticon) with a frictionless linear pressure-overclosure *SURFACE INTERACTION of slope
///    K = contact_stiffness_factor * E / h (Pa/m), h the shortest slave face edge, E the larger
///    Young's modulus of the two bodies: a penalty layer 1/factor of an element thick, so the
///    factor, not the mesh, sets its share of the compliance. The default 5 is CalculiX's most
///    accurate choice on Hertz (docs/measurements.md); stiffer springs make CalculiX's nodal
///    pressures oscillate between neighbouring nodes and slow its Newton loop;
///  - with Coulomb friction (`friction`, mu > 0), *FRICTION under each interaction:
///    mu and CalculiX's stick slope lambda = K / stick_slope_ratio (Pa/m: shear stress per
///    elastic slip of the face-to-face penalty; see stick_slope_ratio). Tresca's law has no
///    CalculiX keyword, so feticon export refuses it (app/export_command.cpp);
///  - kinematic and distributing couplings as a reference node each (labelled after the mesh
///    nodes), its surface and *COUPLING with *KINEMATIC or *DISTRIBUTING; the supports and loads
///    on its DOFs 1-6 as *BOUNDARY and *CLOAD on it (the loads' nodal forces, which the external
///    force holds, left out); a mean coupling as its DCOUP3D element and *DISTRIBUTING COUPLING;
///    a pretension section as its faces and *PRE-TENSION SECTION, without the nodes it doubled
///    (CalculiX doubles them again; a load or set on one of them is refused);
///  - the deck's *EQUATIONs, ADJUST, cyclic symmetry ties, node surfaces (a pair's TYPE=NODE
///    slave), amplitudes (*AMPLITUDE, AMPLITUDE= blocks), *MODEL CHANGE, *CHANGE FRICTION and
///    *CHANGE SURFACE BEHAVIOR (a tie and a pair each in force where the other is not: one pair);
///  - a slave body held only by contact in the direction of the master normal (no Dirichlet
///    component there, like the Hertz cylinder) has no stiffness in CalculiX's first iteration
///    when the bodies touch at a line or point, and floats away; its nodes are shifted by
///    `overclosure` against the master's mean outward normal, so the first iteration finds
///    springs. The body is free in that direction, so the equilibrium only translates it back;
///  - a step whose loads take their values at once (fem::Step::ramp false) as *STEP,
///    AMPLITUDE=STEP (else CalculiX ramps them, a different path);
///  - *STEP with NLGEOM for large displacements, `increments` increments of equal size
///    (feticon's load steps) as the initial and largest increment, so CalculiX takes that many
///    unless its own convergence control cuts one back; output of U, RF and the contact
///    pressure.

#include "fem/problem.hpp"

#include <ostream>
#include <string>
#include <vector>

namespace feticon::io
{
struct CalculixOptions
{
  bool nlgeom = true; ///< large displacements (total Lagrangian)
  int increments = 1; ///< load increments of the step (feticon's load_steps)
  /// Penalty slope K = factor * E / h of the linear pressure-overclosure law.
  double contact_stiffness_factor = 5.0;
  /// Shift (m) of a floating slave body into its master; < 0: 2 % of the shortest slave face edge.
  double overclosure = -1.0;
  /// Coulomb's mu of each pair in each step, friction[step][pair] (0: frictionless); empty:
  /// every pair frictionless. A pair with friction has *FRICTION in its interaction (CalculiX
  /// asks mu > 0 there), and a step where its mu changes *CHANGE FRICTION.
  std::vector<std::vector<double>> friction = {};
  /// CalculiX's stick slope lambda as K / this ratio. The ccx 2.11 manual asks for lambda about
  /// 10 times (*FRICTION) or 100 times (its contact chapter) smaller than the normal spring
  /// constant; 50 sits between. With K = 5 E / h the stick then allows an elastic slip of
  /// tau / lambda = 10 (tau / E) h before sliding, a small fraction of h for stresses far below E.
  double stick_slope_ratio = 50.0;
  /// Per contact pair, whether its rows are node-to-segment (written TYPE=NODE TO SURFACE, its
  /// LINEAR law with sigma_inf = 0 so that the law stays p = K d); missing: SURFACE TO SURFACE.
  std::vector<bool> node_to_segment = {};
};

/// What the deck holds, for messages and for the deck test.
struct CalculixDeckSummary
{
  int64_t n_nodes = 0, n_elements = 0, n_cloads = 0, n_contact_pairs = 0;
  int64_t n_slave_faces = 0, n_master_faces = 0;
  double total_load[3] = {0, 0, 0}; ///< sum of the *CLOAD forces (N) of the last step
  double contact_stiffness = 0;     ///< K of the first pair (Pa/m)
  double stick_slope = 0;           ///< lambda of the first pair's *FRICTION (Pa/m), 0 if none
  double friction_coefficient = 0;  ///< mu of the first pair's *FRICTION, 0 if none
  double overclosure = 0;           ///< shift applied to floating slave bodies (m), 0 if none
};

/// @brief Writes the deck of `problem` to `out`.
/// @throws feticon::Error naming what cannot be translated (a face of a set that is no cell
///   face, a contact pair whose slave body is not one body).
CalculixDeckSummary write_calculix_deck(const fem::Problem& problem, const CalculixOptions& options, std::ostream& out);
} // namespace feticon::io

#pragma once
/// @file Contact pressure at the slave nodes, from the multipliers and from the stresses.
///
/// From multipliers: row i (normalized by ||b_i||) carries the normal force
/// lambda_i / ||b_i|| on its slave node (ALGORITHMS.md section 4); the nodal pressure is that
/// force over the node's tributary area integral(N_a dA) on the slave surface, taken on the
/// reference surface with small displacements and on the current one with large. In plane strain the nodes through the thickness at one x are
/// summed: p(x) = sum F / sum A.
/// From stresses: p = -n' sigma n with the nodally averaged Cauchy stress of the slave body.

#include "fem/problem.hpp"
#include "nonlinear/contact_solution.hpp"
#include "nonlinear/solver_settings.hpp"

#include <vector>

namespace feticon::nonlinear
{
struct PressureSample
{
  int32_t pair = 0; ///< the contact pair (index into fem::Problem::contacts)
  double x = 0;     ///< reference coordinates of the node (of the node line in
  double y = 0;     ///< plane strain, where y and z are those of its first node) (m)
  double z = 0;
  double deformed_x = 0;      ///< x + u_x, averaged over the node line in plane strain (m)
  double deformed_y = 0;      ///< y + u_y, likewise (m)
  double force = 0;           ///< normal contact force of the node(s) (N)
  double area = 0;            ///< their tributary area (m^2)
  double pressure = 0;        ///< force / area (Pa)
  double stress_pressure = 0; ///< -n' sigma n from the averaged stress (Pa)
  double analytic = 0;        ///< McEwen's p(x) or Hertz's p(r) (Pa), when compared
  /// With friction: the friction force on the node(s) (N), its traction (Pa, over `area`),
  /// whether it slides (|F_T| at the bound within 1e-5: Tresca's g area, Coulomb's mu force)
  /// and Cattaneo-Mindlin's shear traction along x (Pa), when compared.
  Eigen::Vector3d friction_force = Eigen::Vector3d::Zero();
  /// The normal contact force on the node(s) as a vector (N): `force` along the rows' normals
  /// (the master's outward ones). With large displacements the contact surface turns, and the
  /// normal forces carry part of a tangential load.
  Eigen::Vector3d normal_force = Eigen::Vector3d::Zero();
  Eigen::Vector3d shear = Eigen::Vector3d::Zero();
  bool slipping = false;
  double shear_analytic = 0;
};

/// Pressure on the slave surface of pair `pair` (an index into problem.contacts). Plane
/// strain (u_z eliminated): one sample per node line through the thickness (same reference
/// x), sorted by x. Otherwise one sample per slave node, sorted by x, then y, then z.
/// `friction`: the pair's law, whose bound tells sliding from sticking samples.
std::vector<PressureSample> slave_pressure_by_x(const fem::Problem& problem, const ContactSolution& solution,
                                                fem::Kinematics kinematics, const Friction& friction = {},
                                                int32_t pair = 0);

/// Tributary area integral(N_a dA) of every mesh node on the slave surface of pair `pair` (m^2;
/// 0 off it): reference surface with linear kinematics, current one (X + u) otherwise.
la::Vector slave_tributary_areas(const fem::Problem& problem, const la::Vector& u, fem::Kinematics kinematics,
                                 int32_t pair = 0);

/// Contact pressure at every mesh node of the slave surface of pair `pair` (Pa; 0 off it), on the
/// surface of slave_tributary_areas. Nodes of linear faces: normal force over tributary area.
/// Nodes of quadratic faces (tri6, quad8), whose forces are near consistent nodal loads (a
/// uniform pressure's are zero at a tri6's corners, A/3 at its midsides), which force over area
/// would turn into 0 at corners and 4/3 p at midsides: the mean pressure of the faces around
/// the node, each face's pressure its share of its nodes' forces (in proportion to their
/// lumped areas, contact/face_geometry.hpp) over its area. A uniform pressure comes back
/// exactly; the L2 projection M p = f, tried first, blew the corners' small forces up to 2.5 p0
/// on the tet10 sphere (docs/elements.md).
la::Vector slave_nodal_pressures(const fem::Problem& problem, const ContactSolution& solution,
                                 fem::Kinematics kinematics, int32_t pair = 0);

/// Per node of the mesh (n_nodes values; 0 off the slave surfaces): each contact row's normal
/// force lambda_i / ||b_i|| over its node's tributary area, summed over the pairs; what the VTU's
/// contact_pressure field and contact.png show.
std::vector<double> row_pressure_per_node(const ContactSolution& solution, int32_t n_nodes);

/// Total normal contact force (N): sum of lambda_i / ||b_i||, over every pair or (pair >= 0)
/// over the rows of that pair.
double total_normal_force(const ContactSolution& solution, int32_t pair = -1);

/// The contact rows, multipliers and tangential rows of `solution` that belong to pair p, with
/// its displacement: what the outputs of one pair read.
ContactSolution pair_solution(const ContactSolution& solution, int32_t p);

} // namespace feticon::nonlinear

#pragma once
/// @file What happens where two surfaces touch: a contact interaction (the Abaqus / CalculiX
/// *SURFACE INTERACTION), its friction law and the formulation of its rows. Each contact pair
/// of a problem (fem::ContactPairNames) carries its own; the solver settings contact.friction.*
/// and contact.formulation, where given, override them for every pair
/// (nonlinear::SolverSettings::interaction).

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace feticon::fem
{
/// Friction on a contact pair (FETI solver; tangential rows, contact/tangential_rows.hpp).
enum class FrictionModel : uint8_t
{
  none,
  tresca, ///< |t_T| <= slip_bound (a traction, Pa), independent of the pressure
  coulomb ///< |t_T| <= coefficient p, by the fixed point on the slip bound in the outer loop
};

struct Friction
{
  FrictionModel model = FrictionModel::none;
  double coefficient = 0; ///< Coulomb's mu
  double slip_bound = 0;  ///< Tresca's g (Pa)
};

/// How a pair's contact rows are built: one closest point per slave node (node_to_segment,
/// contact/contact_constraints.hpp) or integrated dual mortar weights (mortar,
/// contact/mortar_constraints.hpp). Both give rows of the same form -n' on the slave node and
/// +w_a n' on master nodes a with sum_a w_a = 1.
enum class ContactFormulation : uint8_t
{
  node_to_segment = 0, ///< w_a = N_a(xi_bar) at the closest point (ALGORITHMS.md section 4)
  mortar = 1,          ///< w_a = M_ja / D_j, segment-to-segment dual mortar integrals
};

/// How the contact pressure p follows the overclosure d (the slave's penetration into the
/// master, m; a clearance is negative): the Abaqus / CalculiX *SURFACE BEHAVIOR.
enum class NormalLawKind : uint8_t
{
  hard,        ///< d <= 0, p >= 0, p d = 0: exact non-penetration (the rows B_I u <= c_I)
  linear,      ///< p = K max(d, 0): a penalty spring of slope K per area
  exponential, ///< CalculiX's p = p0 exp(beta d), beta = ln(100) / c0 (read, solved as hard)
  tabular      ///< piecewise linear (overclosure, pressure) pairs (read, solved as hard)
};

struct NormalLaw
{
  NormalLawKind kind = NormalLawKind::hard;
  double slope = 0; ///< linear: K (Pa/m)
  /// linear: p = max(K d - sigma_inf, 0). CalculiX's node-to-face springs follow the smoothed
  /// law p = K d (1/2 + atan(d / eps) / pi), eps = pi sigma_inf / K, whose tension at a
  /// clearance is -sigma_inf and which approaches K d - sigma_inf in contact (within 3 % of
  /// sigma_inf from d = 10 eps on): feticon solves that asymptote. 0 for face-to-face pairs,
  /// whose law CalculiX makes bilinear.
  double sigma_inf = 0;
  double c0 = 0; ///< exponential: the clearance at which p = p0 / 100 (m)
  double p0 = 0; ///< exponential: the pressure at zero overclosure (Pa)
  /// exponential: CalculiX's face-to-face variant p = p0 (exp(beta d) - 1) for d >= 0, 0 below;
  /// otherwise its node-to-face one, p = p0 exp(beta d) for d > -c0, 0 beyond.
  bool zero_at_contact = false;
  /// tabular: (overclosure m, pressure Pa) in increasing overclosure, the pressure constant
  /// beyond both ends (CalculiX)
  std::vector<std::pair<double, double>> table = {};
  /// At a slave node that is a corner of no face, the pressure acts on the master face's area
  /// at its closest point, not on the slave node's area: CalculiX's node-to-face springs on a
  /// node surface (TYPE=NODE), which give a node the area of the faces it is a corner of
  /// (tiefaccont.f), and one without any the master face's (springforc_n2f.f): the edge nodes
  /// of quadratic faces, every node of a 2D model (contact::ContactConstraints::master_face_area).
  bool on_master_face = false;
  bool operator==(const NormalLaw&) const = default;

  /// The law's tangent line at overclosure d, p ~ stiffness (d' - zero_overclosure) near d:
  /// what the outer loop solves at each iteration (a compliance on the rows,
  /// dual/contact_qp.hpp), so that its fixed point satisfies the law. Linear: K and sigma_inf /
  /// K at any d. Exponential: at max(d, -c0) (node-to-face; its springs start at -c0) or max(d,
  /// 0) (face-to-face). Tabular: the segment holding d, the first or last one beyond the table.
  struct Tangent
  {
    double stiffness;        ///< dp/dd (Pa/m), > 0
    double zero_overclosure; ///< where the line's pressure is 0 (m)
  };
  Tangent tangent(double overclosure) const;
  /// The overclosure at pressure p > 0 (m): the inverse of the law (hard: 0).
  double overclosure_at(double pressure) const;
  /// Whether tangent() depends on d: the outer loop must iterate to satisfy the law.
  bool is_nonlinear() const { return kind == NormalLawKind::exponential || kind == NormalLawKind::tabular; }
};

/// A pair's interaction: its normal law (the model's; the solver takes it where the setting
/// contact.law is deck, hard contact otherwise), friction and row formulation.
struct ContactInteraction
{
  std::string name; ///< the deck's *SURFACE INTERACTION name; empty for a built-in or problem-file pair
  NormalLaw law;
  Friction friction;
  /// Mortar is the default of every pair (the setting contact.formulation's default); a deck's
  /// NODE TO SURFACE pair is node-to-segment.
  ContactFormulation formulation = ContactFormulation::mortar;
};

/// "none", "tresca" or "coulomb".
const char* friction_model_name(FrictionModel model);
/// "node_to_segment" or "mortar".
const char* formulation_name(ContactFormulation formulation);
/// "hard", "linear", "exponential" or "tabular".
const char* normal_law_name(NormalLawKind kind);
} // namespace feticon::fem

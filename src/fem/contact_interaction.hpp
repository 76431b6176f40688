#pragma once
/// @file What happens where two surfaces touch: a contact interaction (the Abaqus / CalculiX
/// *SURFACE INTERACTION), its friction law and the formulation of its rows. Each contact pair
/// of a problem (fem::ContactPairNames) carries its own; the solver settings contact.friction.*
/// and contact.formulation, where given, override them for every pair
/// (nonlinear::SolverSettings::interaction).

#include <cstdint>
#include <string>

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

/// The normal contact is hard (exact non-penetration, the constraint rows B_I u <= c_I).
struct ContactInteraction
{
  std::string name; ///< the deck's *SURFACE INTERACTION name; empty for a built-in or problem-file pair
  Friction friction;
  /// Mortar is the default of every pair (the setting contact.formulation's default); a deck's
  /// NODE TO SURFACE pair is node-to-segment.
  ContactFormulation formulation = ContactFormulation::mortar;
};

/// "none", "tresca" or "coulomb".
const char* friction_model_name(FrictionModel model);
/// "node_to_segment" or "mortar".
const char* formulation_name(ContactFormulation formulation);
} // namespace feticon::fem

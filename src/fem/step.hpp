#pragma once
/// @file One step of a problem's history (a deck's *STEP, a problem file's `steps:` entry):
/// the loads and supports in force in it, how they get there and in how many increments.
///
/// Every step, the first included, holds the whole set of its loads and supports (what a deck
/// carries over from the step before is resolved by its reader). A load or support without an
/// amplitude goes linearly over the step from its value at the end of the step before (0 in
/// the first) to its own (ramp), or takes its own at once (`ramp = false`: *STEP,
/// AMPLITUDE=STEP); one with an amplitude is its value times a(t). fem::LoadHistory evaluates
/// them at every increment.

#include "fem/body_loads.hpp"
#include "fem/contact_interaction.hpp"
#include "fem/coupling.hpp"
#include "fem/dirichlet.hpp"

#include <optional>
#include <string>
#include <vector>

namespace feticon::fem
{
/// Uniform dead traction (Pa, force per reference area) on a named face set.
struct FaceTraction
{
  std::string set;
  Eigen::Vector3d traction;
  std::string amplitude = {}; ///< Problem::amplitudes name; empty: the step's ramp
};

/// Uniform dead pressure (Pa, positive pushes into the body, on the reference normals) on a
/// named face set (deck *DLOAD Pn).
struct FacePressure
{
  std::string set;
  double pressure;
  std::string amplitude = {};
};

/// A concentrated dead force (N) on one component of one node (deck *CLOAD).
struct NodalForce
{
  int32_t node;
  int component; ///< 0, 1, 2
  double value;
  std::string amplitude = {};
};

/// The temperature of one node at the end of a step (deck *TEMPERATURE, a problem file's
/// `temperature:` load), as CalculiX applies it: without amplitude it goes linearly over the
/// step from the node's temperature at the end of the step before (the initial temperature in
/// the first; at once with `ramp = false`); with one it is value a(t).
struct NodalTemperature
{
  int32_t node;
  double value;
  std::string amplitude = {};
};

/// The lowest temperature a problem may give: absolute zero in degrees Celsius. The unit is
/// the user's (Celsius or kelvin, as in CalculiX); in kelvin every valid value is above it too.
inline constexpr double absolute_zero_celsius = -273.15;
/// Throws feticon::Error naming `what` for a temperature that is not finite or below absolute
/// zero (absolute_zero_celsius).
void check_temperature(double value, const std::string& what);

/// Automatic increments of a step (a deck's *STATIC without DIRECT), in the step's time: the
/// first increment, and the bounds the control keeps it within (fem::LoadHistory grows it after
/// easy increments and halves it where one fails, as CalculiX does).
struct IncrementControl
{
  double initial = 1;
  double minimum = 1e-5;
  double maximum = 1;
  /// At most this many increments (a deck's *STEP, INC=; CalculiX's default 100): where they
  /// stay small the run stops instead of creeping on.
  int max_increments = 100;
};

struct Step
{
  std::vector<DirichletCondition> dirichlet;
  std::vector<FaceTraction> tractions;
  std::vector<FacePressure> pressures;
  std::vector<NodalForce> nodal_forces;
  std::vector<BodyLoad> body_loads; ///< gravity and centrifugal loads (fem/body_loads.hpp)
  /// Supports and loads on the reference nodes of couplings (fem/coupling.hpp).
  std::vector<ReferenceValue> reference_supports = {};
  std::vector<ReferenceValue> reference_loads = {};
  /// Temperatures in force in the step; a node not named goes to (or stays at) its initial
  /// temperature (fem/temperature_history.hpp).
  std::vector<NodalTemperature> temperatures;
  /// Contact pairs (indices into Problem::contacts) out of force in the step: no rows, no
  /// pressure (deck *MODEL CHANGE, TYPE=CONTACT PAIR, REMOVE; ADD puts one back).
  std::vector<int32_t> removed_contacts = {};
  /// Ties (indices into Problem::ties) out of force in the step (a deck's tied contact pair
  /// that *CHANGE SURFACE BEHAVIOR turned into contact; its contact pair is then in force).
  std::vector<int32_t> removed_ties = {};
  /// Contact pairs (indices into Problem::contacts) whose friction in the step is not their
  /// interaction's, with the friction in force (deck *CHANGE FRICTION, which holds until
  /// another changes it).
  std::vector<std::pair<int32_t, Friction>> changed_friction = {};
  /// Contact pairs whose contact law in the step is not their interaction's, with the law in
  /// force (deck *CHANGE SURFACE BEHAVIOR turning a tied pair into contact).
  std::vector<std::pair<int32_t, NormalLaw>> changed_law = {};
  /// Load steps of the step, equal increments; unset: automatic ones if `automatic` is set,
  /// else the solver's (settings load_steps).
  std::optional<int> increments = {};
  std::optional<IncrementControl> automatic = {};
  double time = 1;  ///< the step's time period (*STATIC's), for amplitudes and the outputs
  bool ramp = true; ///< loads without amplitude ramp over the step (false: applied at once)
};
} // namespace feticon::fem

#pragma once
/// @file summary.json's `couplings`: per coupling (fem/coupling.hpp) its reference node's
/// displacement and rotation and the force and moment it transmits (the reaction of a held
/// reference DOF plus the load on it: CalculiX's RF of the reference node).

#include "fem/problem.hpp"
#include "nonlinear/contact_solution.hpp"

#include <nlohmann/json.hpp>

namespace feticon::app
{
/// An array of {name, kind, displacement, rotation, force, moment} (m, rad, N, N m); empty if
/// the problem has no coupling.
nlohmann::ordered_json coupling_summary(const fem::Problem& problem, const nonlinear::ContactSolution& solution,
                                        fem::Kinematics kinematics);
} // namespace feticon::app

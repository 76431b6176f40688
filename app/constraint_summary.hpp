#pragma once
/// @file summary.json's `couplings` and `ties`: per coupling (fem/coupling.hpp) its reference
/// node's displacement and rotation and the force and moment it transmits (the reaction of a
/// held reference DOF plus the load on it: CalculiX's RF of the reference node); per tie the
/// force its slave surface receives.

#include "fem/problem.hpp"
#include "nonlinear/contact_solution.hpp"

#include <nlohmann/json.hpp>

namespace feticon::app
{
/// Every coupling's reference values and reactions at displacement u with CalculiX's RF
/// `reaction` (calculix_reaction): finite rotations where large displacements turn a rank-6
/// kinematic coupling (fem::finite_reference_result), else fem::reference_result.
std::vector<fem::ReferenceResult> reference_results(const fem::Problem& problem, const la::Vector& u,
                                                    const la::Vector& reaction, fem::Kinematics kinematics);

/// An array of {name, kind, displacement, rotation, force, moment} (m, rad, N, N m); empty if
/// the problem has no coupling.
nlohmann::ordered_json coupling_summary(const fem::Problem& problem, const nonlinear::ContactSolution& solution,
                                        fem::Kinematics kinematics);

/// An array of {name, rows, in_force, force} per tie: force (N) the sum over the tie rows' slave
/// DOFs of f_int + B_I' lambda (CalculiX's RF there: the force the master side exerts on the
/// slave side, plus any load applied at those nodes, which ties seldom carry); in_force false
/// for a tie the last step removed (*CHANGE SURFACE BEHAVIOR), whose force is then that of the
/// contact pair in its place.
nlohmann::ordered_json tie_summary(const fem::Problem& problem, const nonlinear::ContactSolution& solution,
                                   fem::Kinematics kinematics);
} // namespace feticon::app

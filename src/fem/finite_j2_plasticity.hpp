#pragma once
/// @file J2 plasticity at finite strain (total Lagrangian): Simo's multiplicative model with a
/// hyperelastic elastic part, as CalculiX's incplas.f implements it (J.C. Simo, Comput. Methods
/// Appl. Mech. Engrg. 66 (1988) 199-219 and 68 (1988) 1-31; Simo and Hughes 1998, box 9.1),
/// written in the reference configuration.
///
/// With C = I + 2 E, J = sqrt(det C) and the state C_p^-1 (the inverse plastic right
/// Cauchy-Green tensor, I at first) and eqps:
///   Cb = J^(-2/3) C_p^-1,  I_e = C : Cb / 3  (= tr(b_e bar) / 3),
///   S_tr = mu (Cb - I_e C^-1)  (the pull-back of s_tr = mu dev(b_e bar)),
///   |s_tr| = sqrt(tr((S_tr C)^2)),  q = sqrt(3/2) |s_tr|.
/// The point yields if q > J sigma_y(eqps) (Kirchhoff stress: J times the table's Cauchy
/// stress, as CalculiX); then the increment d of eqps solves q - 3 mu_bar d = J sigma_y(eqps + d),
/// mu_bar = mu I_e (segment by segment of the table, as at small strain), the deviator becomes
/// S_dev = (1 - 3 mu_bar d / q) S_tr and the state C_p^-1 = J^(2/3) (S_dev / mu + I_e C^-1).
/// S = K (J^2 - 1) / 2 C^-1 + S_dev, with mu and K of *ELASTIC's E and nu.
///
/// Kinematic hardening (YieldCurve::kinematic; incplas.f with the table as its kinematic curve):
/// the state adds the back stress beta (PlasticPointState::back_stress, pulled back, 0 at first),
/// which enters as its isochoric deviator beta_b = J^(-2/3) beta - (C : J^(-2/3) beta / 3) C^-1;
/// the radius stays J sigma_y(0) and the point yields where q of xi = S_tr - beta_b exceeds it,
/// with mu_bar = mu I_e - C : J^(-2/3) beta / 3; the increment d solves q - 3 mu_bar d =
/// J sigma_y(0) + s (sigma_y(eqps + d) - sigma_y(eqps)), s = J mu_bar / mu, and then
/// S_dev = S_tr - (3 mu_bar d / q) xi, C_p^-1 -= 3 mu_bar d / (mu q) J^(2/3) xi and
/// beta += s (sigma_y(eqps + d) - sigma_y(eqps)) / q J^(2/3) xi. That is incplas.f's update, but
/// for the back stress's step: incplas.f takes the slope at the end of the increment times d,
/// which equals the table's rise within one segment and not across a breakpoint (there its back
/// stress moves less than its own yield condition assumed; docs/materials.md). At small strain
/// this is the small-strain kinematic return (fem/j2_plasticity.hpp).
///
/// The stored state (PlasticPointState::plastic_strain) is C_p^-1 - I with plain shears. The
/// tangent dS/dE is taken by central differences of the update (step 1e-6 in each strain
/// component: truncation 1e-12, round-off 1e-10 of the stress scale) and symmetrized (the exact
/// one is symmetric for this associative model); K uses it as the material part. At a yielded
/// point where it is not positive definite (the stress's own terms exceed the shear stiffness
/// the hardening leaves, and FETI's K_M has no geometric stiffness to make up for them) the
/// tangent is the Kirchhoff consistent one without those terms, K J^2 1 (x) 1 + 2 mu_bar theta
/// I_dev - 2 mu_bar theta_bar n (x) n, pulled back through U = sqrt(C) (docs/materials.md has
/// the measurements that chose it).

#include "fem/j2_plasticity.hpp"

namespace feticon::fem
{
/// The return from `committed` at Green-Lagrange strain `strain` (Voigt, engineering shears):
/// the second Piola-Kirchhoff stress (plain shears) and the new state.
/// @param[out] tangent if not null, dS/dE (6x6, engineering shears)
/// @throws feticon::Error if the point is inverted (det C <= 0) or the table softens faster
///         than 3 mu_bar
J2Update finite_j2_return(const Material& material, const Voigt& strain, const PlasticPointState& committed,
                          Eigen::Matrix<double, 6, 6>* tangent = nullptr);
} // namespace feticon::fem

#pragma once
/// @file J2 (von Mises) plasticity with isotropic hardening at small strain: the radial return
/// and its consistent tangent (Simo and Hughes 1998, Computational Inelasticity, box 3.2;
/// ALGORITHMS.md section 7).
///
/// With the shear modulus G, the trial stress sigma_tr = D (eps - eps_p,n) - thermal, its
/// deviator s_tr and q_tr = sqrt(3/2 s_tr : s_tr): if q_tr <= sigma_y(eqps_n) the step is
/// elastic; otherwise the increment d of the equivalent plastic strain solves
///   q_tr - 3 G d - sigma_y(eqps_n + d) = 0
/// (exactly, segment by segment of the piecewise-linear yield curve), s = (1 - 3 G d / q_tr) s_tr,
/// eps_p += 3/2 d s_tr / q_tr, and the consistent tangent is
///   C = K 1 (x) 1 + 2 G theta I_dev - 2 G theta_bar n (x) n,  n = s_tr / |s_tr|,
///   theta = 1 - 3 G d / q_tr,  theta_bar = 1 / (1 + H / (3 G)) - (1 - theta),
/// H = d sigma_y / d eqps at the new eqps. Voigt [11,22,33,12,23,31]: engineering shears in the
/// strains (plastic strain included), plain shears in the stress.
///
/// Kinematic hardening (YieldCurve::kinematic; Simo and Hughes box 3.1 with the table's slope
/// as the kinematic modulus, as CalculiX's incplas_lin.f): s_tr is taken relative to the back
/// stress alpha, the radius stays sigma_y(0), so d solves q_tr - 3 G d = sigma_y(0) +
/// sigma_y(eqps + d) - sigma_y(eqps), and alpha moves by (sigma_y(eqps + d) - sigma_y(eqps))
/// s_tr / q_tr; the same tangent with that H.

#include "fem/material.hpp"
#include "fem/voigt.hpp"

#include <Eigen/Dense>

namespace feticon::fem
{

/// What a J2 material remembers at one integration point between increments.
struct PlasticPointState
{
  /// Small strain: eps_p, engineering shears. Total Lagrangian: C_p^-1 - I, plain shears
  /// (fem/finite_j2_plasticity.hpp). Zero at first either way.
  Voigt plastic_strain = Voigt::Zero();
  double equivalent_plastic_strain = 0; ///< eqps = integral of sqrt(2/3 deps_p : deps_p)
  Voigt back_stress = Voigt::Zero();    ///< the yield surface's centre (kinematic hardening), plain shears
};

struct J2Update
{
  Voigt stress;            ///< sigma (Pa)
  PlasticPointState state; ///< the state at the end of the increment
  bool plastic = false;    ///< the point yielded in this increment
};

/// The increment d >= 0 of the equivalent plastic strain with q_tr - 3 G d = s sigma_y(eqps + d)
/// (s = `scale`: J for the Kirchhoff stress at finite strain), exact on the piecewise-linear
/// table: the first segment from eqps's on which its linear equation's d stays.
/// @throws feticon::Error if a segment softens faster than 3 G (no solution)
double plastic_increment(const YieldCurve& curve, double shear_modulus, double q_trial, double eqps, double scale = 1);

/// The radial return from `committed` at total strain `strain` (engineering shears), less the
/// normal stress `thermal_stress` (alpha E / (1 - 2 nu) Delta T) of a temperature change.
/// `material.plastic` must not be empty.
/// @param[out] tangent if not null, the consistent tangent d sigma / d eps (6x6, engineering
///             shears) of the return; the elasticity matrix where the point did not yield
J2Update j2_return(const Material& material, const Voigt& strain, double thermal_stress,
                   const PlasticPointState& committed, Eigen::Matrix<double, 6, 6>* tangent = nullptr);
} // namespace feticon::fem

#pragma once
/// @file The separable convex set of a contact QP (qp::QpSolver: MPRGP takes its bounds, MPGP
/// (qp/mpgp.hpp) its bounds and discs) and the per-set operations of MPGP.
///
///     Omega = { x : l_i <= x_i <= u_i for every component i,
///                   ||(x_i, x_j) - c_k|| <= r_k for every disc k = (i, j, r_k, c_k) }.
///
/// A component is free (l_i = -inf, u_i = +inf), bounded on one or both sides, or one of the
/// two components of a disc (then l_i = -inf and u_i = +inf: a disc component has no bound).
/// Tresca friction in 3D: the normal multipliers of the contact nodes are bounded below
/// (x_i >= 0), the two tangential ones of a node lie in the disc of the slip bound g >= 0.
///
/// Each function has one purpose and works on this rank's entries only: a disc's two indices
/// are local to one rank, and what has to be reduced over ranks (the largest feasible step)
/// is returned per rank for the caller's la::VectorSpace.
///
/// Active set of a feasible x: component i with a bound at x_i = l_i or x_i = u_i (l_i < u_i;
/// l_i = u_i fixes x_i), and a disc with ||x_d - c|| >= r (1 - disc_tolerance), c its centre
/// (always, for r = 0). On an active disc with r > 0 the outward unit normal is
/// n = (x_d - c) / ||x_d - c||; a disc of radius 0 is a fixed pair (every gradient is a
/// multiplier of it), like l_i = u_i.
///
/// Usage:
///   qp::SeparableConstraints set{lower, upper, {{.i = 4, .j = 5, .radius = 0.3}}};
///   qp::check_separable_constraints(set, n, "feticon qp");
///   qp::project(set, x);                     // x in Omega
///   assert(qp::is_feasible(set, x));

#include "la/types.hpp"

#include <vector>

namespace feticon::qp
{
/// The pair (x_i, x_j) in the disc of radius `radius` about (centre_i, centre_j): a dual
/// contact QP homogenized by lambda = lambda~ + mu has its friction discs |lambda_T| <= g
/// centred at -lambda~_T.
struct Disc
{
  la::Index i = 0;
  la::Index j = 0;
  double radius = 0.0;
  double centre_i = 0.0, centre_j = 0.0;
};

/// Omega: bounds per component and discs over pairs of components (file comment).
struct SeparableConstraints
{
  /// l, -inf for components without a lower bound (and for disc components).
  la::Vector lower;
  /// u, +inf for components without an upper bound (and for disc components). Empty for no
  /// upper bounds at all: MPRGP then runs the arithmetic of its lower-bound algorithm (the same
  /// iterates as with u = +inf, bitwise); MPGP needs u.
  la::Vector upper;
  /// Pairs of distinct components, no component in two discs.
  std::vector<Disc> discs;
};

/// A disc counts as active when ||x_d|| >= r (1 - disc_tolerance): a radial projection lands
/// within a few ulps of r, on either side.
constexpr double disc_tolerance = 1e-12;

/// @brief Checks Omega against n components: sizes, l_i not NaN or +inf, u_i not NaN or
///        -inf, l_i <= u_i, disc indices in [0, n) and distinct, no component in two discs,
///        a disc component without finite bounds, a finite radius >= 0.
/// @param[in] who  names the caller in the message (e.g. "Mpgp::solve").
/// Throws feticon::Error with one line naming the component or disc.
void check_separable_constraints(const SeparableConstraints& set, la::Index n, const char* who);

/// True when the disc is active at x (see the file comment).
bool disc_is_active(const Disc& disc, const la::Vector& x);

/// @brief x <- P_Omega(x): clamps each component into [l_i, u_i] and scales each disc pair
///        outside its disc radially onto the circle (onto 0 for radius 0).
void project(const SeparableConstraints& set, la::Vector& x);

/// @brief True when l <= x <= u exactly and ||x_d|| <= r (1 + disc_tolerance) for every disc.
bool is_feasible(const SeparableConstraints& set, const la::Vector& x);

/// @brief v <- its part in the face of x: 0 on components at a bound and on discs of radius
///        0, the tangential part v_d - (n'v_d) n on an active disc, v elsewhere. An orthogonal
///        projector (symmetric), so D M D stays symmetric for a symmetric M.
void project_onto_face(const SeparableConstraints& set, const la::Vector& x, la::Vector& v);

/// @brief The free gradient phi: g projected onto the face (project_onto_face): g on free
///        components and inactive discs, its tangential part on active discs, 0 elsewhere.
void free_gradient(const SeparableConstraints& set, const la::Vector& x, const la::Vector& g, la::Vector& phi);

/// @brief The chopped gradient beta, 0 on free components and inactive discs: min(g_i, 0) at
///        x_i = l_i < u_i, max(g_i, 0) at x_i = u_i > l_i, 0 on fixed components and discs of
///        radius 0; on an active disc with outward normal n, max(n'g_d, 0) n (a step along
///        -beta leaves the circle inward). phi + beta is the projected gradient g_P, zero
///        exactly at a KKT point.
void chopped_gradient(const SeparableConstraints& set, const la::Vector& x, const la::Vector& g, la::Vector& beta);

/// @brief True when p moves some active disc of radius > 0 on this rank (a step along it then
///        follows the circle through the projection).
bool moves_along_a_circle(const SeparableConstraints& set, const la::Vector& x, const la::Vector& p);

/// @brief The reduced free gradient phi~ = (x - P_Omega(x - alpha phi)) / alpha, so that
///        x - alpha phi~ = P_Omega(x - alpha phi). On bounded components it is written as
///        MPRGP's min((x_i - l_i)/alpha, max((x_i - u_i)/alpha, phi_i)) (the same value,
///        without the round-off of x - (x - alpha phi)).
void reduced_free_gradient(const SeparableConstraints& set, const la::Vector& x, const la::Vector& phi, double alpha,
                           la::Vector& reduced);

/// @brief The curvature nu_d / r_d that an active disc adds along its circle, per component:
///        with g_d = -nu_d n + (tangential part), nu_d = max(-n'g_d, 0), moving by t along
///        the circle changes f by 1/2 t^2 (nu_d / r_d) beyond the quadratic term of A (the
///        Hessian of the Lagrangian). 0 off active discs and on discs of radius 0.
void disc_curvature(const SeparableConstraints& set, const la::Vector& x, const la::Vector& g, la::Vector& curvature);

/// @brief Largest alpha >= 0 with l <= x - alpha p <= u on this rank's components (+inf if
///        none limits it), and the component that limits it (-1 if none).
double max_bound_step(const SeparableConstraints& set, const la::Vector& x, const la::Vector& p, la::Index& blocking);

/// @brief Largest alpha >= 0 with ||x_d - alpha p_d|| <= r for this rank's discs: the
///        positive root of ||x_d - alpha p_d||^2 = r^2 (+inf if p_d = 0 for every disc), and
///        the first index of the disc that limits it (-1 if none).
/// @param[in] include_active  false: active discs are skipped (a step in the face moves them
///        along their circle, through the projection, and is not limited by them).
double max_disc_step(const SeparableConstraints& set, const la::Vector& x, const la::Vector& p, bool include_active,
                     la::Index& blocking);
} // namespace feticon::qp

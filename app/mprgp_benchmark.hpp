#pragma once
/// @file MPRGP on its own (issue 8): time per MPRGP step against the time of one
/// application of its operator, on a large bound-constrained QP with a sparse matrix.

#include <nlohmann/json.hpp>
#include <string>

namespace feticon::app
{
/// @brief The 2D obstacle problem on an n x n interior grid of the unit square, h = 1/(n+1):
///   min 1/2 u'Au - b'u  s.t.  u >= l,
///   A = 5-point Laplacian / h^2,  b = -15,  l(x, y) = sin(3 pi x) sin(3 pi y) / 2 - 0.6,
/// solved by MPRGP from u = 0 (projected), at most `max_iterations` steps (the cost per step
/// needs no converged solve: n = 1000 takes tens of thousands of steps). Reports the steps, the solve time, the median of
/// `applications` timed operator applications and the ratio time per step / application
/// (the limit is about 1: one product per CG step, two per expansion step).
/// @param[in] n            grid points per side (n^2 unknowns); >= 2
/// @param[in] rtol         MPRGP stopping tolerance ||g_P|| <= rtol ||b||
/// @param[in] max_iterations MPRGP step limit
/// @param[in] applications timed operator applications for the median; >= 1
nlohmann::ordered_json mprgp_obstacle_benchmark(int n, double rtol, int max_iterations, int applications,
                                                const std::string& expansion = "std");
} // namespace feticon::app

#include "app/mprgp_benchmark.hpp"
#include "app/qp_counters_json.hpp"

#include "common/error.hpp"
#include "common/timer.hpp"
#include "la/operator.hpp"
#include "qp/mprgp.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <vector>

namespace feticon::app
{
namespace
{
la::SparseMatrix laplacian_2d(int n, double h)
{
  std::vector<la::Triplet> triplets;
  triplets.reserve(5 * static_cast<size_t>(n) * n);
  const double scale = 1.0 / (h * h);
  auto index = [n](int i, int j) { return i * n + j; };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
    {
      const int row = index(i, j);
      triplets.emplace_back(row, row, 4 * scale);
      if (i > 0)
        triplets.emplace_back(row, index(i - 1, j), -scale);
      if (i + 1 < n)
        triplets.emplace_back(row, index(i + 1, j), -scale);
      if (j > 0)
        triplets.emplace_back(row, index(i, j - 1), -scale);
      if (j + 1 < n)
        triplets.emplace_back(row, index(i, j + 1), -scale);
    }
  la::SparseMatrix A(n * n, n * n);
  A.setFromTriplets(triplets.begin(), triplets.end());
  return A;
}

double median(std::vector<double> values)
{
  std::sort(values.begin(), values.end());
  const size_t m = values.size() / 2;
  return values.size() % 2 ? values[m] : 0.5 * (values[m - 1] + values[m]);
}
} // namespace

nlohmann::ordered_json mprgp_obstacle_benchmark(int n, double rtol, int max_iterations, int applications,
                                                const std::string& expansion)
{
  FETICON_CHECK(n >= 2, "the obstacle grid needs n >= 2 points per side, got " << n);
  FETICON_CHECK(applications >= 1, "time at least one operator application, got " << applications);
  const double h = 1.0 / (n + 1);
  const la::SparseMatrix matrix = laplacian_2d(n, h);
  const la::SparseOperator A(matrix);
  const la::Vector b = la::Vector::Constant(n * n, -15.0);
  la::Vector lower(n * n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      lower(i * n + j) =
          std::sin(3 * std::numbers::pi * (i + 1) * h) * std::sin(3 * std::numbers::pi * (j + 1) * h) / 2 - 0.6;

  std::vector<double> seconds(applications);
  la::Vector x = la::Vector::Random(n * n), y;
  for (double& s : seconds)
  {
    const auto start = std::chrono::steady_clock::now();
    A.apply(x, y);
    s = seconds_since(start);
  }
  const double t_apply = median(seconds);

  qp::Mprgp mprgp(A, {.rtol = rtol, .max_iterations = max_iterations, .expansion = qp::expansion_from_name(expansion)});
  x.setZero();
  const qp::QpReport report = mprgp.solve(b, lower, x);
  int64_t active = 0;
  for (la::Index i = 0; i < x.size(); ++i)
    active += x(i) == lower(i);
  const double t_step = report.seconds / std::max(report.iterations, 1);
  nlohmann::ordered_json json = {{"problem", "obstacle_2d"},
                                 {"unknowns", static_cast<int64_t>(n) * n},
                                 {"matrix_nonzeros", matrix.nonZeros()},
                                 {"rtol", rtol},
                                 {"converged", report.converged},
                                 {"expansion", expansion}};
  json.update(qp_counters_json(report));
  json.update({{"active_bounds", active},
               {"solve_seconds", report.seconds},
               {"seconds_per_iteration", t_step},
               {"operator_seconds_median", t_apply},
               {"operator_timings", applications},
               {"ratio_iteration_to_operator", t_step / t_apply},
               {"ratio_solve_to_applications", report.seconds / (report.hessian_multiplications * t_apply)}});
  return json;
}
} // namespace feticon::app

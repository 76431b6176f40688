#pragma once
/// What a QP solve produced, as seen by its monitor, and bitwise comparison of two such traces
/// (MPRGP against itself with other arguments, MPGP against MPRGP).

#include "qp/mprgp.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace feticon::test
{
/// Everything a solve produces: iterates seen by the monitor, the final x and the report.
struct Trace
{
  std::vector<qp::MprgpIterate> iterates;
  la::Vector x;
  qp::QpReport report;
};

/// Bitwise equality of two traces (the reports' times aside).
inline void expect_identical(const Trace& first, const Trace& second)
{
  ASSERT_EQ(first.iterates.size(), second.iterates.size());
  for (std::size_t k = 0; k < first.iterates.size(); ++k)
  {
    const qp::MprgpIterate& a = first.iterates[k];
    const qp::MprgpIterate& b = second.iterates[k];
    EXPECT_EQ(a.step, b.step) << "iterate " << k;
    EXPECT_EQ(a.projected_gradient_norm, b.projected_gradient_norm) << "iterate " << k;
    EXPECT_EQ(a.free_gradient_norm, b.free_gradient_norm) << "iterate " << k;
    EXPECT_EQ(a.chopped_gradient_norm, b.chopped_gradient_norm) << "iterate " << k;
    EXPECT_EQ(a.cost, b.cost) << "iterate " << k;
  }
  EXPECT_TRUE(first.x == second.x);
  EXPECT_EQ(first.report.converged, second.report.converged);
  EXPECT_EQ(first.report.reason, second.report.reason);
  EXPECT_EQ(first.report.iterations, second.report.iterations);
  EXPECT_EQ(first.report.cg_steps, second.report.cg_steps);
  EXPECT_EQ(first.report.expansion_steps, second.report.expansion_steps);
  EXPECT_EQ(first.report.expansion_fallbacks, second.report.expansion_fallbacks);
  EXPECT_EQ(first.report.proportioning_steps, second.report.proportioning_steps);
  EXPECT_EQ(first.report.hessian_multiplications, second.report.hessian_multiplications);
  EXPECT_EQ(first.report.projected_gradient_norm, second.report.projected_gradient_norm);
  EXPECT_EQ(first.report.cost, second.report.cost);
}
} // namespace feticon::test

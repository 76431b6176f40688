#pragma once
/// @file The one JSON writer of qp::QpCounters (summary.json "qp", `feticon qp`,
/// `feticon bench`), and the run's counters summed over its outer iterations.

#include "nonlinear/contact_solution.hpp"
#include "qp/qp_report.hpp"

#include <nlohmann/json.hpp>

namespace feticon::app
{
/// The counters as JSON, without the times (which differ from run to run; the callers put
/// them beside): the step counts always; SMALBE-M's updates when it ran
/// (smalbe_outer_iterations, rho_updates), the timed operator and preconditioner
/// applications when counted, the spectrum estimate (face_spectrum) when a CG run measured it.
nlohmann::ordered_json qp_counters_json(const qp::QpCounters& counters);

/// The QP counters and times of all outer iterations of a run summed.
qp::QpCounters qp_totals(const nonlinear::ContactSolution& solution);

/// summary.json "qp": the run's totals, the last SMALBE-M rho and the outer iteration count.
nlohmann::ordered_json qp_json(const nonlinear::ContactSolution& solution);
} // namespace feticon::app

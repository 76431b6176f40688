#pragma once
/// @file The run of one problem, as `feticon run` does it and as a library call: the problem
/// (a built-in one, a problem file, an input deck or YAML / JSON text), the settings' overrides,
/// the solve, and its results: the results folder if one is given, and in memory always.
///
/// Usage (C++; python/feticon does the same from Python):
///   feticon::app::RunOptions options;
///   options.overrides = {"load_steps=2"};   // as --set
///   options.output.clear();                 // no files: results in memory only
///   const feticon::app::RunResult result = feticon::app::run_problem(options);
///   double p = result.summary["hertz"]["p_peak_computed"];

#include "fem/problem.hpp"
#include "nonlinear/contact_pressure.hpp"
#include "nonlinear/contact_solution.hpp"

#include <nlohmann/json.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace feticon::app
{
struct RunOptions
{
  std::string problem_file;                ///< problem file or input deck; empty: the defaults (Hertz)
  std::optional<std::string> problem_text; ///< the problem as YAML / JSON text instead of a file
  std::string output = "results";          ///< results folder; empty: no files are written
  std::vector<std::string> overrides;      ///< KEY=VALUE, as --set
  std::string restart;                     ///< results folder of an interrupted run to continue
  bool quiet = false;
  bool verbose = false;
  bool overwrite = false; ///< replace another run's results in the output folder
};

/// What a completed run holds in memory: summary.json's content, the model and its solution
/// (displacements u, three per node in node order; contact multipliers), and the contact
/// pressure of each slave node of each pair (contact_pressure.csv's rows).
struct RunResult
{
  nlohmann::ordered_json summary;
  std::shared_ptr<const fem::Problem> problem;
  nonlinear::ContactSolution solution;
  std::vector<nonlinear::PressureSample> pressures;
  fem::Kinematics kinematics = fem::Kinematics::linear;
};

/// Runs the problem of `options`; throws feticon::Error with a one-line message on bad input
/// and when the solve does not complete (its converged steps are in the results folder).
RunResult run_problem(const RunOptions& options);
} // namespace feticon::app

#pragma once
/// @file From settings to what a solver takes: the problem and the solver settings, shared by
/// `feticon run`, `feticon bench` and `feticon export` so that all solve the same thing for the
/// same file.

#include "app/feti_choice.hpp"
#include "fem/problem.hpp"
#include "io/problem_file.hpp"
#include "io/settings.hpp"
#include "nonlinear/solver_settings.hpp"
#include "problems/built_in_problem.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace feticon::app
{
/// The problem file at `path` (empty: the defaults) with `overrides`, knowing the built-in
/// problems' keys.
io::ProblemFile load_problem(const std::filesystem::path& path, const std::vector<std::string>& overrides);

/// The size of the mesh `build_problem` would make, known before it is made (memory guard):
/// from the built-in problem, the boxes of a custom file or a Gmsh file's header.
problems::MeshPrediction predict_mesh(const io::ProblemFile& file);

/// The problem of `problem`: a built-in one, else the file's custom sections or input deck; a
/// deck's numbering, steps and warnings go to `deck` if given.
fem::Problem build_problem(const io::ProblemFile& file, io::DeckInfo* deck = nullptr);

/// Solver settings of the method, QP, contact, Newton and decomposition settings, with the
/// subdomain count and the preconditioner of `feti` (choose_feti on the model size).
nonlinear::SolverSettings solver_settings(const io::Settings& settings, const FetiChoice& feti);

} // namespace feticon::app

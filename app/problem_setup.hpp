#pragma once
/// @file From settings to what a solver takes: the problem and the solver settings, shared by
/// `feticon run` and `feticon bench` so that both solve the same thing for the same file.

#include "fem/problem.hpp"
#include "io/problem_file.hpp"
#include "io/settings.hpp"
#include "nonlinear/solver_settings.hpp"
#include "problems/hertz.hpp"
#include "problems/hertz3d.hpp"

namespace feticon::app
{
/// The Hertz parameters of the `hertz.*` and `material.*` settings.
problems::HertzParameters hertz_parameters(const io::Settings& settings);
problems::Hertz3dParameters hertz3d_parameters(const io::Settings& settings);

/// The size of the mesh `build_problem` would make, known before it is made (memory guard):
/// counted for the built-in meshes and boxes (estimated for Hertz's Gmsh mesh from its size
/// field), declared in a Gmsh file's header.
struct MeshPrediction
{
  int64_t nodes = 0;
  bool plane_strain = false;
};
MeshPrediction predict_mesh(const io::ProblemFile& file);

/// The problem of `problem`: built-in hertz or cantilever_obstacle, else the file's custom
/// sections or input deck; a deck's numbering, steps and warnings go to `deck` if given.
fem::Problem build_problem(const io::ProblemFile& file, io::DeckInfo* deck = nullptr);

/// Solver settings of the method, QP, contact, Newton and decomposition settings; with
/// `subdomain_cells` > 0 the subdomain count follows from the problem's cell count.
nonlinear::SolverSettings solver_settings(const io::Settings& settings, const fem::Problem& problem);

} // namespace feticon::app

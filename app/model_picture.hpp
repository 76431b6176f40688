#pragma once
/// @file The pictures of a run (model.png, contact.png, drawn by scripts/plot_model.py): what
/// they show, extracted here because only the surface is drawn. The boundary faces of the mesh
/// (each face of a cell that no other cell shares) by their corners, with the von Mises stress
/// of their cell; the slave faces of every contact pair split into triangles, with the nodal
/// contact pressure; the reference points of sliding nodes. Written as NumPy .npy files and a
/// meta.json into a folder that the script reads and the run then removes.

#include "fem/problem.hpp"
#include "nonlinear/contact_pressure.hpp"
#include "nonlinear/contact_solution.hpp"

#include <filesystem>
#include <vector>

namespace feticon::app
{
/// @param[in] dir  the folder to write (made if missing)
/// @param[in] samples  the contact pressure samples of every pair (their `slipping` flags)
/// @param[in] si_units  false for a deck's model, whose units are its own
void write_picture_data(const std::filesystem::path& dir, const fem::Problem& problem,
                        const nonlinear::ContactSolution& solution, fem::Kinematics kinematics,
                        const std::vector<nonlinear::PressureSample>& samples, bool si_units);

/// Runs scripts/plot_model.py on `dir` (written by write_picture_data) to draw
/// out_dir/model.png and out_dir/contact.png; a warning, no error, if it cannot.
void draw_model_pictures(const std::filesystem::path& dir, const std::filesystem::path& out_dir);
} // namespace feticon::app

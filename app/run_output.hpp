#pragma once
/// @file Writing a run's results folder: VTU/PVD per converged step, CSV, summary.json.

#include "common/timer.hpp"
#include "fem/problem.hpp"
#include "io/vtu.hpp"
#include "nonlinear/contact_pressure.hpp"
#include "nonlinear/contact_solution.hpp"

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>

namespace feticon::app
{
/// VTU of one converged load step: displacement, Cauchy and von Mises stress per cell,
/// contact pressure at the slave nodes; deformed points for large displacements.
/// @param cells the cells to write (a rank's piece under MPI); empty: the whole mesh
void write_step_vtu(const std::filesystem::path& path, const fem::Problem& problem,
                    const nonlinear::ContactSolution& solution, fem::Kinematics kinematics,
                    const std::vector<int32_t>& cells = {});

/// The .pvtu joining the per-rank pieces of one step written by write_step_vtu.
void write_step_pvtu(const std::filesystem::path& path, const fem::Problem& problem,
                     const std::vector<std::string>& pieces);

/// contact_pressure.csv: position, force, area, pressure from multipliers, from stresses,
/// McEwen's (Hertz only; 0 otherwise); with `friction` also the shear traction (Pa),
/// Cattaneo-Mindlin's along x (Hertz with a tangential load; 0 otherwise) and 1 for a sliding
/// sample.
void write_pressure_csv(const std::filesystem::path& path, const std::vector<nonlinear::PressureSample>& samples,
                        bool friction = false);

/// history.csv: one line per outer iteration.
void write_history_csv(const std::filesystem::path& path, const std::vector<nonlinear::OuterIteration>& history);

/// The end-of-run table: sizes, load steps, contact figures, timings, memory, all taken from
/// summary.json so the two always agree, and a built-in problem's `theory_line` (its
/// comparison with theory, also in summary.json) if not empty.
std::string format_summary(const nlohmann::ordered_json& summary, const std::string& theory_line);

/// PNG plots of the results folder (pressure along the contact, iterations) drawn by
/// scripts/plot_hertz.py with Debian's /usr/bin/python3; a warning, not an error, if that
/// is not possible.
void plot_results(const std::filesystem::path& out_dir);

/// Runs scripts/`name` with `arguments` under /usr/bin/python3 (the source tree's scripts, else
/// the installed ones), its output discarded; a warning if it cannot run or fails.
void run_plot_script(const std::string& name, const std::vector<std::string>& arguments);

/// Makes `out_dir` ready for a new run. A folder holding another run's results (any file
/// feticon writes: summary.json, problem.yaml, step_*.vtu, ...) is refused with a one-line
/// error unless `overwrite`, which first removes those files (and only those), so no stale
/// step of the earlier run stays beside the new ones.
void prepare_output_folder(const std::filesystem::path& out_dir, bool overwrite);

/// Writes JSON atomically with 2-space indentation.
void write_json(const std::filesystem::path& path, const nlohmann::ordered_json& json);
} // namespace feticon::app

/// `feticon run`: solve a problem and write its results folder (app/run.hpp).

#include "app/commands.hpp"
#include "app/run.hpp"
#include "io/settings.hpp"
#include "problems/built_in_problem.hpp"

#include <memory>

namespace feticon::app
{
void register_run_command(CLI::App& app)
{
  auto options = std::make_shared<RunOptions>();
  CLI::App* cmd = app.add_subcommand("run",
                                     "Solve a contact problem (default: Vondrák et al.'s Hertz "
                                     "benchmark) and write a results folder");
  // No CLI11 file check: feticon's own one-line error names a missing file.
  cmd->add_option("problem", options->problem_file,
                  "problem file (YAML) or CalculiX / Abaqus input deck (.inp); omit for the built-in Hertz problem");
  cmd->add_option("--output,-o", options->output, "results folder")->capture_default_str();
  cmd->add_option("--set,-s", options->overrides, "override a setting, KEY=VALUE (repeatable)");
  cmd->add_option("--restart", options->restart,
                  "continue the interrupted run whose results folder is DIR from its last "
                  "converged load step (the folder keeps problem.yaml and checkpoint.bin)");
  cmd->add_flag("--overwrite", options->overwrite,
                "replace the results of an earlier run in the output folder (its feticon files are "
                "removed first; without this flag such a folder is refused)");
  cmd->add_flag("--quiet,-q", options->quiet, "only warnings and errors");
  cmd->add_flag("--verbose,-v", options->verbose, "also one line per QP iteration");
  cmd->footer(
      "Settings (KEY for --set or the problem file; nested YAML maps give dotted keys):\n" +
      io::Settings(problems::setting_specs()).help() +
      "Sections of a custom problem (problem: custom), overridable as --set path.to.key=VALUE\n"
      "(list items by index, e.g. loads.0.traction=[0,0,-2e8]):\n"
      "  mesh: {file: MESH.msh} or {boxes: [{name, origin: [x,y,z], lengths: [..], cells: [nx,ny,nz]}]}\n"
      "  bodies: {NAME: {young: PA, poisson: NU, density: KG_M3}}  one entry per body (density for body loads)\n"
      "  plane_strain: true|false                    u_z = 0 everywhere, eliminated\n"
      "  supports: [{set: NODESET, x: M, y: M, z: M}] prescribed components (m)\n"
      "  loads: [{set: FACESET, traction: [tx, ty, tz]}] dead traction (Pa), or a body load:\n"
      "         {gravity: [gx, gy, gz], body: NAME} (m/s^2; body optional: all) or\n"
      "         {centrifugal: {omega: RAD_S, point: [x,y,z], axis: [ax,ay,az]}, body: NAME}\n"
      "         (both need density: KG_M3 in bodies.NAME)\n"
      "  contact: [{slave: FACESET, master: FACESET}]\n"
      "See examples/ for complete files.");
  cmd->callback([options] { run_problem(*options); });
}
} // namespace feticon::app

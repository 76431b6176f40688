#pragma once
/// @file The results of a deck run in the files CalculiX users read: MODEL.frd (nodal
/// displacements, stresses, reaction forces and contact, every converged load step) and
/// MODEL.dat (the deck's *NODE PRINT, *EL PRINT and *CONTACT PRINT requests in ccx's layout),
/// beside the results folder's own files.

#include "fem/problem.hpp"
#include "io/dat_writer.hpp"
#include "io/deck.hpp"
#include "io/frd_writer.hpp"
#include "nonlinear/contact_solution.hpp"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace feticon::app
{
/// CalculiX's RF: f_int(u) + B_I' lambda (the internal force less the contact force on the
/// body), the support reactions plus the applied nodal loads, 3 per mesh node.
la::Vector calculix_reaction(const fem::Problem& problem, const nonlinear::ContactSolution& solution,
                             fem::Kinematics kinematics);

class CalculixResults
{
public:
  /// Creates OUT/STEM.frd and, if the deck prints anything, OUT/STEM.dat (STEM: the deck's).
  CalculixResults(const std::filesystem::path& out_dir, const fem::Problem& problem, const io::DeckInfo& deck,
                  fem::Kinematics kinematics);
  /// Writes the last converged load step of `solution`.
  void add_step(const nonlinear::ContactSolution& solution);
  /// Warnings of the writers (requests feticon cannot honour), each once.
  const std::vector<std::string>& warnings() const { return _warnings; }

private:
  const fem::Problem& _problem;
  const io::DeckInfo& _deck;
  fem::Kinematics _kinematics;
  std::unique_ptr<io::FrdWriter> _frd;
  std::unique_ptr<io::DatWriter> _dat;
  std::vector<std::string> _warnings;
};
} // namespace feticon::app

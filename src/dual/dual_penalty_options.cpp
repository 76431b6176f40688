#include "dual/dual_penalty_problem.hpp"

namespace feticon::dual
{
DualPenaltyOptions::DualPenaltyOptions() : DualPenaltyOptions(io::Settings{}) {}

DualPenaltyOptions::DualPenaltyOptions(const io::Settings& s)
{
  method = s.text("method") == "dual_penalty" ? DualMethod::dual_penalty : DualMethod::smalbe;
  rho = s.number("rho");
  smalbe_M0 = s.number("smalbe.M0");
  smalbe_beta = s.number("smalbe.beta");
  rtol = s.number("qp.rtol");
  max_iterations = s.integer("qp.max_iterations");
  expansion = qp::expansion_from_name(s.text("qp.expansion"));
  const std::string& name = s.text("qp.preconditioner");
  // auto: the Dirichlet one unless app::choose_feti resolves it (SolverSettings).
  preconditioner = name == "lumped" ? DualPreconditioner::lumped
      : name == "none"              ? DualPreconditioner::none
                                    : DualPreconditioner::dirichlet;
  constraint_scaling = s.flag("qp.constraint_scaling");
  spectrum_steps = s.integer("qp.spectrum_steps");
}
} // namespace feticon::dual

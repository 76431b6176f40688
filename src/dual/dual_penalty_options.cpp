#include "dual/dual_penalty_problem.hpp"

namespace feticon::dual
{
DualPenaltyOptions::DualPenaltyOptions() : DualPenaltyOptions(io::Settings{}) {}

DualPenaltyOptions::DualPenaltyOptions(const io::Settings& s)
{
  method = s.text("method") == "dual_penalty" ? DualMethod::dual_penalty : DualMethod::smalbe;
  // The dual penalty's feasibility error falls like 1 / rho (0.27 / rho on Hertz, 0.37 / rho on
  // hertz3d at 121k DOFs; docs/contact.md): unless given, rho = 1e3 keeps it under
  // contact.feasibility_tolerance (1e-3). SMALBE-M is exact at any rho, and fastest at 1.
  rho = method == DualMethod::dual_penalty && !s.given("rho") ? 1e3 : s.number("rho");
  smalbe_M0 = s.number("smalbe.M0");
  smalbe_beta = s.number("smalbe.beta");
  smalbe_rho_growth = s.is_auto("smalbe.rho_growth") ? 0.0 : s.number("smalbe.rho_growth");
  rtol = s.number("qp.rtol");
  force_rtol = s.number("qp.force_rtol");
  max_iterations = s.integer("qp.max_iterations");
  // auto: std unless app::choose_feti resolves it (SolverSettings).
  expansion =
      s.is_auto("qp.expansion") ? qp::MprgpExpansion::standard : qp::expansion_from_name(s.text("qp.expansion"));
  const std::string& name = s.text("qp.preconditioner");
  // auto: the Dirichlet one unless app::choose_feti resolves it (SolverSettings).
  preconditioner = name == "lumped" ? DualPreconditioner::lumped
      : name == "none"              ? DualPreconditioner::none
                                    : DualPreconditioner::dirichlet;
  constraint_scaling = s.flag("qp.constraint_scaling");
  spectrum_steps = s.integer("qp.spectrum_steps");
}
} // namespace feticon::dual

/// feticon: frictionless contact of elastic bodies with large displacements by FETI.
///
/// Every error ends here as one line on stderr and a non-zero exit status.

#include "app/commands.hpp"
#include "common/error.hpp"
#include "common/log.hpp"
#include "par/communicator.hpp"

#include <iostream>

namespace
{
/// One line on stderr; under MPI with the rank, and the other ranks are ended (an error on
/// one rank must not leave the others waiting in a collective).
int fail(const char* what, int code)
{
  const feticon::par::Communicator world = feticon::par::Communicator::world();
  if (world.serial())
  {
    std::cerr << "feticon: error: " << what << '\n';
    return code;
  }
  std::cerr << "feticon: error (rank " << world.rank() << "): " << what << std::endl;
  world.abort(code);
}
} // namespace

int main(int argc, char** argv)
{
  feticon::par::Environment mpi(argc, argv);
  feticon::log::set_rank(feticon::par::Communicator::world().rank());
  CLI::App app{"feticon: frictionless contact of elastic bodies with large displacements "
               "by FETI domain decomposition (dual penalty + MPRGP)"};
  app.require_subcommand(1);
  feticon::app::register_run_command(app);
  feticon::app::register_qp_command(app);
  feticon::app::register_export_command(app);
  feticon::app::register_bench_command(app);
  try
  {
    app.parse(argc, argv);
  }
  catch (const CLI::ParseError& e)
  {
    return app.exit(e);
  }
  catch (const feticon::Error& e)
  {
    return fail(e.what(), 1);
  }
  catch (const std::exception& e)
  {
    return fail(e.what(), 2);
  }
  return 0;
}

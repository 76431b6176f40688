/// feticon: frictionless contact of elastic bodies with large displacements by FETI.
///
/// Every error ends here as one line on stderr and a non-zero exit status.

#include "app/commands.hpp"
#include "common/error.hpp"

#include <iostream>

int main(int argc, char** argv)
{
  CLI::App app{"feticon: frictionless contact of elastic bodies with large displacements "
               "by FETI domain decomposition (dual penalty + MPRGP)"};
  app.require_subcommand(1);
  feticon::app::register_run_command(app);
  feticon::app::register_qp_command(app);
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
    std::cerr << "feticon: error: " << e.what() << '\n';
    return 1;
  }
  catch (const std::exception& e)
  {
    std::cerr << "feticon: error: " << e.what() << '\n';
    return 2;
  }
  return 0;
}

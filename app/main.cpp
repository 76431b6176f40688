/// feticon: frictionless contact of elastic bodies with large displacements by FETI.
///
/// Every error ends here as one line on stderr and a non-zero exit status.

#include "app/commands.hpp"
#include "common/error.hpp"
#include "common/log.hpp"
#include "la/blas_core.hpp"
#include "par/communicator.hpp"

#include <cstdio>
#include <malloc.h>
#include <iostream>
#include <string>
#include <unistd.h>

namespace
{
/// `what` with its control characters escaped (\n, \r, \t, \xNN): messages quote the input,
/// which may hold any byte, and an error stays one line on any terminal.
std::string one_line(const char* what)
{
  std::string out;
  for (const char* c = what; *c; ++c)
  {
    const auto byte = static_cast<unsigned char>(*c);
    if (byte >= 0x20 && byte != 0x7f)
      out += *c;
    else if (byte == '\n')
      out += "\\n";
    else if (byte == '\r')
      out += "\\r";
    else if (byte == '\t')
      out += "\\t";
    else
    {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", byte);
      out += hex;
    }
  }
  return out;
}

/// One line on stderr; under MPI with the rank, and the other ranks are ended (an error on
/// one rank must not leave the others waiting in a collective).
int fail(const char* raw, int code)
{
  const std::string what = one_line(raw);
  const feticon::par::Communicator world = feticon::par::Communicator::world();
  if (world.serial())
  {
    std::cerr << "feticon: error: " << what << '\n';
    return code;
  }
  // One write(2): mpirun forwards each rank's stderr in the chunks it reads, and its abort
  // banner would otherwise land in the middle of a line written piece by piece.
  const std::string line = "feticon: error (rank " + std::to_string(world.rank()) + "): " + what + '\n';
  [[maybe_unused]] const ssize_t written = ::write(STDERR_FILENO, line.data(), line.size());
  world.abort(code);
}

/// Freed memory stays with the allocator for the next allocation of its size. By default
/// glibc maps blocks over 128 KiB (adapting up to 32 MiB) afresh and unmaps them on free, and
/// every page of the next one faults in again: the stiffness copies, factor workspaces and
/// dense blocks of each outer iteration. Page faults are dear on virtual machines
/// (docs/measurements.md).
void keep_freed_memory()
{
  mallopt(M_MMAP_THRESHOLD, 32 << 20); // glibc's largest; bigger blocks are still mapped
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
}
} // namespace

int main(int argc, char** argv)
{
  feticon::la::rerun_with_better_blas_core(argv); // before any thread, MPI or output
  keep_freed_memory();
  feticon::par::Environment mpi(argc, argv);
  feticon::log::set_rank(feticon::par::Communicator::world().rank());
  CLI::App app{"feticon: contact of solid bodies with friction and large displacements "
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

/// feticon from C++: the Hertz benchmark of Vondrák et al. run through the library, then the
/// same problem at half the load, each compared with Hertz's peak pressure.
///
/// Steps: 1. options as `feticon run` takes them (no results folder: the results stay in
/// memory); 2. run; 3. read the summary and the contact pressures.

#include <app/run.hpp>
#include <common/error.hpp>

#include <cstdio>

int main()
{
  try
  {
    for (const char* load : {"4e8", "2e8"})
    {
      // 1. The built-in Hertz problem with one setting overridden, as --set does.
      feticon::app::RunOptions options;
      options.overrides = {std::string("hertz.line_load=") + load};
      options.output.clear();
      options.quiet = true;
      // 2. The solve.
      const feticon::app::RunResult result = feticon::app::run_problem(options);
      // 3. The results: summary.json's figures and contact_pressure.csv's rows.
      const auto& hertz = result.summary["hertz"];
      std::printf("Q = %s N/m: p_peak %.6e Pa, Hertz p0 %.6e Pa, %zu slave nodes, %d MPRGP iterations\n", load,
                  hertz["p_peak_computed"].get<double>(), hertz["p0_analytic"].get<double>(), result.pressures.size(),
                  result.summary["qp"]["iterations"].get<int>());
    }
  }
  catch (const feticon::Error& e)
  {
    std::fprintf(stderr, "hertz_example: %s\n", e.what());
    return 1;
  }
  return 0;
}

#include "app/run_output.hpp"

#include "contact/contact_constraints.hpp"
#include "fem/stress.hpp"
#include "fem/hex8_element.hpp"
#include "common/error.hpp"
#include "common/log.hpp"
#include "common/atomic_file.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <numeric>
#include <sstream>

extern char** environ; // the environment passed on to the plotting script

namespace feticon::app
{
namespace
{
/// Names and components of the step fields (values empty), shared by pieces and .pvtu.
struct StepFields
{
  io::VtuField displacement{"displacement", 3, {}}, pressure{"contact_pressure", 1, {}};
  /// The contact pair whose slave surface holds the node (its index in fem::Problem::contacts);
  /// -1 on no slave surface.
  io::VtuField contact_pair{"contact_pair", 1, {}};
  io::VtuField cauchy{"cauchy_stress", 6, {}}, mises{"von_mises", 1, {}};
  io::VtuField temperature_change{"temperature_change", 1, {}}; ///< T - T_0 (K), written when the problem has one
  /// The mean equivalent plastic strain of each cell's points, written when a body is plastic.
  io::VtuField plastic_strain{"equivalent_plastic_strain", 1, {}};

  std::vector<io::VtuField> point_fields(bool thermal) const
  {
    std::vector<io::VtuField> fields{displacement, pressure, contact_pair};
    if (thermal)
      fields.push_back(temperature_change);
    return fields;
  }
  std::vector<io::VtuField> cell_fields(bool plastic) const
  {
    std::vector<io::VtuField> fields{cauchy, mises};
    if (plastic)
      fields.push_back(plastic_strain);
    return fields;
  }
};
} // namespace

void write_step_vtu(const std::filesystem::path& path, const fem::Problem& problem,
                    const nonlinear::ContactSolution& solution, fem::Kinematics kinematics,
                    const std::vector<int32_t>& cells)
{
  std::vector<int32_t> node_of_local;
  const mesh::Mesh piece = cells.empty() ? mesh::Mesh{} : mesh::submesh(problem.mesh, cells, node_of_local);
  const mesh::Mesh& mesh = cells.empty() ? problem.mesh : piece;
  if (cells.empty())
  {
    node_of_local.resize(mesh.n_nodes());
    std::iota(node_of_local.begin(), node_of_local.end(), 0);
  }
  std::vector<int32_t> local_of_node(problem.mesh.n_nodes(), -1);
  la::Vector u(3 * static_cast<la::Index>(node_of_local.size()));
  for (size_t k = 0; k < node_of_local.size(); ++k)
  {
    local_of_node[node_of_local[k]] = static_cast<int32_t>(k);
    u.segment<3>(3 * static_cast<la::Index>(k)) = solution.u.segment<3>(3 * node_of_local[k]);
  }
  la::Vector dT;
  if (solution.temperature_change.size() > 0)
  {
    dT.resize(static_cast<la::Index>(node_of_local.size()));
    for (size_t k = 0; k < node_of_local.size(); ++k)
      dT(static_cast<la::Index>(k)) = solution.temperature_change(node_of_local[k]);
  }
  StepFields f;
  f.displacement.values.assign(u.data(), u.data() + u.size());
  f.temperature_change.values.assign(dT.data(), dT.data() + dT.size());
  const fem::MeshPlasticStates plastic = cells.empty() ? solution.plastic : solution.plastic.subset(cells);
  for (int32_t c = 0; !plastic.empty() && c < mesh.n_cells(); ++c)
    f.plastic_strain.values.push_back(plastic.mean_equivalent_plastic_strain(c));
  for (const auto& s : fem::cell_cauchy_stresses(mesh, u, problem.materials, kinematics, dT, &plastic))
  {
    // VTK's symmetric tensor order: xx, yy, zz, xy, yz, xz (feticon Voigt: 11,22,33,12,23,31).
    for (int k = 0; k < 6; ++k)
      f.cauchy.values.push_back(s(k));
    f.mises.values.push_back(fem::von_mises(s));
  }
  const std::vector<double> pressure = nonlinear::row_pressure_per_node(solution, problem.mesh.n_nodes());
  for (const int32_t node : node_of_local)
    f.pressure.values.push_back(pressure[node]);
  f.contact_pair.values.assign(mesh.n_nodes(), -1.0);
  for (size_t p = 0; p < problem.contacts.size(); ++p)
  {
    const fem::ContactPairNames& pair = problem.contacts[p];
    for (int32_t node : contact::slave_nodes(problem.mesh, {pair.slave, pair.master, pair.slave_nodes}))
      if (local_of_node[node] >= 0)
        f.contact_pair.values[local_of_node[node]] = static_cast<double>(p);
  }
  if (kinematics == fem::Kinematics::total_lagrangian)
  {
    io::PointMatrix x = mesh.nodes;
    for (int32_t n = 0; n < mesh.n_nodes(); ++n)
      x.row(n) += u.segment<3>(3 * n).transpose();
    const Eigen::Ref<const io::PointMatrix> ref(x);
    io::write_vtu(path, mesh, &ref, f.point_fields(dT.size() > 0), f.cell_fields(!plastic.empty()));
  }
  else
    io::write_vtu(path, mesh, nullptr, f.point_fields(dT.size() > 0), f.cell_fields(!plastic.empty()));
}

void write_step_pvtu(const std::filesystem::path& path, const fem::Problem& problem,
                     const std::vector<std::string>& pieces)
{
  const StepFields f;
  io::write_pvtu(path, pieces, problem.mesh, f.point_fields(problem.has_temperatures()),
                 f.cell_fields(problem.has_plastic_body()));
}

void write_pressure_csv(const std::filesystem::path& path, const std::vector<nonlinear::PressureSample>& samples,
                        bool friction)
{
  std::ostringstream os;
  os << "pair,x_m,y_m,z_m,force_N,area_m2,pressure_multipliers_Pa,pressure_stress_Pa,pressure_analytic_Pa,"
        "x_deformed_m,y_deformed_m";
  os << (friction ? ",shear_x_Pa,shear_y_Pa,shear_z_Pa,shear_analytic_x_Pa,slip\n" : "\n");
  char line[480];
  for (const auto& s : samples)
  {
    std::snprintf(line, sizeof line, "%d,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e", s.pair, s.x, s.y, s.z,
                  s.force, s.area, s.pressure, s.stress_pressure, s.analytic, s.deformed_x, s.deformed_y);
    os << line;
    if (friction)
    {
      std::snprintf(line, sizeof line, ",%.9e,%.9e,%.9e,%.9e,%d", s.shear.x(), s.shear.y(), s.shear.z(),
                    s.shear_analytic, s.slipping ? 1 : 0);
      os << line;
    }
    os << '\n';
  }
  feticon::write_file_atomically(path, os.str());
}

void write_history_csv(const std::filesystem::path& path, const std::vector<nonlinear::OuterIteration>& history)
{
  std::ostringstream os;
  os << "load_step,outer_iteration,mprgp_iterations,hessian_multiplications,smalbe_outer,"
        "residual_norm,displacement_change,active_contacts,feasibility_error,seconds\n";
  for (const auto& it : history)
    os << it.load_step << ',' << it.iteration << ',' << it.qp.iterations << ',' << it.qp.hessian_multiplications << ','
       << it.qp.outer_iterations << ',' << it.residual_norm << ',' << it.displacement_change << ','
       << it.active_contacts << ',' << it.feasibility_error << ',' << it.seconds << '\n';
  feticon::write_file_atomically(path, os.str());
}

std::string format_summary(const nlohmann::ordered_json& s, const std::string& theory_line)
{
  std::ostringstream os;
  char line[256];
  auto put = [&](const char* format, auto... values) {
    std::snprintf(line, sizeof line, format, values...);
    os << line << '\n';
  };
  os << "\n---------------------------------------------------------------- summary\n";
  put("problem %s, method %s, %s displacements, converged: %s", s["problem"].get<std::string>().c_str(),
      s["method"].get<std::string>().c_str(), s["displacements"].get<std::string>().c_str(),
      s["converged"].get<bool>() ? "yes" : "NO");
  put("DOFs %ld, elements %ld, subdomains %ld, dual size %ld, coarse size %ld", s["degrees_of_freedom"].get<long>(),
      s["elements"].get<long>(), s["subdomains"].get<long>(), s["dual_size"].get<long>(), s["coarse_size"].get<long>());
  put("%-6s %-12s %-8s %-12s %-10s", "step", "load factor", "outer", "inner total", "converged");
  int step = 0;
  for (const auto& st : s["steps"])
  {
    int inner = 0;
    for (int i : st["inner_iterations"])
      inner += i;
    put("%-6d %-12.4g %-8d %-12d %-10s", ++step, st["load_factor"].get<double>(), st["outer_iterations"].get<int>(),
        inner, st["converged"].get<bool>() ? "yes" : "no");
  }
  put("MPRGP steps %d (CG %d, expansion %d, proportioning %d), operator products %d", s["qp"]["iterations"].get<int>(),
      s["qp"]["cg_steps"].get<int>(), s["qp"]["expansion_steps"].get<int>(), s["qp"]["proportioning_steps"].get<int>(),
      s["qp"]["hessian_multiplications"].get<int>());
  if (s.contains("contact"))
  {
    const auto& c = s["contact"];
    put("contact: force %.6g N, peak pressure %.4g MPa, area %.4g m^2, %ld active rows, "
        "feasibility %.1e",
        c["total_normal_force"].get<double>(), c["peak_pressure"].get<double>() / 1e6, c["contact_area"].get<double>(),
        c["active_constraints"].get<long>(), c["feasibility_error"].get<double>());
  }
  if (!theory_line.empty())
    os << theory_line << '\n';
  os << "time (s):";
  for (const auto& [phase, seconds] : s["timings_seconds"].items())
  {
    std::snprintf(line, sizeof line, " %s %.3f;", phase.c_str(), seconds.get<double>());
    os << line;
  }
  os << '\n';
  put("peak memory %.1f MiB", s["peak_memory_bytes"].get<double>() / (1024.0 * 1024.0));
  return os.str();
}

void run_plot_script(const std::string& name, const std::vector<std::string>& arguments)
{
  // The source tree's scripts (a build tree's runs), else the installed ones.
  std::filesystem::path script = std::filesystem::path(FETICON_SOURCE_DIR) / "scripts" / name;
  if (!std::filesystem::exists(script))
    script = std::filesystem::path(FETICON_SCRIPTS_INSTALL_DIR) / name;
  std::string python = "/usr/bin/python3";
  if (!std::filesystem::exists(python) || !std::filesystem::exists(script))
  {
    log::warning("no PNG plots: " + python + " or " + script.string() + " is missing");
    return;
  }
  // An argument vector, no shell: a folder name reaches the script as it is, whatever quotes
  // or semicolons it holds.
  std::vector<std::string> words = {python, script.string()};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& word : words)
    argv.push_back(word.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t quiet;
  posix_spawn_file_actions_init(&quiet);
  posix_spawn_file_actions_addopen(&quiet, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&quiet, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  int status = 0;
  const bool started = posix_spawn(&pid, python.c_str(), &quiet, nullptr, argv.data(), environ) == 0;
  posix_spawn_file_actions_destroy(&quiet);
  if (!started || waitpid(pid, &status, 0) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    log::warning("no PNG plots: " + script.string() + " failed (python3-matplotlib installed?)");
}

void plot_results(const std::filesystem::path& out_dir) { run_plot_script("plot_hertz.py", {out_dir.string()}); }

namespace
{
/// Whether `name` is a file a run writes into its folder (run_command.cpp, plot_hertz.py,
/// the checkpoint), including the temporaries of atomic writes (NAME.tmp.*).
bool is_result_file(std::string name)
{
  if (const auto tmp = name.find(".tmp."); tmp != std::string::npos)
    name.resize(tmp);
  for (const char* fixed :
       {"summary.json", "problem.yaml", "history.csv", "contact_pressure.csv", "solution.pvd", "checkpoint.bin",
        "contact_pressure.png", "iterations.png", "shear_traction.png", "model.png", "contact.png"})
    if (name == fixed)
      return true;
  // step_NNN.vtu, step_NNN.pvtu, step_NNN_rankNNN.vtu
  auto digits = [&name](size_t from, size_t to) {
    return to > from &&
        std::all_of(name.begin() + from, name.begin() + to, [](unsigned char c) { return std::isdigit(c) != 0; });
  };
  const size_t dot = name.rfind('.');
  if (name.rfind("step_", 0) != 0 || dot == std::string::npos)
    return false;
  const std::string extension = name.substr(dot);
  if (extension != ".vtu" && extension != ".pvtu")
    return false;
  const size_t rank = name.find("_rank");
  return rank == std::string::npos ? digits(5, dot) : extension == ".vtu" && digits(5, rank) && digits(rank + 5, dot);
}
} // namespace

void prepare_output_folder(const std::filesystem::path& out_dir, bool overwrite)
{
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::exists(out_dir, ec))
  {
    FETICON_CHECK(fs::is_directory(out_dir, ec),
                  "the output folder " << out_dir.string() << " exists and is not a folder");
    std::vector<fs::path> results;
    for (const auto& entry : fs::directory_iterator(out_dir, ec))
      if (entry.is_regular_file(ec) && is_result_file(entry.path().filename().string()))
        results.push_back(entry.path());
    FETICON_CHECK(!ec, "cannot read the output folder " << out_dir.string() << ": " << ec.message());
    FETICON_CHECK(results.empty() || overwrite,
                  "the output folder " << out_dir.string() << " holds another run's results ("
                                       << results.front().filename().string()
                                       << "); give --overwrite to replace them, or another --output");
    for (const auto& file : results)
    {
      fs::remove(file, ec);
      FETICON_CHECK(!ec, "--overwrite: cannot remove " << file.string() << ": " << ec.message());
    }
  }
  fs::create_directories(out_dir, ec);
  FETICON_CHECK(!ec, "cannot create the output folder " << out_dir.string() << ": " << ec.message());
}

void write_json(const std::filesystem::path& path, const nlohmann::ordered_json& json)
{
  // A deck's bytes that are not UTF-8 (echoed in a warning) become U+FFFD rather than a failed
  // summary of a completed run.
  feticon::write_file_atomically(path, json.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
}
} // namespace feticon::app

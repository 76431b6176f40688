#include "app/checkpoint.hpp"

#include "common/error.hpp"
#include "common/atomic_file.hpp"

#include <fstream>
#include <nlohmann/json.hpp>

namespace feticon::app
{
namespace
{
constexpr char magic[9] = "FETICKP1";

template <class T>
void write_block(std::ostream& os, const T* data, int64_t count)
{
  os.write(reinterpret_cast<const char*>(&count), sizeof count);
  os.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(count * sizeof(T)));
}

template <class T>
std::vector<T> read_block(std::istream& is, const std::filesystem::path& path)
{
  int64_t count = -1;
  is.read(reinterpret_cast<char*>(&count), sizeof count);
  FETICON_CHECK(is && count >= 0 && count < (int64_t(1) << 36), path.string() << ": truncated or corrupt checkpoint");
  std::vector<T> values(static_cast<size_t>(count));
  is.read(reinterpret_cast<char*>(values.data()), static_cast<std::streamsize>(count * sizeof(T)));
  FETICON_CHECK(is, path.string() << ": truncated checkpoint");
  return values;
}

nlohmann::json records(const nonlinear::ContactSolution& s)
{
  nlohmann::json steps = nlohmann::json::array(), history = nlohmann::json::array();
  for (const auto& st : s.steps)
    steps.push_back({st.load_factor, st.outer_iterations, st.converged, st.displacement_change, st.residual_norm,
                     st.inner_iterations, st.floor});
  for (const auto& it : s.history)
    history.push_back({it.load_step,
                       it.iteration,
                       it.qp.iterations,
                       it.qp.cg_steps,
                       it.qp.expansion_steps,
                       it.qp.proportioning_steps,
                       it.qp.hessian_multiplications,
                       it.qp.outer_iterations,
                       it.residual_norm,
                       it.displacement_change,
                       it.active_contacts,
                       it.feasibility_error,
                       it.seconds,
                       it.qp.ritz.min,
                       it.qp.ritz.max,
                       it.qp.ritz.cg_steps,
                       it.qp.rho_updates,
                       it.final_rho,
                       it.qp.expansion_fallbacks,
                       it.qp.operator_applications,
                       it.qp.operator_seconds,
                       it.qp.preconditioner_applications,
                       it.qp.preconditioner_seconds,
                       it.qp.seconds,
                       it.qp.feasibility_corrections});
  return {{"completed_steps", s.restart.completed_steps},
          {"steps", steps},
          {"history", history},
          {"smalbe_M", s.restart.dual.M},
          {"smalbe_rho", s.restart.dual.rho},
          {"pfp_norm", s.restart.dual.operator_norm},
          {"escalated", s.restart.escalated},
          {"warnings", s.warnings}};
}
/// One outer iteration of the records' history, as records() wrote it (rows of older
/// checkpoints are shorter: what they lack stays 0).
nonlinear::OuterIteration outer_iteration_record(const nlohmann::json& h)
{
  nonlinear::OuterIteration it;
  it.load_step = h[0];
  it.iteration = h[1];
  it.qp.iterations = h[2];
  it.qp.cg_steps = h[3];
  it.qp.expansion_steps = h[4];
  it.qp.proportioning_steps = h[5];
  it.qp.hessian_multiplications = h[6];
  it.qp.outer_iterations = h[7];
  it.residual_norm = h[8];
  it.displacement_change = h[9];
  it.active_contacts = h[10];
  it.feasibility_error = h[11];
  it.seconds = h[12];
  if (h.size() > 15) // written since the spectrum estimate exists
  {
    it.qp.ritz.min = h[13];
    it.qp.ritz.max = h[14];
    it.qp.ritz.cg_steps = h[15];
  }
  if (h.size() > 17) // written since SMALBE-M reports its rho
  {
    it.qp.rho_updates = h[16];
    it.final_rho = h[17];
  }
  if (h.size() > 23) // written since the counters are one type (all of them restored)
  {
    it.qp.expansion_fallbacks = h[18];
    it.qp.operator_applications = h[19];
    it.qp.operator_seconds = h[20];
    it.qp.preconditioner_applications = h[21];
    it.qp.preconditioner_seconds = h[22];
    it.qp.seconds = h[23];
  }
  if (h.size() > 24) // written since SMALBE-M's feasibility correction exists
    it.qp.feasibility_corrections = h[24];
  return it;
}
} // namespace

void write_checkpoint(const std::filesystem::path& path, const nonlinear::ContactSolution& solution)
{
  const auto& r = solution.restart;
  // Warnings echo deck bytes that need not be UTF-8: replaced (U+FFFD), not a failed checkpoint.
  const std::string json = records(solution).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  feticon::write_file_atomically(path, [&](std::ostream& os) {
    os.write(magic, 8);
    write_block(os, r.u_stacked.data(), r.u_stacked.size());
    write_block(os, r.dual.x.data(), r.dual.x.size());
    write_block(os, r.contact_slave.data(), static_cast<int64_t>(r.contact_slave.size()));
    write_block(os, r.contact_lambda.data(), static_cast<int64_t>(r.contact_lambda.size()));
    write_block(os, json.data(), static_cast<int64_t>(json.size()));
    // Last, so that checkpoints written before it existed still read (their runs continue
    // with a cold SMALBE-M start).
    write_block(os, r.dual.omega.data(), r.dual.omega.size());
    write_block(os, r.schur_boundary.data(), static_cast<int64_t>(r.schur_boundary.size()));         // likewise
    write_block(os, r.contact_tangential.data(), static_cast<int64_t>(r.contact_tangential.size())); // likewise
    write_block(os, r.contact_pair.data(), static_cast<int64_t>(r.contact_pair.size()));             // likewise
    write_block(os, r.plastic.data(), static_cast<int64_t>(r.plastic.size()));                       // likewise
    write_block(os, r.linear_rows_selected.data(), static_cast<int64_t>(r.linear_rows_selected.size()));
    write_block(os, r.stage_start.data(), static_cast<int64_t>(r.stage_start.size())); // likewise
  });
}

void read_checkpoint(const std::filesystem::path& path, nonlinear::ContactSolution& solution)
{
  FETICON_CHECK(std::filesystem::exists(path),
                "--restart: " << path.parent_path().string() << " has no " << path.filename().string()
                              << ": the run ended before its first load step converged, so there is "
                                 "nothing to continue; start it again (feticon run --overwrite)");
  std::ifstream is(path, std::ios::binary);
  FETICON_CHECK(is, "cannot open the checkpoint " << path.string());
  char head[8];
  is.read(head, 8);
  FETICON_CHECK(is && std::equal(head, head + 8, magic), path.string() << " is not a feticon checkpoint");
  auto& r = solution.restart;
  const auto u = read_block<double>(is, path);
  const auto lambda = read_block<double>(is, path);
  r.u_stacked = Eigen::Map<const la::Vector>(u.data(), static_cast<la::Index>(u.size()));
  r.dual.x = Eigen::Map<const la::Vector>(lambda.data(), static_cast<la::Index>(lambda.size()));
  r.contact_slave = read_block<int32_t>(is, path);
  r.contact_lambda = read_block<double>(is, path);
  const auto text = read_block<char>(is, path);
  nlohmann::json json;
  try
  {
    json = nlohmann::json::parse(std::string(text.begin(), text.end()));
    r.completed_steps = json.at("completed_steps").get<int>();
    r.dual.M = json.value("smalbe_M", 0.0);
    r.dual.rho = json.value("smalbe_rho", 0.0);
    r.dual.operator_norm = json.value("pfp_norm", 0.0);
    r.escalated = json.value("escalated", false);
    solution.steps.clear();
    for (const auto& st : json.at("steps"))
    {
      nonlinear::LoadStep step;
      step.load_factor = st[0].get<double>();
      step.outer_iterations = st[1].get<int>();
      step.converged = st[2].get<bool>();
      step.displacement_change = st[3].get<double>();
      step.residual_norm = st[4].get<double>();
      step.inner_iterations = st[5].get<std::vector<int>>();
      step.floor = st.size() > 6 ? st[6].get<std::string>() : std::string();
      if (!step.floor.empty()) // the run's warnings name the steps that ended at a floor
        solution.warnings.push_back(nonlinear::floor_warning(static_cast<int>(solution.steps.size()) + 1, step));
      solution.steps.push_back(std::move(step));
    }
    solution.history.clear();
    for (const auto& h : json.at("history"))
      solution.history.push_back(outer_iteration_record(h));
    // The run's warnings as they were (cutbacks among them); before they were written, the
    // floors' alone, made from the steps above.
    if (json.contains("warnings"))
      solution.warnings = json.at("warnings").get<std::vector<std::string>>();
  }
  catch (const nlohmann::json::exception& e)
  {
    FETICON_CHECK(false, path.string() << ": corrupt checkpoint records (" << e.what() << ")");
  }
  if (is.peek() != std::char_traits<char>::eof())
  {
    const auto beta = read_block<double>(is, path);
    r.dual.omega = Eigen::Map<const la::Vector>(beta.data(), static_cast<la::Index>(beta.size()));
  }
  if (is.peek() != std::char_traits<char>::eof())
    r.schur_boundary = read_block<int32_t>(is, path);
  if (is.peek() != std::char_traits<char>::eof())
    r.contact_tangential = read_block<double>(is, path);
  if (is.peek() != std::char_traits<char>::eof())
    r.contact_pair = read_block<int32_t>(is, path);
  if (is.peek() != std::char_traits<char>::eof())
    r.plastic = read_block<double>(is, path);
  if (is.peek() != std::char_traits<char>::eof())
    r.linear_rows_selected = read_block<int32_t>(is, path);
  if (is.peek() != std::char_traits<char>::eof())
    r.stage_start = read_block<double>(is, path);
  FETICON_CHECK(r.contact_pair.empty() || r.contact_pair.size() == r.contact_slave.size(),
                path.string() << ": the checkpoint has " << r.contact_pair.size() << " contact pairs for "
                              << r.contact_slave.size() << " contact multipliers");
  FETICON_CHECK(r.completed_steps >= 1 && r.u_stacked.allFinite(),
                path.string() << ": the checkpoint holds no converged step");
}
} // namespace feticon::app

#include "app/checkpoint.hpp"

#include "common/error.hpp"
#include "common/atomic_file.hpp"

#include <fstream>
#include <span>
#include <type_traits>
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

/// Visits the fields of one outer iteration of the history in their order in a checkpoint's row,
/// the one list both the writer and the reader follow (the rows of older checkpoints end after
/// field 13, 16, 18 or 24: what they lack stays 0).
template <class Iteration, class Visit>
void for_each_history_field(Iteration& it, Visit&& visit)
{
  visit(it.load_step);
  visit(it.iteration);
  visit(it.qp.iterations);
  visit(it.qp.cg_steps);
  visit(it.qp.expansion_steps);
  visit(it.qp.proportioning_steps);
  visit(it.qp.hessian_multiplications);
  visit(it.qp.outer_iterations);
  visit(it.residual_norm);
  visit(it.displacement_change);
  visit(it.active_contacts);
  visit(it.feasibility_error);
  visit(it.seconds);
  visit(it.qp.ritz.min);
  visit(it.qp.ritz.max);
  visit(it.qp.ritz.cg_steps);
  visit(it.qp.rho_updates);
  visit(it.final_rho);
  visit(it.qp.expansion_fallbacks);
  visit(it.qp.operator_applications);
  visit(it.qp.operator_seconds);
  visit(it.qp.preconditioner_applications);
  visit(it.qp.preconditioner_seconds);
  visit(it.qp.seconds);
  visit(it.qp.feasibility_corrections);
}
constexpr size_t history_fields = 25; ///< for_each_history_field's count

/// The history as one block of history_fields doubles a row: written as JSON (as older
/// checkpoints have it) it was the cost of a run of many small load steps, the whole history
/// formatted again at every step (fricloop, 310 load steps: 0.66 s of output in 1.84 s).
std::vector<double> history_block(const nonlinear::ContactSolution& s)
{
  std::vector<double> out;
  out.reserve(s.history.size() * history_fields);
  for (const nonlinear::OuterIteration& it : s.history)
    for_each_history_field(it, [&](const auto& field) { out.push_back(static_cast<double>(field)); });
  FETICON_ASSERT(out.size() == s.history.size() * history_fields, "history_fields is not the fields' count");
  return out;
}

nlohmann::json records(const nonlinear::ContactSolution& s)
{
  nlohmann::json steps = nlohmann::json::array();
  for (const auto& st : s.steps)
    steps.push_back({st.load_factor, st.outer_iterations, st.converged, st.displacement_change, st.residual_norm,
                     st.inner_iterations, st.floor});
  return {{"completed_steps", s.restart.completed_steps},
          {"steps", steps},
          {"history_fields", history_fields}, // the history: the last block (history_block)
          {"smalbe_M", s.restart.dual.M},
          {"smalbe_rho", s.restart.dual.rho},
          {"pfp_norm", s.restart.dual.operator_norm},
          {"escalated", s.restart.escalated},
          {"warnings", s.warnings}};
}

/// One outer iteration from its row (for_each_history_field's order; a shorter row of an older
/// checkpoint leaves the rest 0).
nonlinear::OuterIteration outer_iteration_record(std::span<const double> h)
{
  nonlinear::OuterIteration it;
  size_t k = 0;
  for_each_history_field(it, [&](auto& field) {
    if (k < h.size())
      field = static_cast<std::remove_reference_t<decltype(field)>>(h[k]);
    ++k;
  });
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
    const std::vector<double> history = history_block(solution);
    write_block(os, history.data(), static_cast<int64_t>(history.size()));
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
  size_t history_fields_read = 0; // 0: the history is in the JSON (older checkpoints)
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
    history_fields_read = json.value("history_fields", size_t{0});
    if (json.contains("history")) // written before the history was a block of its own
      for (const auto& h : json.at("history"))
        solution.history.push_back(outer_iteration_record(h.get<std::vector<double>>()));
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
  if (history_fields_read > 0)
  {
    const size_t fields = history_fields_read;
    const auto history = read_block<double>(is, path);
    FETICON_CHECK(history.size() % fields == 0,
                  path.string() << ": the checkpoint's history has " << history.size() << " values, not rows of "
                                << fields);
    for (size_t k = 0; k < history.size(); k += fields)
      solution.history.push_back(outer_iteration_record(std::span(history).subspan(k, fields)));
  }
  FETICON_CHECK(r.contact_pair.empty() || r.contact_pair.size() == r.contact_slave.size(),
                path.string() << ": the checkpoint has " << r.contact_pair.size() << " contact pairs for "
                              << r.contact_slave.size() << " contact multipliers");
  FETICON_CHECK(r.completed_steps >= 1 && r.u_stacked.allFinite(),
                path.string() << ": the checkpoint holds no converged step");
}
} // namespace feticon::app

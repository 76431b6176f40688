#pragma once
/// @file Run settings: documented keys with defaults and ranges (solver, output and the
/// built-in problems), filled by io/problem_file from a YAML file (nested maps give dotted
/// keys, e.g. qp: {rtol: 1e-6} is qp.rtol) and command-line overrides. Unknown keys and bad
/// values are errors that name the key, the source and what is expected.

#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <optional>
#include <string>
#include <vector>

namespace feticon::io
{
struct SettingSpec
{
  std::string key;
  /// Empty for an optional number: unset unless given (optional_number).
  std::string default_value;
  std::string help;
  enum class Type
  {
    number,
    integer,
    text,
    boolean
  } type = Type::number;
  std::vector<std::string> choices; ///< for text: allowed values (empty = any)
  double min = -1e300;              ///< for numbers: inclusive range
  double max = 1e300;
  bool min_exclusive = false;
  bool max_exclusive = false;
  /// For an integer: "auto" is also a value (the run chooses; Settings::is_auto).
  bool or_auto = false;
  /// The key overrides the model's own value (each contact pair's interaction) only where it
  /// is given; to_yaml writes it commented out otherwise, so that a rerun keeps the model's.
  bool overrides_model = false;
};

/// The keys of a run at their values. The table is the solver's and the outputs' keys
/// (io/settings.cpp) and those a layer above declares, as deal.II's ParameterHandler takes
/// each class's declarations: the built-in problems (problems::setting_specs) declare their
/// own keys and refine `problem`, whose table here knows only `custom`.
class Settings
{
public:
  /// The solver's and the outputs' keys at their defaults.
  Settings();
  /// Those and `declared`, which come first in the documentation; a declared key replaces the
  /// table's key of that name.
  explicit Settings(std::vector<SettingSpec> declared);
  /// Every key of this table, in documentation order.
  const std::vector<SettingSpec>& specs() const { return *_specs; }
  /// Help text listing every key with default and meaning.
  std::string help() const;

  /// Sets `key` from text; `source` (e.g. "--set" or a file name) names it in errors.
  void set(const std::string& key, const std::string& value, const std::string& source);

  double number(const std::string& key) const;
  /// An optional number: empty if the key was not given.
  std::optional<double> optional_number(const std::string& key) const;
  /// An integer key's value; an error for a key at "auto" (ask is_auto first).
  int integer(const std::string& key) const;
  /// True if `key` (an integer key that allows it) is "auto".
  bool is_auto(const std::string& key) const { return _values.at(key) == "auto"; }
  const std::string& text(const std::string& key) const;
  bool flag(const std::string& key) const;
  /// True if `key` was set (problem file, deck, --set), false if it has its default.
  bool given(const std::string& key) const { return _given.count(key) > 0; }

  /// The effective settings as YAML (written to the results folder).
  std::string to_yaml() const;

  /// The spec of `key`; throws feticon::Error "unknown key" naming `source` if there is none.
  const SettingSpec& spec(const std::string& key, const std::string& source) const;
  /// True if `key` is in the table.
  bool knows(const std::string& key) const;

private:
  std::shared_ptr<const std::vector<SettingSpec>> _specs; ///< shared by copies
  std::map<std::string, std::string> _values;
  std::set<std::string> _given;
};
} // namespace feticon::io

#pragma once
/// @file Typed access to the structured sections of a problem file (io/problem_file.cpp,
/// io/problem_steps.cpp): every error names the file and the key.

#include "common/error.hpp"

#include <Eigen/Core>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <cstdlib>
#include <set>
#include <string>

namespace feticon::io
{
/// Typed access to the structured sections of a problem file, errors naming file and key.
struct ProblemReader
{
  const std::string& source;

  double number(const YAML::Node& node, const std::string& key) const
  {
    FETICON_CHECK(node && node.IsScalar(), source << ": " << key << " must be a number");
    const std::string text = node.as<std::string>();
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    FETICON_CHECK(end && *end == '\0' && !text.empty() && std::isfinite(v),
                  source << ": " << key << " = '" << text << "' is not a finite number");
    return v;
  }
  Eigen::Vector3d vector3(const YAML::Node& node, const std::string& key) const
  {
    FETICON_CHECK(node && node.IsSequence() && node.size() == 3,
                  source << ": " << key << " must be a list of three numbers, e.g. [0, 0, -1e8]");
    return {number(node[0], key + "[0]"), number(node[1], key + "[1]"), number(node[2], key + "[2]")};
  }
  std::string text(const YAML::Node& node, const std::string& key) const
  {
    FETICON_CHECK(node && node.IsScalar(), source << ": " << key << " must be a name");
    return node.as<std::string>();
  }
  void only_keys(const YAML::Node& node, const std::string& where, const std::set<std::string>& allowed) const
  {
    FETICON_CHECK(node.IsMap(), source << ": " << where << " must be a map of keys");
    for (const auto& kv : node)
    {
      const std::string k = kv.first.as<std::string>();
      if (allowed.count(k))
        continue;
      std::string list;
      for (const auto& a : allowed)
        list += (list.empty() ? "" : ", ") + a;
      FETICON_CHECK(false, source << ": unknown key '" << k << "' in " << where << "; allowed: " << list);
    }
  }
};

/// "a, b, c": the names of a map's keys, for "it has: ..." in messages.
template <class Map>
std::string names_of(const Map& map)
{
  std::string list;
  for (const auto& [name, value] : map)
    list += (list.empty() ? "" : ", ") + name;
  return list;
}
} // namespace feticon::io

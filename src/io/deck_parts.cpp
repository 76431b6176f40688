#include "io/deck_parts.hpp"

#include "common/error.hpp"

#include <cmath>
#include <numbers>
#include <set>

namespace feticon::io
{
RecordedLine::RecordedLine(const DeckDataLine& line)
    : _columns(line.columns), _continues(line.continues), _where(line.where)
{
  for (const std::string_view field : line.fields)
  {
    _spans.emplace_back(_text.size(), field.size());
    _text.append(field);
  }
}

DeckDataLine RecordedLine::view() const
{
  DeckDataLine out;
  const std::string_view text(_text);
  for (const auto& [offset, length] : _spans)
    out.fields.push_back(text.substr(offset, length));
  out.columns = _columns;
  out.continues = _continues;
  out.where = _where;
  return out;
}

Eigen::Matrix3d rotation_about_axis(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double angle_degrees)
{
  const Eigen::Vector3d axis = b - a;
  FETICON_CHECK(axis.norm() > 0, "the rotation axis needs two different points a and b");
  return Eigen::AngleAxisd(angle_degrees * std::numbers::pi / 180, axis.normalized()).toRotationMatrix();
}

bool allowed_in_part(const std::string& keyword)
{
  static const std::set<std::string> allowed = {
      "NODE", "ELEMENT", "NSET", "ELSET", "SURFACE", "SOLID SECTION", "EQUATION", "ORIENTATION", "SECTION CONTROLS"};
  return allowed.count(keyword) != 0;
}

DeckKeyword scoped_keyword(const DeckKeyword& keyword, const std::string& prefix)
{
  DeckKeyword out = keyword;
  for (auto& [key, value] : out.parameters)
  {
    const bool set_name = key == "NSET" || key == "ELSET";
    const bool surface_name = key == "NAME" && keyword.name == "SURFACE";
    if ((set_name || surface_name) && !value.empty())
      value = prefix + value;
  }
  return out;
}
} // namespace feticon::io

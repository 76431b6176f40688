#pragma once
/// @file Abaqus/CAE's parts and assemblies (*PART ... *END PART, *ASSEMBLY, *INSTANCE ... *END
/// INSTANCE; Abaqus Keywords Reference, "*INSTANCE", and Analysis User's Guide, "Defining an
/// assembly"). A part is a mesh with its sets, surfaces and sections; an instance places a copy
/// of it in the model. The deck reader keeps a part's keyword and data lines as text
/// (RecordedKeyword) and reads them again for each instance of it, under that instance's scope:
/// - names: what the part defines (NSET=, ELSET=, a *SURFACE's NAME=) and names in its data lines
///   are the instance's, "INSTANCE.NAME", the way Abaqus qualifies them (scoped_keyword);
/// - numbers: node and element labels are shifted past every label read before (the first
///   instance keeps the part's), since feticon's model has one numbering; a label is named from
///   outside the part as "INSTANCE.LABEL";
/// - coordinates: the instance's placement, a translation and then a rotation about an axis.

#include "io/deck_tokenizer.hpp"

#include <Eigen/Dense>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace feticon::io
{
/// A data line kept as text, to be read again as a DeckDataLine.
class RecordedLine
{
public:
  explicit RecordedLine(const DeckDataLine& line);
  /// The line as the tokenizer gave it; its views point into this object.
  DeckDataLine view() const;

private:
  std::string _text;                             ///< the fields one after the other
  std::vector<std::pair<size_t, size_t>> _spans; ///< offset and length of each field in _text
  std::vector<int64_t> _columns;
  bool _continues = false;
  DeckPosition _where;
};

struct RecordedKeyword
{
  DeckKeyword keyword;
  std::vector<RecordedLine> lines;
};

/// A *PART: its keyword blocks in deck order.
struct DeckPart
{
  DeckPosition where;
  std::vector<RecordedKeyword> keywords;
};

/// Where an instance puts its part: x -> a + R (x + t - a), the translation t first and then the
/// rotation R by `angle` about the axis from a to b (right-handed), as Abaqus's *INSTANCE data
/// lines give them.
struct InstancePlacement
{
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis_point = Eigen::Vector3d::Zero();
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();

  Eigen::Vector3d apply(const Eigen::Vector3d& x) const
  {
    return axis_point + rotation * (x + translation - axis_point);
  }
};

/// The rotation matrix of `angle_degrees` about the axis through a and b.
/// @throws feticon::Error if a and b coincide.
Eigen::Matrix3d rotation_about_axis(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double angle_degrees);

/// A placed instance: its part's labels are shifted by these offsets in the model.
struct DeckInstance
{
  std::string part;
  int64_t node_offset = 0, element_offset = 0;
  DeckPosition where;
};

/// Whose names and numbers the lines being read use: the model's (empty prefix, no offsets) or
/// an instance's.
struct DeckScope
{
  std::string prefix; ///< "INSTANCE." or empty
  int64_t node_offset = 0, element_offset = 0;
  const InstancePlacement* placement = nullptr; ///< for *NODE coordinates; null: as given
};

/// The keywords a part may hold (a mesh, its sets, surfaces and sections); anything else
/// belongs to the model or the assembly.
bool allowed_in_part(const std::string& keyword);

/// `keyword` as an instance reads it: the set and surface names of its parameters (NSET= of *NODE
/// and *NSET, ELSET= of *ELEMENT, *ELSET and *SOLID SECTION, NAME= of *SURFACE) prefixed with
/// `prefix`. MATERIAL= stays: materials belong to the model.
DeckKeyword scoped_keyword(const DeckKeyword& keyword, const std::string& prefix);
} // namespace feticon::io

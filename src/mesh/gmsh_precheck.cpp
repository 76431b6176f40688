#include "mesh/gmsh_precheck.hpp"

#include "common/error.hpp"

#include <array>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace feticon::mesh
{
namespace
{
/// Lines of the file with their numbers; a line longer than `max_line` (binary data) is
/// returned cut, so a file without line breaks is never read into one string.
class LineReader
{
public:
  explicit LineReader(const std::filesystem::path& path) : _in(path, std::ios::binary) {}
  bool good() const { return static_cast<bool>(_in); }

  bool next(std::string& line)
  {
    line.clear();
    char c = 0;
    while (_in.get(c) && c != '\n')
      if (line.size() < max_line)
        line.push_back(c);
    if (!_in && line.empty())
      return false;
    ++_number;
    if (!line.empty() && line.back() == '\r')
      line.pop_back();
    return true;
  }

  /// Reads `count` values of `bytes` bytes each (binary MSH 4 headers).
  bool binary(std::array<uint64_t, 4>& values, int count, int bytes)
  {
    for (int i = 0; i < count; ++i)
    {
      values[i] = 0;
      if (!_in.read(reinterpret_cast<char*>(&values[i]), bytes))
        return false;
    }
    return true;
  }

  int64_t number() const { return _number; }

private:
  static constexpr size_t max_line = 4096;
  std::ifstream _in;
  int64_t _number = 0;
};

/// A count as declared in a header: a non-negative integer below 10^13.
int64_t parse_count(const std::string& token, const std::string& where, int64_t line, const char* what)
{
  size_t used = 0;
  long long value = -1;
  try
  {
    value = std::stoll(token, &used);
  }
  catch (const std::exception&)
  {
    used = 0;
  }
  FETICON_CHECK(used == token.size() && !token.empty() && value >= 0 && value < 10'000'000'000'000LL,
                where << ": line " << line << ": " << what << " '" << token
                      << "' is not a count (a non-negative integer)");
  return value;
}

std::vector<std::string> tokens(const std::string& line)
{
  std::istringstream is(line);
  std::vector<std::string> out;
  for (std::string t; is >> t;)
    out.push_back(t);
  return out;
}

/// One `dim tag "name"` line of $PhysicalNames.
void check_physical_name(const std::string& line, const std::string& where, int64_t number)
{
  std::istringstream is(line);
  std::string dim, tag;
  is >> dim >> tag;
  std::string rest;
  std::getline(is, rest);
  const size_t open = rest.find('"'), close = rest.rfind('"');
  FETICON_CHECK(!dim.empty() && !tag.empty() && open != std::string::npos && close > open,
                where << ": line " << number << ": $PhysicalNames entry '" << line
                      << "' is not 'dimension tag \"name\"'");
  FETICON_CHECK(dim.size() == 1 && dim[0] >= '0' && dim[0] <= '3',
                where << ": line " << number << ": $PhysicalNames entry '" << line << "' has dimension " << dim
                      << "; dimensions are 0 to 3");
  size_t used = 0;
  long long value = 0;
  try
  {
    value = std::stoll(tag, &used);
  }
  catch (const std::exception&)
  {
    used = 0;
  }
  FETICON_CHECK(used == tag.size() && value >= 1 && value <= 2147483647LL,
                where << ": line " << number << ": $PhysicalNames entry '" << line << "' has tag " << tag
                      << "; tags are positive integers");
}
} // namespace

GmshDeclaredSizes precheck_gmsh_file(const std::filesystem::path& path, const std::string& where)
{
  LineReader in(path);
  FETICON_CHECK(in.good(), where << ": cannot be opened for reading");
  std::string line;
  while (in.next(line) && line.find_first_not_of(" \t") == std::string::npos)
  {
  }
  FETICON_CHECK(line == "$MeshFormat", where << ": line " << in.number()
                                             << ": expected $MeshFormat (is this a Gmsh MSH file?)");
  FETICON_CHECK(in.next(line), where << ": ends inside $MeshFormat");
  const std::vector<std::string> format = tokens(line);
  FETICON_CHECK(format.size() >= 3 && (format[0].rfind("2.", 0) == 0 || format[0].rfind("4.", 0) == 0) &&
                    (format[1] == "0" || format[1] == "1"),
                where << ": line " << in.number() << ": '" << line
                      << "' is not a MSH 2 or MSH 4 format line ('4.1 0 8': version, ascii 0 or binary 1, "
                         "size of a double)");
  const bool msh4 = format[0][0] == '4', binary = format[1] == "1";
  const int size_t_bytes = std::stoi(format[2]);

  // Every node or element takes at least one byte of the file in any format, so a count
  // beyond the file's size is a corrupt header, refused before libgmsh allocates for it.
  std::error_code ec;
  const auto file_bytes = static_cast<int64_t>(std::filesystem::file_size(path, ec));
  auto plausible = [&](int64_t count, const char* section)
  {
    FETICON_CHECK(ec || count <= file_bytes, where << ": line " << in.number() << ": the " << section
                                                   << " header declares " << count << " entries, more than the "
                                                   << file_bytes << " bytes of the file could hold");
    return count;
  };

  GmshDeclaredSizes sizes;
  // Counts of $Nodes / $Elements: MSH 2 `N`; MSH 4 `blocks N min max` (binary: size_t values).
  auto declared_count = [&](const char* section) -> int64_t
  {
    if (msh4 && binary)
    {
      std::array<uint64_t, 4> values{};
      FETICON_CHECK(size_t_bytes == 4 || size_t_bytes == 8, where << ": size_t of " << size_t_bytes << " bytes");
      FETICON_CHECK(in.binary(values, 4, size_t_bytes), where << ": ends in the " << section << " header");
      FETICON_CHECK(values[1] < 10'000'000'000'000ULL,
                    where << ": the " << section << " header declares " << values[1] << " entries");
      return static_cast<int64_t>(values[1]);
    }
    FETICON_CHECK(in.next(line), where << ": ends after " << section);
    const std::vector<std::string> t = tokens(line);
    FETICON_CHECK(t.size() == (msh4 ? 4u : 1u), where << ": line " << in.number() << ": the " << section
                                                     << " header '" << line << "' must have "
                                                     << (msh4 ? "4 numbers" : "1 number"));
    return parse_count(t[msh4 ? 1 : 0], where, in.number(), section);
  };
  while (in.next(line))
  {
    if (line == "$PhysicalNames")
    {
      FETICON_CHECK(in.next(line), where << ": ends after $PhysicalNames");
      const int64_t count = parse_count(line, where, in.number(), "the $PhysicalNames count");
      int64_t read = 0;
      while (in.next(line) && line != "$EndPhysicalNames")
      {
        ++read;
        FETICON_CHECK(read <= count, where << ": line " << in.number() << ": more $PhysicalNames entries than the "
                                           << count << " declared");
        check_physical_name(line, where, in.number());
      }
      FETICON_CHECK(line == "$EndPhysicalNames", where << ": $PhysicalNames has no $EndPhysicalNames");
      FETICON_CHECK(read == count, where << ": line " << in.number() << ": $PhysicalNames declares " << count
                                         << " entries but lists " << read);
    }
    else if (line == "$Nodes")
      sizes.nodes = plausible(declared_count("$Nodes"), "$Nodes");
    else if (line == "$Elements")
    {
      sizes.elements = plausible(declared_count("$Elements"), "$Elements");
      break; // the counts are all the memory guard needs; libgmsh reads the rest
    }
  }
  return sizes;
}
} // namespace feticon::mesh

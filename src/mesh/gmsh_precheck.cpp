#include "mesh/gmsh_precheck.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <array>
#include <climits>
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
/// Integer tokens of a data line of $Nodes / $Elements (ASCII).
std::vector<int64_t> integers(const std::string& line, const std::string& where, int64_t number, const char* what)
{
  std::vector<int64_t> out;
  for (const std::string& t : tokens(line))
    out.push_back(parse_count(t, where, number, what));
  return out;
}

/// Tags of the nodes an ASCII $Nodes section lists (sorted), its body checked against its
/// header: libgmsh 4.8 frees memory twice when the count is lower than the entries, and
/// crashes on tags out of their declared range. MSH 2: `N` then `tag x y z` lines; MSH 4:
/// `blocks N min max`, then per block `dim entity parametric n`, n tag lines, n coordinate lines.
std::vector<int64_t> ascii_node_tags(LineReader& in, const std::vector<int64_t>& header, bool msh4,
                                     const std::string& where)
{
  std::string line;
  std::vector<int64_t> tags;
  const int64_t declared = header[msh4 ? 1 : 0];
  // `numbers`: the numbers a node line must hold: 4 in MSH 2 (libgmsh 4.8 reads `tag x y z` by
  // scanning, so a fifth number became the next node's tag and a crash: "15 0.5 0. 5 0.5"
  // from the fuzzer), 1 for MSH 4's tag lines.
  auto read_tag = [&](int64_t low, int64_t high, size_t numbers) {
    FETICON_CHECK(in.next(line) && line != "$EndNodes",
                  where << ": line " << in.number() << ": $Nodes declares " << declared << " nodes but lists fewer");
    const std::vector<std::string> words = tokens(line);
    FETICON_CHECK(words.size() == numbers,
                  where << ": line " << in.number() << ": a node line holds " << words.size() << " numbers, not "
                        << numbers << (msh4 ? " (the tag)" : " (tag x y z)"));
    const int64_t tag = parse_count(words[0], where, in.number(), "the node tag");
    FETICON_CHECK(tag >= low && tag <= high,
                  where << ": line " << in.number() << ": node tag " << tag << " is outside " << low << ".." << high);
    tags.push_back(tag);
  };
  if (!msh4)
    for (int64_t k = 0; k < declared; ++k)
      read_tag(1, INT32_MAX, 4);
  else
  {
    const int64_t low = std::max<int64_t>(1, header[2]), high = std::min<int64_t>(INT32_MAX, header[3]);
    for (int64_t block = 0; block < header[0]; ++block)
    {
      FETICON_CHECK(in.next(line), where << ": ends inside $Nodes");
      const std::vector<int64_t> b = integers(line, where, in.number(), "a $Nodes block header value");
      FETICON_CHECK(b.size() == 4 && b[3] <= declared - static_cast<int64_t>(tags.size()),
                    where << ": line " << in.number() << ": node block '" << line << "' lists more nodes than the "
                          << declared << " declared (or is not 'dim entity parametric count')");
      for (int64_t k = 0; k < b[3]; ++k)
        read_tag(low, high, 1);
      for (int64_t k = 0; k < b[3]; ++k)
        FETICON_CHECK(in.next(line) && line != "$EndNodes", where << ": ends inside a block of coordinates");
    }
  }
  FETICON_CHECK(in.next(line) && line == "$EndNodes",
                where << ": line " << in.number() << ": $Nodes declares " << declared
                      << " nodes but lists more (expected $EndNodes)");
  std::sort(tags.begin(), tags.end());
  FETICON_CHECK(std::adjacent_find(tags.begin(), tags.end()) == tags.end(), where << ": $Nodes lists a node tag twice");
  return tags;
}

/// The body of an ASCII $Elements section against its header and the node tags: each
/// element's nodes must exist (libgmsh 4.8 crashes on a negative or unknown node tag).
/// MSH 2: `tag type ntags tags... nodes...`; MSH 4: per block `dim entity type n`, n lines
/// `tag nodes...`.
void check_ascii_elements(LineReader& in, const std::vector<int64_t>& header, bool msh4,
                          const std::vector<int64_t>& node_tags, const std::string& where)
{
  std::string line;
  const int64_t declared = header[msh4 ? 1 : 0];
  auto check_nodes = [&](const std::vector<std::string>& t, size_t first) {
    FETICON_CHECK(t.size() > first, where << ": line " << in.number() << ": element '" << line << "' has no nodes");
    for (size_t k = first; k < t.size(); ++k)
    {
      const int64_t tag = parse_count(t[k], where, in.number(), "the element's node tag");
      FETICON_CHECK(std::binary_search(node_tags.begin(), node_tags.end(), tag),
                    where << ": line " << in.number() << ": element '" << line << "' names node " << tag
                          << ", which $Nodes does not list");
    }
  };
  auto next_element = [&]() {
    FETICON_CHECK(in.next(line) && line != "$EndElements",
                  where << ": line " << in.number() << ": $Elements declares " << declared
                        << " elements but lists fewer");
    return tokens(line);
  };
  int64_t listed = 0;
  if (!msh4)
    for (; listed < declared; ++listed)
    {
      const std::vector<std::string> t = next_element();
      const int64_t n_tags = t.size() >= 3 ? parse_count(t[2], where, in.number(), "the element's tag count") : 0;
      FETICON_CHECK(t.size() >= 3 && static_cast<int64_t>(t.size()) > 3 + n_tags,
                    where << ": line " << in.number() << ": element '" << line
                          << "' is not 'tag type ntags tags... nodes...'");
      check_nodes(t, static_cast<size_t>(3 + n_tags));
    }
  else
    for (int64_t block = 0; block < header[0]; ++block)
    {
      FETICON_CHECK(in.next(line), where << ": ends inside $Elements");
      const std::vector<int64_t> b = integers(line, where, in.number(), "an $Elements block header value");
      FETICON_CHECK(b.size() == 4 && b[3] <= declared - listed,
                    where << ": line " << in.number() << ": element block '" << line
                          << "' lists more elements than the " << declared
                          << " declared (or is not 'dim entity type count')");
      for (int64_t k = 0; k < b[3]; ++k, ++listed)
        check_nodes(next_element(), 1);
    }
  FETICON_CHECK(listed == declared && in.next(line) && line == "$EndElements",
                where << ": line " << in.number() << ": $Elements declares " << declared
                      << " elements but lists more (expected $EndElements)");
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
  FETICON_CHECK(line == "$MeshFormat",
                where << ": line " << in.number() << ": expected $MeshFormat (is this a Gmsh MSH file?)");
  FETICON_CHECK(in.next(line), where << ": ends inside $MeshFormat");
  const std::vector<std::string> format = tokens(line);
  FETICON_CHECK(format.size() >= 3 && (format[0].rfind("2.", 0) == 0 || format[0].rfind("4.", 0) == 0) &&
                    (format[1] == "0" || format[1] == "1"),
                where << ": line " << in.number() << ": '" << line
                      << "' is not a MSH 2 or MSH 4 format line ('4.1 0 8': version, ascii 0 or binary 1, "
                         "size of a double)");
  const bool msh4 = format[0][0] == '4', binary = format[1] == "1";
  FETICON_CHECK(format[2] == "8" || format[2] == "4",
                where << ": line " << in.number() << ": data size '" << format[2]
                      << "' in the format line is not 8 or 4 (the bytes of a double, MSH 2, or of a size_t, MSH 4)");
  const int size_t_bytes = format[2] == "4" ? 4 : 8;

  // Every node or element takes at least one byte of the file in any format, so a count
  // beyond the file's size is a corrupt header, refused before libgmsh allocates for it.
  std::error_code ec;
  const auto file_bytes = static_cast<int64_t>(std::filesystem::file_size(path, ec));
  auto plausible = [&](int64_t count, const char* section) {
    FETICON_CHECK(ec || count <= file_bytes,
                  where << ": line " << in.number() << ": the " << section << " header declares " << count
                        << " entries, more than the " << file_bytes << " bytes of the file could hold");
    return count;
  };

  GmshDeclaredSizes sizes;
  // The header of $Nodes / $Elements: MSH 2 `N`; MSH 4 `blocks N min max` (binary: size_t
  // values). Its count (N) is checked against the file's size.
  auto section_header = [&](const char* section) -> std::vector<int64_t> {
    std::vector<int64_t> header;
    if (msh4 && binary)
    {
      std::array<uint64_t, 4> values{};
      FETICON_CHECK(size_t_bytes == 4 || size_t_bytes == 8, where << ": size_t of " << size_t_bytes << " bytes");
      FETICON_CHECK(in.binary(values, 4, size_t_bytes), where << ": ends in the " << section << " header");
      for (const uint64_t v : values)
      {
        FETICON_CHECK(v < 10'000'000'000'000ULL, where << ": the " << section << " header declares " << v);
        header.push_back(static_cast<int64_t>(v));
      }
    }
    else
    {
      FETICON_CHECK(in.next(line), where << ": ends after " << section);
      header = integers(line, where, in.number(), section);
      FETICON_CHECK(header.size() == (msh4 ? 4u : 1u),
                    where << ": line " << in.number() << ": the " << section << " header '" << line << "' must have "
                          << (msh4 ? "4 numbers" : "1 number"));
    }
    plausible(header[msh4 ? 1 : 0], section);
    return header;
  };
  // The bodies of the sections are checked in ASCII files; a binary file's are left to libgmsh.
  std::vector<int64_t> node_tags;
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
        FETICON_CHECK(read <= count,
                      where << ": line " << in.number() << ": more $PhysicalNames entries than the " << count
                            << " declared");
        check_physical_name(line, where, in.number());
      }
      FETICON_CHECK(line == "$EndPhysicalNames", where << ": $PhysicalNames has no $EndPhysicalNames");
      FETICON_CHECK(read == count,
                    where << ": line " << in.number() << ": $PhysicalNames declares " << count << " entries but lists "
                          << read);
    }
    else if (line == "$Nodes")
    {
      const std::vector<int64_t> header = section_header("$Nodes");
      sizes.nodes = header[msh4 ? 1 : 0];
      if (binary)
        break; // the counts are what the memory guard needs; libgmsh reads the rest
      node_tags = ascii_node_tags(in, header, msh4, where);
    }
    else if (line == "$Elements")
    {
      const std::vector<int64_t> header = section_header("$Elements");
      sizes.elements = header[msh4 ? 1 : 0];
      check_ascii_elements(in, header, msh4, node_tags, where);
    }
  }
  return sizes;
}
} // namespace feticon::mesh

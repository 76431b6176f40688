#include "la/matrix_market.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace feticon::la
{
namespace
{
/// Reads a file line by line and turns every problem into "<path>:<line>: <what>".
class LineReader
{
public:
  explicit LineReader(const std::string& path) : _path(path), _in(path)
  {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
      throw Error(path +
                  (std::filesystem::exists(path, ec) ? ": is not a regular file (a folder or a device?)"
                                                     : ": no such Matrix Market file"));
    if (!_in)
      throw Error(path + ": cannot open the Matrix Market file for reading");
    _bytes = static_cast<long double>(std::filesystem::file_size(path, ec));
  }

  /// Refuses a size line declaring more lines than the file could hold (each at least
  /// `min_bytes` long): a corrupt header, refused before anything is allocated for it.
  void check_plausible(long double lines, int min_bytes, const char* what) const
  {
    if (lines * min_bytes > _bytes)
      fail("the size line declares " + std::to_string(static_cast<long long>(std::min(lines, 1e18L))) + " " + what +
           ", more than the " + std::to_string(static_cast<long long>(_bytes)) + " bytes of the file could hold");
  }

  /// Next line, without a trailing '\r'; false at the end of the file.
  bool next(std::string& line)
  {
    if (!std::getline(_in, line))
      return false;
    ++_line;
    if (!line.empty() && line.back() == '\r')
      line.pop_back();
    return true;
  }

  /// Next line that is neither a comment nor blank; false at the end of the file.
  bool next_data(std::string& line)
  {
    while (next(line))
    {
      const auto first = line.find_first_not_of(" \t");
      if (first != std::string::npos && line[first] != '%')
        return true;
    }
    return false;
  }

  [[noreturn]] void fail(const std::string& what) const
  {
    throw Error(_path + ":" + std::to_string(_line) + ": " + what);
  }

  /// For a file that ends too early: names the line where more was expected.
  [[noreturn]] void fail_at_end(const std::string& what) const
  {
    throw Error(_path + ":" + std::to_string(_line + 1) + ": " + what);
  }

private:
  std::string _path;
  std::ifstream _in;
  long _line = 0;
  long double _bytes = 0;
};

/// Whitespace-separated numbers of one line, checked one by one.
class Tokens
{
public:
  Tokens(const std::string& line, const LineReader& reader) : _cursor(line.c_str()), _reader(reader) {}

  long long integer(const char* what)
  {
    char* end = nullptr;
    errno = 0;
    const long long value = std::strtoll(_cursor, &end, 10);
    if (end == _cursor || !ends_token(end))
      _reader.fail(std::string("expected an integer ") + what + ", found '" + token() + "'");
    if (errno == ERANGE)
      _reader.fail(std::string(what) + " '" + token() + "' is out of range");
    _cursor = end;
    return value;
  }

  double real(const char* what)
  {
    char* end = nullptr;
    const double value = std::strtod(_cursor, &end);
    if (end == _cursor || !ends_token(end))
      _reader.fail(std::string("expected a number ") + what + ", found '" + token() + "'");
    // inf has a meaning (an absent bound), NaN none.
    if (std::isnan(value))
      _reader.fail(std::string("NaN ") + what + " is not a number");
    _cursor = end;
    return value;
  }

  /// Fails if anything but whitespace is left.
  void finish(const char* after)
  {
    while (std::isspace(static_cast<unsigned char>(*_cursor)))
      ++_cursor;
    if (*_cursor != '\0')
      _reader.fail(std::string("unexpected text '") + _cursor + "' after " + after);
  }

private:
  static bool ends_token(const char* end) { return *end == '\0' || std::isspace(static_cast<unsigned char>(*end)); }

  /// The next token, for messages ("<end of line>" if none).
  std::string token() const
  {
    const char* begin = _cursor;
    while (std::isspace(static_cast<unsigned char>(*begin)))
      ++begin;
    const char* end = begin;
    while (*end != '\0' && !std::isspace(static_cast<unsigned char>(*end)))
      ++end;
    return begin == end ? std::string("<end of line>") : std::string(begin, end);
  }

  const char* _cursor;
  const LineReader& _reader;
};

struct Header
{
  bool coordinate = false;
  bool symmetric = false;
};

std::string lower_case(std::string word)
{
  std::transform(word.begin(), word.end(), word.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return word;
}

Header read_header(LineReader& reader)
{
  std::string line;
  if (!reader.next(line))
    reader.fail_at_end("empty file; expected a '%%MatrixMarket matrix ...' header");
  std::istringstream words(line);
  std::string banner, object, format, field, symmetry, extra;
  words >> banner >> object >> format >> field >> symmetry;
  if (lower_case(banner) != "%%matrixmarket")
    reader.fail("expected the header '%%MatrixMarket matrix coordinate|array real general|"
                "symmetric', found '" +
                line + "'");
  if (lower_case(object) != "matrix")
    reader.fail("unsupported object '" + object + "'; expected 'matrix'");
  Header header;
  format = lower_case(format);
  if (format != "coordinate" && format != "array")
    reader.fail("unsupported format '" + format + "'; expected 'coordinate' or 'array'");
  header.coordinate = format == "coordinate";
  field = lower_case(field);
  if (field != "real" && field != "integer")
    reader.fail("unsupported field '" + field + "'; expected 'real' or 'integer'");
  symmetry = lower_case(symmetry);
  if (symmetry != "general" && symmetry != "symmetric")
    reader.fail("unsupported symmetry '" + symmetry + "'; expected 'general' or 'symmetric'");
  header.symmetric = symmetry == "symmetric";
  if (words >> extra)
    reader.fail("unexpected text '" + extra + "' after the header");
  return header;
}

/// Reads a row or column count and checks that it fits the 32-bit indices of SparseMatrix.
int read_dimension(Tokens& tokens, const LineReader& reader, const char* what)
{
  const long long value = tokens.integer(what);
  if (value < 0 || value > INT_MAX)
    reader.fail(std::string(what) + " = " + std::to_string(value) + " must be in 0.." + std::to_string(INT_MAX));
  return static_cast<int>(value);
}

/// Reads "i j value" of a coordinate file into 0-based indices.
void read_entry(const std::string& line, const LineReader& reader, int rows, int cols, int& row, int& col,
                double& value)
{
  Tokens tokens(line, reader);
  const long long i = tokens.integer("row index");
  const long long j = tokens.integer("column index");
  value = tokens.real("value");
  tokens.finish("the entry 'row column value'");
  if (i < 1 || i > rows)
    reader.fail("row index " + std::to_string(i) + " out of range 1.." + std::to_string(rows));
  if (j < 1 || j > cols)
    reader.fail("column index " + std::to_string(j) + " out of range 1.." + std::to_string(cols));
  row = static_cast<int>(i - 1);
  col = static_cast<int>(j - 1);
}

/// Reads the size line and the entries of a coordinate file as 0-based triplets;
/// `column_vector` requires exactly one column.
std::vector<Triplet> read_coordinate(LineReader& reader, bool symmetric, bool column_vector, int& rows, int& cols)
{
  std::string line;
  if (!reader.next_data(line))
    reader.fail_at_end("file ends before the size line 'rows columns entries'");
  Tokens size(line, reader);
  rows = read_dimension(size, reader, "row count");
  cols = read_dimension(size, reader, "column count");
  const long long entries = size.integer("entry count");
  size.finish("the size line 'rows columns entries'");
  if (column_vector && cols != 1)
    reader.fail("expected a column vector (1 column), found " + std::to_string(cols) + " columns");
  const long double capacity = static_cast<long double>(rows) * cols;
  if (entries < 0 || static_cast<long double>(entries) > capacity)
    reader.fail("entry count " + std::to_string(entries) + " must be in 0..rows*columns");
  if (symmetric && rows != cols)
    reader.fail("a symmetric matrix must be square, found " + std::to_string(rows) + " x " + std::to_string(cols));
  reader.check_plausible(entries, 6, "entries"); // "i j v\n"

  std::vector<Triplet> triplets;
  triplets.reserve(static_cast<std::size_t>(std::min(entries, 1LL << 24)) * (symmetric ? 2 : 1));
  int triangle = 0; // symmetric files: +1 lower, -1 upper, 0 none seen yet
  for (long long k = 0; k < entries; ++k)
  {
    if (!reader.next_data(line))
      reader.fail_at_end("file ends after " + std::to_string(k) + " of " + std::to_string(entries) + " entries");
    int row = 0, col = 0;
    double value = 0.0;
    read_entry(line, reader, rows, cols, row, col, value);
    triplets.emplace_back(row, col, value);
    if (symmetric && row != col)
    {
      const int side = row > col ? 1 : -1;
      if (triangle != 0 && side != triangle)
        reader.fail("symmetric file stores entries of both triangles; store only one");
      triangle = side;
      triplets.emplace_back(col, row, value);
    }
  }
  if (reader.next_data(line))
    reader.fail("more entries than the " + std::to_string(entries) + " declared");
  return triplets;
}
} // namespace

MatrixMarketSize read_matrix_market_size(const std::string& path)
{
  LineReader reader(path);
  const Header header = read_header(reader);
  std::string line;
  if (!reader.next_data(line))
    reader.fail_at_end("file ends before the size line");
  Tokens size(line, reader);
  MatrixMarketSize out;
  out.rows = read_dimension(size, reader, "row count");
  out.cols = read_dimension(size, reader, "column count");
  out.entries = header.coordinate ? size.integer("entry count") : static_cast<long long>(out.rows) * out.cols;
  if (header.coordinate &&
      (out.entries < 0 || static_cast<long double>(out.entries) > static_cast<long double>(out.rows) * out.cols))
    reader.fail("entry count " + std::to_string(out.entries) + " must be in 0..rows*columns");
  reader.check_plausible(out.entries, header.coordinate ? 6 : 2, header.coordinate ? "entries" : "values");
  out.symmetric = header.symmetric;
  return out;
}

SparseMatrix read_matrix_market_sparse(const std::string& path)
{
  LineReader reader(path);
  const Header header = read_header(reader);
  if (!header.coordinate)
    reader.fail("a sparse matrix needs the 'coordinate' format, found 'array'");
  int rows = 0, cols = 0;
  const std::vector<Triplet> triplets = read_coordinate(reader, header.symmetric, false, rows, cols);
  SparseMatrix matrix(rows, cols);
  matrix.setFromTriplets(triplets.begin(), triplets.end());
  return matrix;
}

Vector read_matrix_market_dense(const std::string& path)
{
  LineReader reader(path);
  const Header header = read_header(reader);
  if (header.symmetric)
    reader.fail("a vector file must be 'general', found 'symmetric'");
  if (header.coordinate)
  {
    int rows = 0, cols = 0;
    const std::vector<Triplet> triplets = read_coordinate(reader, false, true, rows, cols);
    Vector vector = Vector::Zero(rows);
    for (const Triplet& t : triplets)
      vector[t.row()] += t.value();
    return vector;
  }

  std::string line;
  if (!reader.next_data(line))
    reader.fail_at_end("file ends before the size line 'rows columns'");
  Tokens size(line, reader);
  const int rows = read_dimension(size, reader, "row count");
  const int cols = read_dimension(size, reader, "column count");
  size.finish("the size line 'rows columns'");
  if (cols != 1)
    reader.fail("expected a column vector (1 column), found " + std::to_string(cols) + " columns");
  reader.check_plausible(rows, 2, "values"); // "v\n"
  Vector vector(rows);
  for (int i = 0; i < rows; ++i)
  {
    if (!reader.next_data(line))
      reader.fail_at_end("file ends after " + std::to_string(i) + " of " + std::to_string(rows) + " values");
    Tokens tokens(line, reader);
    vector[i] = tokens.real("value");
    tokens.finish("the value");
  }
  if (reader.next_data(line))
    reader.fail("more values than the " + std::to_string(rows) + " declared");
  return vector;
}

void write_matrix_market_dense(const std::string& path, const Vector& vector)
{
  std::FILE* file = std::fopen(path.c_str(), "w");
  FETICON_CHECK(file != nullptr, path << ": cannot open the file for writing");
  std::fprintf(file, "%%%%MatrixMarket matrix array real general\n%ld 1\n", static_cast<long>(vector.size()));
  for (Index i = 0; i < vector.size(); ++i)
    std::fprintf(file, "%.17g\n", vector[i]);
  const bool failed = std::ferror(file) != 0;
  const bool closed = std::fclose(file) == 0;
  FETICON_CHECK(!failed && closed, path << ": writing the Matrix Market file failed");
}
} // namespace feticon::la

#include "io/fixed_width.hpp"

#include "common/error.hpp"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>

namespace feticon::io
{
namespace
{
void append_right_justified(std::string& out, const char* text, std::size_t n, int width)
{
  if (static_cast<int>(n) < width)
    out.append(static_cast<std::size_t>(width) - n, ' ');
  out.append(text, n);
}

/// d.ddde+XX of `value` with `precision` digits after the point (std::to_chars follows printf's
/// %e: at least two exponent digits). Returns the length; `text` holds at least 64 chars.
std::size_t scientific(char* text, double value, int precision)
{
  const std::to_chars_result result = std::to_chars(text, text + 64, value, std::chars_format::scientific, precision);
  FETICON_ASSERT(result.ec == std::errc(), "to_chars failed for precision " << precision);
  return static_cast<std::size_t>(result.ptr - text);
}
} // namespace

void append_c_exponential(std::string& out, double value, int width, int precision)
{
  char text[64];
  std::size_t n = 0;
  if (std::isnan(value))
    n = static_cast<std::size_t>(std::snprintf(text, sizeof text, "%s", std::signbit(value) ? "-NAN" : "NAN"));
  else if (std::isinf(value))
    n = static_cast<std::size_t>(std::snprintf(text, sizeof text, "%s", value < 0 ? "-INF" : "INF"));
  else
  {
    n = scientific(text, value, precision);
    char* e = static_cast<char*>(std::memchr(text, 'e', n));
    FETICON_ASSERT(e != nullptr, "no exponent in " << std::string(text, n));
    *e = 'E';
  }
  append_right_justified(out, text, n, width);
}

void append_fortran_1pe(std::string& out, double value, int width, int precision)
{
  char text[64];
  std::size_t n = 0;
  if (std::isnan(value))
    n = static_cast<std::size_t>(std::snprintf(text, sizeof text, "NaN"));
  else if (std::isinf(value))
    n = static_cast<std::size_t>(std::snprintf(text, sizeof text, "%s", value < 0 ? "-Infinity" : "Infinity"));
  else
  {
    n = scientific(text, value, precision);
    char* e = static_cast<char*>(std::memchr(text, 'e', n));
    FETICON_ASSERT(e != nullptr, "no exponent in " << std::string(text, n));
    const std::size_t exponent_digits = n - static_cast<std::size_t>(e - text) - 2;
    if (exponent_digits == 3)
    {
      // Fortran's Ew.d form for 99 < |exponent| <= 999: the sign takes the place of the 'E'.
      std::memmove(e, e + 1, n - static_cast<std::size_t>(e - text) - 1);
      --n;
    }
    else
      *e = 'E';
  }
  append_right_justified(out, text, n, width);
}

void append_fortran_e(std::string& out, double value, int width, int precision)
{
  FETICON_ASSERT(precision >= 1 && precision <= 30, "precision " << precision);
  char text[64];
  std::size_t n = 0;
  if (!std::isfinite(value))
  {
    append_fortran_1pe(out, value, width, precision);
    return;
  }
  const bool negative = std::signbit(value);
  int exponent = 0;
  char digits[64];
  if (value == 0.0)
    std::memset(digits, '0', static_cast<std::size_t>(precision));
  else
  {
    // d.ddd e X with precision digits in all = 0.dddd e X+1.
    char mantissa[64];
    const std::size_t length = scientific(mantissa, std::abs(value), precision - 1);
    const char* e = static_cast<const char*>(std::memchr(mantissa, 'e', length));
    FETICON_ASSERT(e != nullptr, "no exponent");
    // to_chars writes no terminating zero: read the exponent's sign and digits up to `length`.
    int magnitude = 0;
    for (const char* digit = e + 2; digit < mantissa + length; ++digit)
      magnitude = 10 * magnitude + (*digit - '0');
    exponent = (e[1] == '-' ? -magnitude : magnitude) + 1;
    digits[0] = mantissa[0];
    if (precision > 1)
      std::memcpy(digits + 1, mantissa + 2, static_cast<std::size_t>(precision - 1));
  }
  if (negative)
    text[n++] = '-';
  text[n++] = '0';
  text[n++] = '.';
  std::memcpy(text + n, digits, static_cast<std::size_t>(precision));
  n += static_cast<std::size_t>(precision);
  const int magnitude = std::abs(exponent);
  if (magnitude <= 99)
    n += static_cast<std::size_t>(
        std::snprintf(text + n, sizeof text - n, "E%c%02d", exponent < 0 ? '-' : '+', magnitude));
  else
    n += static_cast<std::size_t>(
        std::snprintf(text + n, sizeof text - n, "%c%03d", exponent < 0 ? '-' : '+', magnitude));
  // Fortran drops the optional leading zero when the field is one character short.
  if (static_cast<int>(n) > width)
  {
    const std::size_t zero = negative ? 1 : 0;
    std::memmove(text + zero, text + zero + 1, n - zero - 1);
    --n;
  }
  append_right_justified(out, text, n, width);
}

void append_integer(std::string& out, int64_t value, int width)
{
  char text[24];
  const std::to_chars_result result = std::to_chars(text, text + sizeof text, value);
  append_right_justified(out, text, static_cast<std::size_t>(result.ptr - text), width);
}

TextFileBuffer::TextFileBuffer(std::FILE* file, const std::string& path_for_messages)
    : _file(file), _path(path_for_messages)
{
}

void TextFileBuffer::write()
{
  if (buffer.empty())
    return;
  const std::size_t written = std::fwrite(buffer.data(), 1, buffer.size(), _file);
  FETICON_CHECK(written == buffer.size(),
                "cannot write '" << _path << "' (" << written << " of " << buffer.size()
                                 << " bytes written): is the disk full?");
  buffer.clear();
}

CFile create_file(const std::filesystem::path& path)
{
  if (path.has_parent_path())
  {
    std::error_code error;
    std::filesystem::create_directories(path.parent_path(), error);
    FETICON_CHECK(!error, "cannot create the folder '" << path.parent_path().string() << "': " << error.message());
  }
  CFile file(std::fopen(path.c_str(), "wb"));
  FETICON_CHECK(file != nullptr, "cannot create '" << path.string() << "': check that its folder is writable");
  return file;
}

void close_file(CFile& file, const std::filesystem::path& path)
{
  if (!file)
    return;
  const int status = std::fclose(file.release());
  FETICON_CHECK(status == 0, "cannot write '" << path.string() << "': is the disk full?");
}
} // namespace feticon::io

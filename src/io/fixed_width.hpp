#pragma once
/// @file Fixed-width number fields of CalculiX's text results (.frd written by C's printf, .dat
/// by Fortran edit descriptors), appended to a string buffer with std::to_chars: a million-node
/// result is tens of millions of fields, which printf or iostreams format several times slower.
/// And the C file the buffer goes to (frd_writer, dat_writer).
///
/// Each function appends exactly `width` characters (right-justified) unless the value needs
/// more, which the callers rule out (labels are checked, exponents bounded as noted).

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

namespace feticon::io
{
/// printf("%{width}.{precision}E", value): mantissa d.ddd, 'E', sign, at least two exponent
/// digits; non-finite values as glibc prints them (NAN, INF, -INF).
void append_c_exponential(std::string& out, double value, int width, int precision);

/// Fortran 1PE{width}.{precision} (gfortran): one digit before the point, exponent E+dd;
/// a three-digit exponent drops the 'E' (d.dddddd-100), so -1.0e-100 still fits E13.6.
/// Non-finite values as gfortran writes them (NaN, Infinity, -Infinity).
void append_fortran_1pe(std::string& out, double value, int width, int precision);

/// Fortran E{width}.{precision} without scale factor: 0.ddddddd E+dd (mantissa in [0.1, 1)),
/// the form of CalculiX's "and time  0.1000000E+01".
void append_fortran_e(std::string& out, double value, int width, int precision);

/// A right-justified integer (printf("%{width}lld") / Fortran I{width}).
void append_integer(std::string& out, int64_t value, int width);

struct CFileCloser
{
  void operator()(std::FILE* file) const { std::fclose(file); }
};
/// An open C file, closed by its destructor.
using CFile = std::unique_ptr<std::FILE, CFileCloser>;

/// Creates (or truncates) `path` for writing, creating missing parent directories.
/// @throws feticon::Error naming the path if it cannot be created.
CFile create_file(const std::filesystem::path& path);

/// Flushes and closes `file` (no-op if already closed).
/// @throws feticon::Error naming `path` if the data cannot be written (disk full).
void close_file(CFile& file, const std::filesystem::path& path);

/// @brief A string buffer in front of a C file: callers append text to `buffer`, and
/// flush_if_full() hands it to the file in pieces of about 1 MiB, so a million-line block is
/// never held in memory at once.
class TextFileBuffer
{
public:
  /// Does not own `file`.
  explicit TextFileBuffer(std::FILE* file, const std::string& path_for_messages);
  std::string buffer;
  /// Writes the buffer to the file if it holds 1 MiB or more.
  void flush_if_full()
  {
    if (buffer.size() >= (std::size_t{1} << 20))
      write();
  }
  /// Writes the buffer to the file (std::fwrite, no fflush).
  /// @throws feticon::Error naming the file if the write fails (disk full).
  void write();

private:
  std::FILE* _file;
  std::string _path;
};
} // namespace feticon::io

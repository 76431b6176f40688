#pragma once
/// @file Base64 encoding (RFC 4648 alphabet, '=' padding), as used by VTK XML "binary" arrays.

#include <array>
#include <cstddef>
#include <ostream>
#include <string>

namespace feticon::io
{
/// @brief Streaming base64 encoder: bytes given to write() are encoded as one continuous stream.
///
/// Usage: Base64Writer encoder(out); encoder.write(header, 8); encoder.write(data, n);
/// encoder.finish(); The writer does not own the stream; it must outlive the encoder.
class Base64Writer
{
public:
  explicit Base64Writer(std::ostream& out) : _out(out) {}
  /// Encodes `n_bytes` bytes from `data` (any object representation).
  void write(const void* data, std::size_t n_bytes);
  /// Encodes the last 1 or 2 pending bytes with padding and flushes; call once at the end.
  void finish();

private:
  void flush_buffer();

  std::ostream& _out;
  std::array<unsigned char, 3> _pending{};
  int _n_pending = 0;
  std::string _buffer;
};

/// Base64 encoding of `n_bytes` bytes at `data`.
std::string base64_encode(const void* data, std::size_t n_bytes);
} // namespace feticon::io

#include "io/base64.hpp"

#include <sstream>

namespace feticon::io
{
namespace
{
constexpr char alphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
/// Characters collected before each write to the stream, to keep large arrays fast.
constexpr std::size_t buffer_capacity = 1 << 16;

void encode_group(const unsigned char* bytes, int n_bytes, std::string& out)
{
  const unsigned value = (unsigned{bytes[0]} << 16) | (n_bytes > 1 ? unsigned{bytes[1]} << 8 : 0u) |
      (n_bytes > 2 ? unsigned{bytes[2]} : 0u);
  out += alphabet[(value >> 18) & 63];
  out += alphabet[(value >> 12) & 63];
  out += n_bytes > 1 ? alphabet[(value >> 6) & 63] : '=';
  out += n_bytes > 2 ? alphabet[value & 63] : '=';
}
} // namespace

void Base64Writer::write(const void* data, std::size_t n_bytes)
{
  const auto* bytes = static_cast<const unsigned char*>(data);
  std::size_t position = 0;
  // Complete a group left over from the previous call first, so the stream stays continuous.
  while (_n_pending > 0 && _n_pending < 3 && position < n_bytes)
    _pending[_n_pending++] = bytes[position++];
  if (_n_pending == 3)
  {
    encode_group(_pending.data(), 3, _buffer);
    _n_pending = 0;
  }
  for (; position + 3 <= n_bytes; position += 3)
  {
    encode_group(bytes + position, 3, _buffer);
    if (_buffer.size() >= buffer_capacity)
      flush_buffer();
  }
  while (position < n_bytes)
    _pending[_n_pending++] = bytes[position++];
}

void Base64Writer::finish()
{
  if (_n_pending > 0)
    encode_group(_pending.data(), _n_pending, _buffer);
  _n_pending = 0;
  flush_buffer();
}

void Base64Writer::flush_buffer()
{
  _out.write(_buffer.data(), static_cast<std::streamsize>(_buffer.size()));
  _buffer.clear();
}

std::string base64_encode(const void* data, std::size_t n_bytes)
{
  std::ostringstream out;
  Base64Writer encoder(out);
  encoder.write(data, n_bytes);
  encoder.finish();
  return out.str();
}
} // namespace feticon::io

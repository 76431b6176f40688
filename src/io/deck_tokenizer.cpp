#include "io/deck_tokenizer.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>

namespace feticon::io
{
namespace
{
constexpr size_t initial_buffer_bytes = size_t{4} << 20;
/// A line longer than this is no deck line (a binary file, a file without line ends).
constexpr size_t max_line_bytes = size_t{1} << 20;
constexpr size_t max_include_depth = 32;

bool is_blank(char c) { return c == ' ' || c == '\t'; }

std::string_view trim(std::string_view s)
{
  while (!s.empty() && is_blank(s.front()))
    s.remove_prefix(1);
  while (!s.empty() && (is_blank(s.back()) || s.back() == '\r'))
    s.remove_suffix(1);
  return s;
}

/// Upper case with runs of blanks made single: "contact  pair" -> "CONTACT PAIR".
std::string normalized(std::string_view s)
{
  std::string out;
  out.reserve(s.size());
  for (char c : trim(s))
  {
    if (is_blank(c))
    {
      if (!out.empty() && out.back() != ' ')
        out.push_back(' ');
      continue;
    }
    out.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
  }
  return out;
}
} // namespace

std::string DeckPosition::str() const
{
  std::string out = (file ? *file : std::string("deck")) + ":" + std::to_string(line);
  if (column > 0)
    out += ":" + std::to_string(column);
  return out;
}

bool DeckKeyword::has(std::string_view key) const { return value(key) != nullptr; }

const std::string* DeckKeyword::value(std::string_view key) const
{
  for (const auto& [k, v] : parameters)
    if (k == key)
      return &v;
  return nullptr;
}

/// One open file, read through a buffer.
struct DeckTokenizer::Source
{
  std::FILE* file = nullptr;
  std::filesystem::path path; ///< canonical: circular *INCLUDEs are found by it
  const std::string* name = nullptr;
  std::vector<char> buffer = std::vector<char>(initial_buffer_bytes);
  size_t begin = 0, end = 0;
  int64_t line = 0;
  bool eof = false;

  ~Source()
  {
    if (file)
      std::fclose(file);
  }

  /// The next raw line (without its '\n'); false at the end of the file.
  bool next(std::string_view& out, int64_t& bytes_read)
  {
    for (;;)
    {
      const char* start = buffer.data() + begin;
      if (const void* nl = std::memchr(start, '\n', end - begin))
      {
        const size_t length = static_cast<const char*>(nl) - start;
        out = {start, length};
        begin += length + 1;
        ++line;
        return true;
      }
      if (eof)
      {
        if (begin == end)
          return false;
        out = {start, end - begin};
        begin = end;
        ++line;
        return true;
      }
      // Keep the partial line, then fill the rest of the buffer.
      std::memmove(buffer.data(), start, end - begin);
      end -= begin;
      begin = 0;
      if (end == buffer.size())
      {
        FETICON_CHECK(buffer.size() < max_line_bytes + initial_buffer_bytes,
                      *name << ":" << line + 1 << ": a line longer than " << max_line_bytes
                            << " bytes; this is no input deck (a binary file?)");
        buffer.resize(buffer.size() * 2);
      }
      const size_t n = std::fread(buffer.data() + end, 1, buffer.size() - end, file);
      FETICON_CHECK(!std::ferror(file), *name << ": reading failed: " << std::strerror(errno));
      end += n;
      bytes_read += static_cast<int64_t>(n);
      eof = n == 0;
    }
  }
};

DeckTokenizer::DeckTokenizer(const std::filesystem::path& path) { open(path, DeckPosition{}); }

DeckTokenizer::~DeckTokenizer() = default;

void DeckTokenizer::open(const std::filesystem::path& path, const DeckPosition& from)
{
  const std::string where = from.file ? from.str() + ": *INCLUDE: " : std::string();
  std::error_code ec;
  FETICON_CHECK(std::filesystem::is_regular_file(path, ec),
                where << "input deck " << path.string()
                      << (std::filesystem::exists(path, ec) ? " is not a regular file" : " does not exist"));
  auto source = std::make_unique<Source>();
  source->path = std::filesystem::weakly_canonical(path, ec);
  for (const auto& open : _stack)
    FETICON_CHECK(open->path != source->path,
                  where << "circular *INCLUDE: " << path.string() << " is already being read");
  FETICON_CHECK(_stack.size() < max_include_depth,
                where << "*INCLUDE nested deeper than " << max_include_depth << " files");
  source->file = std::fopen(path.c_str(), "rb");
  FETICON_CHECK(source->file, where << "cannot open " << path.string() << ": " << std::strerror(errno));
  _file_names.push_back(path.string());
  source->name = &_file_names.back();
  _stack.push_back(std::move(source));
}

bool DeckTokenizer::read_line()
{
  while (!_stack.empty())
  {
    Source& top = *_stack.back();
    std::string_view raw;
    if (!top.next(raw, _bytes_read))
    {
      _stack.pop_back();
      continue;
    }
    const std::string_view line = trim(raw);
    if (line.empty() || line.starts_with("**"))
      continue;
    _line = line;
    _where = {top.name, top.line, 0};
    _have_line = true;
    return true;
  }
  return false;
}

bool DeckTokenizer::next_keyword(DeckKeyword& out)
{
  for (;;)
  {
    if (!_have_line && !read_line())
      return false;
    if (_line.front() != '*')
    {
      _have_line = false; // a data line no handler read
      continue;
    }
    // The keyword line and its continuations (a trailing comma), copied: reading on moves
    // the buffer.
    std::string text(_line.substr(1));
    out.where = _where;
    _have_line = false;
    while (!text.empty() && text.back() == ',')
    {
      FETICON_CHECK(read_line() && _line.front() != '*',
                    out.where.str() << ": keyword line ends with a comma but no continuation line follows");
      text += _line;
      _have_line = false;
    }
    out.parameters.clear();
    size_t start = 0;
    bool first = true;
    while (start <= text.size())
    {
      size_t comma = text.find(',', start);
      if (comma == std::string::npos)
        comma = text.size();
      const std::string_view part = trim(std::string_view(text).substr(start, comma - start));
      start = comma + 1;
      if (first)
      {
        out.name = normalized(part);
        FETICON_CHECK(!out.name.empty(), out.where.str() << ": a '*' with no keyword name");
        first = false;
        continue;
      }
      if (part.empty())
        continue;
      const size_t eq = part.find('=');
      std::string key = normalized(part.substr(0, eq));
      FETICON_CHECK(!key.empty(),
                    out.where.str() << ": *" << out.name << ": a parameter with no name ('" << std::string(part)
                                    << "')");
      std::string value;
      if (eq != std::string_view::npos)
      {
        const std::string_view raw = trim(part.substr(eq + 1));
        value = key == "INPUT" ? std::string(raw) : normalized(raw);
      }
      out.parameters.emplace_back(std::move(key), std::move(value));
    }
    if (out.name == "INCLUDE")
    {
      const std::string* input = out.value("INPUT");
      FETICON_CHECK(input && !input->empty(), out.where.str() << ": *INCLUDE needs INPUT=FILE");
      std::filesystem::path path(*input);
      if (path.is_relative())
      {
        // Relative to the including file's folder, as a deck moved with its parts expects;
        // CalculiX itself opens it relative to the working folder, tried second.
        const std::filesystem::path beside = std::filesystem::path(*out.where.file).parent_path() / path;
        std::error_code ec;
        if (std::filesystem::exists(beside, ec) || !std::filesystem::exists(path, ec))
          path = beside;
      }
      open(path, out.where);
      continue;
    }
    return true;
  }
}

int64_t DeckTokenizer::count_data_lines()
{
  int64_t count = 0;
  while ((_have_line || read_line()) && _line.front() != '*')
  {
    _have_line = false;
    ++count;
  }
  return count;
}

bool DeckTokenizer::next_data(DeckDataLine& out)
{
  if (!_have_line && !read_line())
    return false;
  if (_line.front() == '*')
    return false;
  out.fields.clear();
  out.columns.clear();
  out.where = _where;
  out.continues = !_line.empty() && _line.back() == ',';
  const std::string_view line = out.continues ? _line.substr(0, _line.size() - 1) : _line;
  const char* base = _line.data();
  size_t start = 0;
  for (;;)
  {
    size_t comma = line.find(',', start);
    const bool last = comma == std::string_view::npos;
    if (last)
      comma = line.size();
    std::string_view field = line.substr(start, comma - start);
    while (!field.empty() && is_blank(field.front()))
      field.remove_prefix(1);
    while (!field.empty() && is_blank(field.back()))
      field.remove_suffix(1);
    out.fields.push_back(field);
    out.columns.push_back(field.data() - base + 1);
    if (last)
      break;
    start = comma + 1;
  }
  _have_line = false;
  return true;
}
} // namespace feticon::io

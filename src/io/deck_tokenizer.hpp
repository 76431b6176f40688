#pragma once
/// @file The lines of a CalculiX / Abaqus input deck: keyword lines ("*NAME, KEY=VALUE, ...",
/// continued on the next line after a trailing comma) and data lines (comma-separated
/// fields), with comments ("**") and blank lines skipped and *INCLUDE files read in place.
///
/// The files are streamed through a buffer of a few MiB, not held whole: a deck of a million
/// nodes is larger than the mesh it describes (io/deck.hpp, the memory of reading).

#include <cstdint>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace feticon::io
{
/// File and 1-based line (and column, 0 if none) of a deck position, for messages.
struct DeckPosition
{
  const std::string* file = nullptr;
  int64_t line = 0;
  int64_t column = 0;
  /// "FILE:LINE" or "FILE:LINE:COLUMN".
  std::string str() const;
};

/// A keyword line: name and parameters upper-cased (the deck's names are case-insensitive),
/// except the value of INPUT= (a file name).
struct DeckKeyword
{
  std::string name;                                            ///< "CONTACT PAIR": upper case, inner blanks kept single
  std::vector<std::pair<std::string, std::string>> parameters; ///< KEY, VALUE ("" for a flag)
  DeckPosition where;

  bool has(std::string_view key) const;
  /// The value of KEY, or nullptr.
  const std::string* value(std::string_view key) const;
};

/// A data line split at its commas, fields trimmed. The views are valid until the next call
/// of the tokenizer.
struct DeckDataLine
{
  std::vector<std::string_view> fields;
  std::vector<int64_t> columns; ///< 1-based column of every field
  bool continues = false;       ///< the line ended with a comma (the record goes on)
  DeckPosition where;
  /// The position of field i.
  DeckPosition at(size_t i) const { return {where.file, where.line, i < columns.size() ? columns[i] : 0}; }
};

class DeckTokenizer
{
public:
  /// Opens `path`; throws feticon::Error if it cannot be read.
  explicit DeckTokenizer(const std::filesystem::path& path);
  ~DeckTokenizer();
  DeckTokenizer(const DeckTokenizer&) = delete;
  DeckTokenizer& operator=(const DeckTokenizer&) = delete;

  /// The next keyword line (data lines before it that no one read are skipped); false at the
  /// end of the deck. *INCLUDE is handled here and never returned.
  bool next_keyword(DeckKeyword& out);
  /// The next data line of the current keyword; false when a keyword line or the end follows.
  bool next_data(DeckDataLine& out);
  /// Skips the data lines of the current keyword and returns how many there were.
  int64_t count_data_lines();
  /// The storage of the file names DeckPosition points to, for positions that outlive the
  /// tokenizer (moving a deque keeps its elements in place).
  std::deque<std::string> take_file_names() { return std::move(_file_names); }
  /// Bytes of the deck's files read so far.
  int64_t bytes_read() const { return _bytes_read; }

private:
  struct Source;
  /// The next non-comment, non-blank raw line into _line (trailing CR and blanks removed).
  bool read_line();
  void open(const std::filesystem::path& path, const DeckPosition& from);

  std::vector<std::unique_ptr<Source>> _stack; ///< the open files, *INCLUDE on top
  std::deque<std::string> _file_names;         ///< stable storage for DeckPosition::file
  std::string_view _line;                      ///< the current raw line
  DeckPosition _where;
  bool _have_line = false; ///< _line is read but not yet consumed
  int64_t _bytes_read = 0;
};
} // namespace feticon::io

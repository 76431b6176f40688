#pragma once
/// @file Error type and the two checking macros used throughout feticon.
///
/// FETICON_CHECK  always on: input, files, configuration. Throws feticon::Error whose
///                message names the offending value and, where possible, a fix.
/// FETICON_ASSERT debug builds only: internal invariants and sizes.

#include <sstream>
#include <stdexcept>
#include <string>

namespace feticon
{
/// The one exception type feticon throws for bad input or failed solves.
class Error : public std::runtime_error
{
public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

namespace detail
{
[[noreturn]] void throw_error(const std::string& message, const char* file, int line, bool with_location);
} // namespace detail
} // namespace feticon

/// Always-on check; `message` is a stream expression, e.g. "E = " << E << " must be > 0".
#define FETICON_CHECK(cond, message)                                                                                   \
  do                                                                                                                   \
  {                                                                                                                    \
    if (!(cond))                                                                                                       \
    {                                                                                                                  \
      std::ostringstream feticon_check_stream_;                                                                        \
      feticon_check_stream_ << message;                                                                                \
      ::feticon::detail::throw_error(feticon_check_stream_.str(), __FILE__, __LINE__, false);                          \
    }                                                                                                                  \
  } while (false)

#ifdef NDEBUG
#define FETICON_ASSERT(cond, message)                                                                                  \
  do                                                                                                                   \
  {                                                                                                                    \
  } while (false)
#else
#define FETICON_ASSERT(cond, message)                                                                                  \
  do                                                                                                                   \
  {                                                                                                                    \
    if (!(cond))                                                                                                       \
    {                                                                                                                  \
      std::ostringstream feticon_assert_stream_;                                                                       \
      feticon_assert_stream_ << "internal error: " #cond ": " << message;                                              \
      ::feticon::detail::throw_error(feticon_assert_stream_.str(), __FILE__, __LINE__, true);                          \
    }                                                                                                                  \
  } while (false)
#endif

#include "common/error.hpp"

namespace feticon::detail
{
void throw_error(const std::string& message, const char* file, int line, bool with_location)
{
  if (with_location)
    throw Error(message + " [" + file + ":" + std::to_string(line) + "]");
  throw Error(message);
}
} // namespace feticon::detail

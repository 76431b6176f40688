#include "common/atomic_file.hpp"

#include "common/error.hpp"

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <system_error>

#include <unistd.h>

namespace feticon
{
namespace
{
/// A name unique per process and call, so concurrent writers never share a temporary file.
std::filesystem::path temporary_path(const std::filesystem::path& path)
{
  static std::atomic<unsigned long> counter{0};
  // Appends rather than a chain of operator+: GCC 12 -O3 warns falsely (-Wrestrict) on the chain.
  std::string name = ".";
  name += path.filename().string();
  name += ".tmp.";
  name += std::to_string(::getpid());
  name += ".";
  name += std::to_string(counter++);
  return path.parent_path() / name;
}
} // namespace

void write_file_atomically(const std::filesystem::path& path, const std::string& content)
{
  write_file_atomically(
      path, [&content](std::ostream& out) { out.write(content.data(), static_cast<std::streamsize>(content.size())); });
}

void write_file_atomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write)
{
  FETICON_CHECK(path.has_filename(), "cannot write '" << path.string() << "': it names no file");
  const std::filesystem::path parent = path.parent_path();
  if (!parent.empty())
  {
    std::error_code error;
    std::filesystem::create_directories(parent, error);
    FETICON_CHECK(!error,
                  "cannot write '" << path.string() << "': creating directory '" << parent.string()
                                   << "' failed: " << error.message());
  }

  const std::filesystem::path temporary = temporary_path(path);
  try
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    FETICON_CHECK(out.is_open(),
                  "cannot write '" << path.string() << "': opening '" << temporary.string()
                                   << "' failed: " << std::strerror(errno));
    write(out);
    out.close();
    FETICON_CHECK(!out.fail(), "cannot write '" << path.string() << "': the output stream failed (disk full?)");
    std::error_code error;
    std::filesystem::rename(temporary, path, error);
    FETICON_CHECK(!error,
                  "cannot write '" << path.string() << "': renaming '" << temporary.string()
                                   << "' onto it failed: " << error.message());
  }
  catch (...)
  {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw;
  }
}
} // namespace feticon

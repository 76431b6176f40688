#pragma once
/// Scratch folders for the io unit tests (below the build tree).

#include <filesystem>
#include <string>

namespace feticon::test
{
/// An empty folder test_output/unit_io/<name> in the build tree.
inline std::filesystem::path fresh_directory(const std::string& name)
{
  const std::filesystem::path directory = std::filesystem::path(FETICON_BINARY_DIR) / "test_output" / "unit_io" / name;
  std::filesystem::remove_all(directory);
  std::filesystem::create_directories(directory);
  return directory;
}
} // namespace feticon::test

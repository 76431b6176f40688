/// Tests of the base64 encoder (reference: the test vectors of RFC 4648, section 10) and of
/// atomic file writing (reference: the file system after each call).

#include "common/atomic_file.hpp"
#include "io/base64.hpp"

#include "common/error.hpp"

#include "io_test_files.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace feticon::io
{
namespace
{
namespace fs = std::filesystem;

using test::fresh_directory;

std::string read(const fs::path& path)
{
  std::ifstream in(path, std::ios::binary);
  std::ostringstream content;
  content << in.rdbuf();
  return content.str();
}

std::vector<std::string> listing(const fs::path& directory)
{
  std::vector<std::string> names;
  for (const auto& entry : fs::recursive_directory_iterator(directory))
    names.push_back(fs::relative(entry.path(), directory).string());
  std::sort(names.begin(), names.end());
  return names;
}
} // namespace

TEST(Base64, Rfc4648Vectors)
{
  const std::vector<std::pair<std::string, std::string>> vectors = {{"", ""},
                                                                    {"f", "Zg=="},
                                                                    {"fo", "Zm8="},
                                                                    {"foo", "Zm9v"},
                                                                    {"foob", "Zm9vYg=="},
                                                                    {"fooba", "Zm9vYmE="},
                                                                    {"foobar", "Zm9vYmFy"}};
  for (const auto& [plain, encoded] : vectors)
    EXPECT_EQ(base64_encode(plain.data(), plain.size()), encoded) << plain;
  const unsigned char high[] = {0xff, 0xfe, 0x00, 0x80};
  EXPECT_EQ(base64_encode(high, 4), "//4AgA==");
}

TEST(Base64, StreamingSplitsEncodeLikeOneBlock)
{
  std::string bytes;
  for (int i = 0; i < 200; ++i)
    bytes += static_cast<char>((i * 37 + 11) % 256);
  const std::string whole = base64_encode(bytes.data(), bytes.size());
  for (std::size_t first = 0; first <= 7; ++first)
    for (std::size_t second = 0; second <= 7; ++second)
    {
      std::ostringstream out;
      Base64Writer encoder(out);
      encoder.write(bytes.data(), first);
      encoder.write(bytes.data() + first, second);
      encoder.write(bytes.data() + first + second, bytes.size() - first - second);
      encoder.finish();
      EXPECT_EQ(out.str(), whole) << first << " " << second;
    }
}

TEST(AtomicFile, WritesCreatesDirectoriesAndLeavesNoTemporary)
{
  const fs::path directory = fresh_directory("atomic_write");
  const fs::path path = directory / "a" / "b" / "out.txt";
  write_file_atomically(path, "first");
  EXPECT_EQ(read(path), "first");
  write_file_atomically(path, [](std::ostream& out) { out << "second " << 2; });
  EXPECT_EQ(read(path), "second 2");
  EXPECT_EQ(listing(directory), (std::vector<std::string>{"a", "a/b", "a/b/out.txt"}));
}

TEST(AtomicFile, FailingCallbackKeepsTheOldFile)
{
  const fs::path directory = fresh_directory("atomic_callback_throws");
  const fs::path path = directory / "out.txt";
  write_file_atomically(path, "complete");
  EXPECT_THROW(write_file_atomically(
                   path,
                   [](std::ostream& out) {
    out << "half";
    throw std::runtime_error("writer failed");
                   }),
               std::runtime_error);
  EXPECT_EQ(read(path), "complete");
  EXPECT_EQ(listing(directory), (std::vector<std::string>{"out.txt"}));
}

TEST(AtomicFile, UnwritablePathThrowsNamingIt)
{
  const fs::path directory = fresh_directory("atomic_unwritable");
  // A regular file where a directory is needed fails even for root.
  write_file_atomically(directory / "plain_file", "x");
  const fs::path path = directory / "plain_file" / "sub" / "out.txt";
  try
  {
    write_file_atomically(path, "content");
    FAIL() << "no error for " << path;
  }
  catch (const Error& error)
  {
    EXPECT_NE(std::string(error.what()).find(path.string()), std::string::npos) << error.what();
  }
  // A directory in place of the file: the rename fails.
  fs::create_directories(directory / "is_a_directory" / "child");
  EXPECT_THROW(write_file_atomically(directory / "is_a_directory", "content"), Error);
  EXPECT_EQ(listing(directory), (std::vector<std::string>{"is_a_directory", "is_a_directory/child", "plain_file"}));
}
} // namespace feticon::io

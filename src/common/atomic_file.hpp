#pragma once
/// @file Atomic file output: a file is either complete or absent (or its previous version).
///
/// The content goes to a temporary file in the same directory, which is then renamed over the
/// target (std::filesystem::rename, atomic within one POSIX file system). A reader such as
/// ParaView polling an output folder, or a run killed mid-write, never sees a truncated file.
/// The data are not fsync'ed: this protects against crashes of the process, not of the machine.

#include <filesystem>
#include <functional>
#include <ostream>
#include <string>

namespace feticon
{
/// @brief Writes `content` to `path` atomically, creating missing parent directories.
/// @throws feticon::Error naming the path if a directory cannot be created or the write or the
///         rename fails; no temporary file is left behind.
void write_file_atomically(const std::filesystem::path& path, const std::string& content);

/// @brief Streaming variant: `write` produces the content into a binary std::ostream, so large
/// outputs (VTU) are not held in memory a second time.
///
/// If `write` throws, the temporary file is removed, `path` is left as it was and the exception
/// propagates.
/// @throws feticon::Error as the other overload, also if the stream is in a failed state after
///         `write`.
void write_file_atomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write);
} // namespace feticon

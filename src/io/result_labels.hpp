#pragma once
/// @file The deck numbering that CalculiX's result files (.frd, .dat) print: one label per mesh
/// node or cell, or none for 1..n. Labels are 32-bit as CalculiX's own (its integers are
/// Fortran INTEGER*4 unless built with 8-byte integers), which halves what a million-node deck
/// keeps beside its mesh.

#include "common/error.hpp"

#include <cstdint>
#include <filesystem>
#include <vector>

namespace feticon::io
{
using Labels = std::vector<int32_t>;

/// Checks that `labels` is empty or holds one positive label per `n` items; `file` names the
/// result kind ("frd", "dat") for the message.
inline void check_labels(const Labels& labels, int64_t n, const char* what, const char* file,
                         const std::filesystem::path& path)
{
  if (labels.empty())
    return;
  FETICON_CHECK(static_cast<int64_t>(labels.size()) == n,
                file << " '" << path.string() << "': " << labels.size() << " " << what << " labels for " << n << " "
                     << what << "s; pass one per " << what << " or none (1..n)");
  for (const int32_t label : labels)
    FETICON_CHECK(label >= 1,
                  file << " '" << path.string() << "': " << what << " label " << label << " is not positive");
}

/// The label of item `index` (0-based): labels[index], or index + 1 without labels.
inline int64_t label_of(const Labels& labels, int64_t index)
{
  return labels.empty() ? index + 1 : labels[static_cast<std::size_t>(index)];
}
} // namespace feticon::io

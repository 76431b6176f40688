#include "app/petsc_binary.hpp"

#include "common/error.hpp"

#include <bit>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <vector>

namespace feticon::app
{
namespace
{
// PETSc's class ids at the head of a binary object (petscmat.h, petscvec.h).
constexpr int32_t mat_file_class_id = 1211216;
constexpr int32_t vec_file_class_id = 1211214;

template <class T>
T big_endian(T value)
{
  if constexpr (std::endian::native == std::endian::little)
  {
    unsigned char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    for (size_t i = 0; i < sizeof(T) / 2; ++i)
      std::swap(bytes[i], bytes[sizeof(T) - 1 - i]);
    std::memcpy(&value, bytes, sizeof(T));
  }
  return value;
}

class BinaryFile
{
public:
  explicit BinaryFile(const std::filesystem::path& path) : _path(path), _out(path, std::ios::binary)
  {
    FETICON_CHECK(_out, "cannot write " << path);
  }
  template <class T>
  void put(T value)
  {
    value = big_endian(value);
    _out.write(reinterpret_cast<const char*>(&value), sizeof(T));
  }
  ~BinaryFile() noexcept(false)
  {
    _out.close();
    FETICON_CHECK(_out, "writing " << _path << " failed");
  }

private:
  std::filesystem::path _path;
  std::ofstream _out;
};

int32_t index32(la::Index i, const char* what)
{
  FETICON_CHECK(i <= std::numeric_limits<int32_t>::max(), what << " " << i << " is beyond PETSc's 32-bit indices");
  return static_cast<int32_t>(i);
}
} // namespace

void write_petsc_matrix(const std::filesystem::path& path, const la::SparseMatrix& A)
{
  // Column-major storage of a symmetric matrix is its row-major storage: column j is row j.
  la::SparseMatrix M = A;
  M.makeCompressed();
  BinaryFile file(path);
  file.put(mat_file_class_id);
  file.put(index32(M.rows(), "rows"));
  file.put(index32(M.cols(), "columns"));
  file.put(index32(M.nonZeros(), "nonzeros"));
  for (la::Index j = 0; j < M.outerSize(); ++j)
    file.put(static_cast<int32_t>(M.outerIndexPtr()[j + 1] - M.outerIndexPtr()[j]));
  for (la::Index k = 0; k < M.nonZeros(); ++k)
    file.put(static_cast<int32_t>(M.innerIndexPtr()[k]));
  for (la::Index k = 0; k < M.nonZeros(); ++k)
    file.put(M.valuePtr()[k]);
}

void write_petsc_vectors(const std::filesystem::path& path, const la::Matrix& V)
{
  BinaryFile file(path);
  for (la::Index j = 0; j < V.cols(); ++j)
  {
    file.put(vec_file_class_id);
    file.put(index32(V.rows(), "rows"));
    for (la::Index i = 0; i < V.rows(); ++i)
      file.put(V(i, j));
  }
}
} // namespace feticon::app
